//! Reads WKT and GeoJSON files into polygon sets (every ring kept, orientation kept) and segments.

mod geojson_checks;
mod wkt_geometry;
mod wkt_text;

pub use geojson_checks::RingEnds;

use std::fmt;
use std::path::Path;
use std::str::FromStr;

use clip_core::{Operand, Polygons, Ring, Segment, validate_polygons, validate_segments};
use geo::Geometry;

use crate::cli_error::InputError;
use crate::console;

/// What a file holds: its rings (from polygons) and its segments (from line strings).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Shapes {
    /// Every ring of every polygon that encloses area, in file order, each with the orientation
    /// it has in the file.
    pub rings: Vec<Ring>,
    /// Every edge of every line string (a `LINESTRING` of n points gives n - 1 segments).
    pub segments: Vec<Segment>,
    /// True when the file holds line strings (even none, as `LINESTRING EMPTY`), not polygons.
    pub line_strings: bool,
    /// What reading dropped, one note each: rings of fewer than 3 distinct points, which add
    /// nothing to any winding number (GEOS and Boost.Geometry accept and ignore them too).
    pub dropped: Vec<String>,
}

impl Shapes {
    /// The rings as one polygon operand.
    pub fn polygons(&self) -> Polygons {
        Polygons::new(self.rings.clone())
    }
}

/// Where something is in its file, for messages: `feature 2, polygon 0, ring 1` (every index
/// counts from 0); nothing for the file's one geometry.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Place(String);

impl Place {
    /// The part `part` of what is here: `feature 2` then `ring 1` is `feature 2, ring 1`.
    pub fn then(&self, part: impl fmt::Display) -> Place {
        if self.0.is_empty() { Place(part.to_string()) } else { Place(format!("{}, {part}", self.0)) }
    }
}

impl fmt::Display for Place {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(if self.0.is_empty() { "the geometry" } else { &self.0 })
    }
}

/// A geometry and where it is in its file.
#[derive(Clone, Debug, PartialEq)]
pub struct Placed {
    /// Where: `feature 2` in a FeatureCollection, nothing for a file's one geometry.
    pub place: Place,
    /// The geometry.
    pub geometry: Geometry<f64>,
}

impl Placed {
    /// A geometry that is the whole of what is read.
    pub fn whole(geometry: Geometry<f64>) -> Placed {
        Placed { place: Place::default(), geometry }
    }
}

/// A file's geometries, and what reading them left out.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Parsed {
    /// The geometries, in file order.
    pub geometries: Vec<Placed>,
    /// What the file held that clipping in the plane drops (z, m), one note each.
    pub dropped: Vec<String>,
}

/// Reads a text file whole, without the UTF-8 byte order mark some editors put first (it marks
/// the encoding and is no part of the text).
pub fn read_text(path: &Path) -> Result<String, InputError> {
    let text = std::fs::read_to_string(path).map_err(|e| InputError::new(path, format!("cannot read it: {e}")))?;
    Ok(match text.strip_prefix('\u{feff}') {
        Some(rest) => rest.to_owned(),
        None => text,
    })
}

/// Reads a file: GeoJSON when its name ends in `.geojson` or `.json`, WKT otherwise. What is
/// dropped in reading is said on standard error.
pub fn read_shapes(path: &Path) -> Result<Shapes, InputError> {
    let text = read_text(path)?;
    let (shapes, dropped) =
        shapes_from_text(&text, is_geojson(path)).map_err(|problem| InputError::new(path, problem))?;
    for note in &dropped {
        console::note(format_args!("{}: {note}", path.display()));
    }
    Ok(shapes)
}

/// A file's text read as [`read_shapes`] reads it (GeoJSON or WKT): its shapes, and one note for
/// each thing reading dropped. The `readers` fuzz target calls this with any text.
pub fn shapes_from_text(text: &str, geojson: bool) -> Result<(Shapes, Vec<String>), String> {
    let parsed = if geojson { parse_geojson(text) } else { parse_wkt(text) }?;
    // An empty geometry (`MULTIPOLYGON EMPTY`) is the empty region, a valid operand.
    let shapes = shapes_of(&parsed.geometries)?;
    let dropped = parsed.dropped.into_iter().chain(shapes.dropped.iter().cloned()).collect();
    Ok((shapes, dropped))
}

/// Reads a polygon operand and validates it (finite, in range, rings of at least 3 points).
pub fn read_polygons(path: &Path, operand: Operand) -> Result<Polygons, InputError> {
    let shapes = read_shapes(path)?;
    if !shapes.segments.is_empty() && shapes.rings.is_empty() {
        return Err(InputError::new(path, format!("the {operand} must be polygons, but it holds line strings")));
    }
    let polygons = shapes.polygons();
    validate_polygons(&polygons, operand).map_err(|e| InputError::new(path, e.to_string()))?;
    Ok(polygons)
}

/// Reads segments and validates them (finite, in range).
pub fn read_segments(path: &Path) -> Result<Vec<Segment>, InputError> {
    let shapes = read_shapes(path)?;
    if !shapes.rings.is_empty() {
        return Err(InputError::new(path, "the segments must be line strings, but it holds polygons".into()));
    }
    validate_segments(&shapes.segments).map_err(|e| InputError::new(path, e.to_string()))?;
    Ok(shapes.segments)
}

/// Whether `path` names a GeoJSON file (`.geojson`, `.json`); anything else is read as WKT.
pub fn is_geojson(path: &Path) -> bool {
    matches!(
        path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref(),
        Some("geojson" | "json")
    )
}

/// Parses WKT text into a geometry.
pub fn parse_wkt(text: &str) -> Result<Parsed, String> {
    wkt_text::check(text)?;
    // `()` is an empty ring or line string, which the wkt crate reads only as `EMPTY`.
    let text = wkt_text::empty_parentheses_as_empty(text);
    let wkt = wkt::Wkt::<f64>::from_str(text.trim()).map_err(|e| format!("not valid WKT: {e}"))?;
    wkt_geometry::check_rings(&wkt, &Place::default())?;
    let dropped = wkt_geometry::dropped(&wkt).into_iter().collect();
    let geometry = Geometry::try_from(wkt).map_err(|e| format!("unusable WKT: {e}"))?;
    Ok(Parsed { geometries: vec![Placed::whole(geometry)], dropped })
}

/// The message for GeoJSON text that does not parse, for every reader of GeoJSON.
pub fn not_valid_geojson(e: impl std::fmt::Display) -> String {
    match e.to_string() {
        // serde_json stops at 128 levels rather than overflow the stack: say what the limit is.
        e if e.contains("recursion limit exceeded") => {
            format!("not valid GeoJSON: nested deeper than 128 levels ({e})")
        }
        e => format!("not valid GeoJSON: {e}"),
    }
}

/// Parses GeoJSON text into its geometries: a FeatureCollection's one per feature with a
/// geometry (a feature whose geometry is null holds nothing), else the one.
fn parse_geojson(text: &str) -> Result<Parsed, String> {
    geojson_geometries(&geojson::GeoJson::from_str(text).map_err(not_valid_geojson)?)
}

/// The geometries of parsed GeoJSON, checked, as [`parse_geojson`] gives them.
fn geojson_geometries(json: &geojson::GeoJson) -> Result<Parsed, String> {
    let found: Vec<(Place, Option<&geojson::Geometry>)> = match json {
        geojson::GeoJson::FeatureCollection(fc) => fc
            .features
            .iter()
            .enumerate()
            .map(|(i, f)| (Place::default().then(format_args!("feature {i}")), f.geometry.as_ref()))
            .collect(),
        geojson::GeoJson::Feature(f) => vec![(Place::default(), f.geometry.as_ref())],
        geojson::GeoJson::Geometry(g) => vec![(Place::default(), Some(g))],
    };
    let mut parsed = Parsed::default();
    let mut beyond_xy = false;
    for (place, g) in found {
        let Some(g) = g else { continue };
        let geometry = geo_geometry(&g.value, &place, RingEnds::MustClose, &mut beyond_xy)?;
        parsed.geometries.push(Placed { place, geometry });
    }
    if beyond_xy {
        parsed.dropped.push("positions' numbers after x and y (z) dropped: clipping is in the plane".into());
    }
    Ok(parsed)
}

/// A GeoJSON geometry at `place` as geo types, its positions (and rings, as `ends` says) checked
/// first: the conversion indexes a position's x and y unchecked, so a position `[0]` would panic
/// in it. Sets `beyond_xy` when a position has more than x and y.
pub fn geo_geometry(
    value: &geojson::GeometryValue,
    place: &Place,
    ends: RingEnds,
    beyond_xy: &mut bool,
) -> Result<Geometry, String> {
    geojson_checks::check_geometry(value, place, ends, beyond_xy)?;
    Geometry::try_from(value).map_err(|e| format!("{place}: unusable GeoJSON: {e}"))
}

/// A GeoJSON subject of features, each to be clipped on its own.
#[derive(Clone, Debug, PartialEq)]
pub struct Features {
    /// A FeatureCollection (else one Feature).
    pub collection: bool,
    /// Its features in order.
    pub features: Vec<FeatureShapes>,
    /// True when they hold line strings, not polygons.
    pub line_strings: bool,
    /// What reading dropped or left as it was, one note each (z values, rings that enclose
    /// nothing, features with no geometry).
    pub notes: Vec<String>,
}

/// One feature: its id and properties, and its shapes (none for a null geometry).
#[derive(Clone, Debug, PartialEq)]
pub struct FeatureShapes {
    /// Where it is: `feature 2`.
    pub place: Place,
    /// Its `id`, if any.
    pub id: Option<geojson::feature::Id>,
    /// Its `properties`, if any.
    pub properties: Option<geojson::JsonObject>,
    /// Its rings or segments; `None` when its geometry is null.
    pub shapes: Option<Shapes>,
}

/// A GeoJSON file's features, each read on its own; `None` when it holds a bare geometry. Every
/// feature is checked as [`read_shapes`] checks a file (one kind across them all).
pub fn read_features(path: &Path) -> Result<Option<Features>, InputError> {
    let text = read_text(path)?;
    let features = features_from_text(&text).map_err(|problem| InputError::new(path, problem))?;
    for note in features.iter().flat_map(|f| &f.notes) {
        console::note(format_args!("{}: {note}", path.display()));
    }
    Ok(features)
}

/// [`read_features`] on text.
pub fn features_from_text(text: &str) -> Result<Option<Features>, String> {
    let json = geojson::GeoJson::from_str(text).map_err(not_valid_geojson)?;
    let (collection, features): (bool, Vec<&geojson::Feature>) = match &json {
        geojson::GeoJson::FeatureCollection(fc) => (true, fc.features.iter().collect()),
        geojson::GeoJson::Feature(f) => (false, vec![f]),
        geojson::GeoJson::Geometry(_) => return Ok(None),
    };
    let parsed = geojson_geometries(&json)?;
    // All of them at once first: one kind (polygons or line strings) across the features.
    let all = shapes_of(&parsed.geometries)?;
    let mut notes: Vec<String> = parsed.dropped.into_iter().chain(all.dropped).collect();
    let mut geometries = parsed.geometries.into_iter();
    let mut out = Vec::with_capacity(features.len());
    for (i, f) in features.into_iter().enumerate() {
        let place = if collection { Place::default().then(format_args!("feature {i}")) } else { Place::default() };
        let shapes = match f.geometry {
            None => {
                let which = if collection { place.to_string() } else { "the feature".to_owned() };
                notes
                    .push(format!("{which} has no geometry (null): it is written back as it is, with a null geometry"));
                None
            }
            Some(_) => {
                let placed = geometries.next().ok_or("a feature's geometry went missing in reading")?;
                Some(shapes_of(std::slice::from_ref(&placed))?)
            }
        };
        out.push(FeatureShapes { place, id: f.id.clone(), properties: f.properties.clone(), shapes });
    }
    Ok(Some(Features { collection, features: out, line_strings: all.line_strings, notes }))
}

/// The rings and segments of some geometries, in order.
pub fn shapes_of(geometries: &[Placed]) -> Result<Shapes, String> {
    let mut collector = Collector::default();
    geometries.iter().try_for_each(|g| collector.add(&g.geometry, &g.place))?;
    Ok(collector.shapes)
}

/// Gathers rings and segments. A file holds polygons or line strings, not both: `clip` runs the
/// one or the other, so the rest would be dropped without a word (a line string among polygons
/// is more likely a ring written wrong than something to ignore).
#[derive(Default)]
struct Collector {
    shapes: Shapes,
    /// The first polygon or line string: where it is, and its kind.
    first: Option<(Place, &'static str)>,
}

impl Collector {
    /// Adds a geometry's rings and segments; points are refused (they have no area and no length).
    fn add(&mut self, g: &Geometry<f64>, place: &Place) -> Result<(), String> {
        match g {
            Geometry::Polygon(p) => self.add_polygon(p, place),
            Geometry::MultiPolygon(mp) => {
                for (i, p) in mp.0.iter().enumerate() {
                    self.add_polygon(p, &place.then(format_args!("polygon {i}")));
                }
            }
            Geometry::Rect(r) => self.add_polygon(&r.to_polygon(), place),
            Geometry::Triangle(t) => self.add_polygon(&t.to_polygon(), place),
            Geometry::LineString(ls) => {
                check_points(ls, place)?;
                self.shapes.segments.extend(ls.lines().map(Segment::from));
            }
            Geometry::MultiLineString(mls) => {
                for (i, ls) in mls.0.iter().enumerate() {
                    check_points(ls, &place.then(format_args!("line string {i}")))?;
                }
                self.shapes.segments.extend(mls.0.iter().flat_map(|ls| ls.lines()).map(Segment::from));
            }
            Geometry::Line(l) => self.shapes.segments.push(Segment::from(*l)),
            Geometry::GeometryCollection(c) => {
                return c
                    .0
                    .iter()
                    .enumerate()
                    .try_for_each(|(i, g)| self.add(g, &place.then(format_args!("member {i}"))));
            }
            Geometry::Point(_) | Geometry::MultiPoint(_) => {
                return Err(format!("{place} holds points: expected polygons or line strings"));
            }
        }
        self.one_kind(g, place)
    }

    /// Adds a polygon's rings (the exterior is ring 0), each with its orientation. A ring of
    /// fewer than 3 distinct points encloses nothing and adds nothing to any winding number: it
    /// is dropped with a note saying where it was, as GEOS and Boost.Geometry read it. This is
    /// the one place such rings are dropped; the clippers refuse them, as their input contract
    /// says.
    fn add_polygon(&mut self, p: &geo::Polygon<f64>, place: &Place) {
        // `POLYGON EMPTY` is the empty region: nothing to drop or say.
        if p.exterior().0.is_empty() && p.interiors().is_empty() {
            return;
        }
        for (i, ls) in std::iter::once(p.exterior()).chain(p.interiors()).enumerate() {
            let ring = Ring::from(ls);
            let distinct = ring.distinct_points_up_to(3);
            if distinct < 3 {
                let what = match distinct {
                    0 => "is empty".to_owned(),
                    1 => "has 1 distinct point".to_owned(),
                    n => format!("has {n} distinct points"),
                };
                self.shapes.dropped.push(format!(
                    "{} {what} and encloses nothing: dropped (it adds nothing to any winding number)",
                    place.then(format_args!("ring {i}"))
                ));
                continue;
            }
            self.shapes.rings.push(ring);
        }
    }

    /// Refuses `g` when it is of the other kind (polygons, line strings) than the first one.
    fn one_kind(&mut self, g: &Geometry<f64>, place: &Place) -> Result<(), String> {
        let kind = kind_name(g);
        let polygonal = |kind: &str| matches!(kind, "Polygon" | "MultiPolygon" | "Rect" | "Triangle");
        match &self.first {
            None => {
                self.shapes.line_strings = !polygonal(kind);
                self.first = Some((place.clone(), kind));
            }
            Some((first_place, first_kind)) if polygonal(first_kind) != polygonal(kind) => {
                return Err(format!(
                    "{place} is a {kind}, but {first_place} is a {first_kind}: a file holds polygons or line strings, \
                     not both"
                ));
            }
            Some(_) => {}
        }
        Ok(())
    }
}

/// A line string of one point has no segment: refused rather than dropped (none is `EMPTY`).
fn check_points(ls: &geo::LineString<f64>, place: &Place) -> Result<(), String> {
    if ls.0.len() == 1 {
        return Err(format!("{place} has 1 point: a line string needs two or more"));
    }
    Ok(())
}

/// The geometry's type as GeoJSON names it.
fn kind_name(g: &Geometry<f64>) -> &'static str {
    match g {
        Geometry::Point(_) => "Point",
        Geometry::Line(_) => "Line",
        Geometry::LineString(_) => "LineString",
        Geometry::Polygon(_) => "Polygon",
        Geometry::MultiPoint(_) => "MultiPoint",
        Geometry::MultiLineString(_) => "MultiLineString",
        Geometry::MultiPolygon(_) => "MultiPolygon",
        Geometry::GeometryCollection(_) => "GeometryCollection",
        Geometry::Rect(_) => "Rect",
        Geometry::Triangle(_) => "Triangle",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wkt_shapes(text: &str) -> Result<Shapes, String> {
        shapes_of(&parse_wkt(text)?.geometries)
    }

    fn geojson_shapes(text: &str) -> Result<Shapes, String> {
        shapes_of(&parse_geojson(text)?.geometries)
    }

    #[test]
    fn wkt_rings_keep_their_orientation_and_order() {
        let shapes = wkt_shapes("MULTIPOLYGON(((0 0,0 4,4 4,4 0,0 0)),((1 1,2 1,2 2,1 2,1 1)))").unwrap();
        assert_eq!(shapes.rings.len(), 2);
        assert!(shapes.rings[0].signed_area() < 0.0, "clockwise ring read as clockwise");
        assert!(shapes.rings[1].signed_area() > 0.0);
        assert_eq!(shapes.rings[0].len(), 4, "closing vertex dropped");
    }

    #[test]
    fn geojson_feature_collections_of_polygons_or_of_line_strings() {
        let polygon = r#"{"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}}"#;
        let line =
            r#"{"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[[0,0],[2,2],[3,0]]}}"#;
        let nothing = r#"{"type":"Feature","properties":{},"geometry":null}"#;
        let collection =
            |features: &[&str]| format!(r#"{{"type":"FeatureCollection","features":[{}]}}"#, features.join(","));
        let shapes = geojson_shapes(&collection(&[polygon, nothing, polygon])).unwrap();
        assert_eq!((shapes.rings.len(), shapes.segments.len()), (2, 0));
        let shapes = geojson_shapes(&collection(&[line, line])).unwrap();
        assert_eq!((shapes.rings.len(), shapes.segments.len()), (0, 4));
    }

    #[test]
    fn geojson_line_string_among_polygons_is_an_error_naming_it() {
        let text = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}},
            {"type":"Feature","properties":{},"geometry":null},
            {"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[[0,0],[2,2],[3,0]]}}]}"#;
        assert_eq!(
            geojson_shapes(text).unwrap_err(),
            "feature 2 is a LineString, but feature 0 is a Polygon: a file holds polygons or line strings, not both"
        );
        assert_eq!(
            wkt_shapes("GEOMETRYCOLLECTION(LINESTRING(0 0,1 1),GEOMETRYCOLLECTION(POLYGON((0 0,1 0,1 1,0 0))))")
                .unwrap_err(),
            "member 1, member 0 is a Polygon, but member 0 is a LineString: a file holds polygons or line strings, not both"
        );
    }

    #[test]
    fn line_string_of_one_point_is_an_error() {
        assert_eq!(
            wkt_shapes("LINESTRING(0 0)").unwrap_err(),
            "the geometry has 1 point: a line string needs two or more"
        );
        assert_eq!(
            wkt_shapes("MULTILINESTRING((0 0,1 1),(2 2))").unwrap_err(),
            "line string 1 has 1 point: a line string needs two or more"
        );
        assert_eq!(wkt_shapes("LINESTRING EMPTY").unwrap(), Shapes { line_strings: true, ..Shapes::default() });
    }

    #[test]
    fn broken_text_is_an_error_not_a_panic() {
        assert!(parse_wkt("POLYGON((0 0, 1 1").is_err());
        assert!(parse_wkt("").is_err());
        assert!(parse_geojson("{\"type\": \"Polygon\"").is_err());
        assert_eq!(
            wkt_shapes("POINT(1 2)").unwrap_err(),
            "the geometry holds points: expected polygons or line strings"
        );
    }
}
