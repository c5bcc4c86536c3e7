//! Reads WKT and GeoJSON files into polygon sets (every ring kept, orientation kept) and segments.

mod geojson_checks;
mod wkt_geometry;
mod wkt_text;

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
    /// Every ring of every polygon, in file order, each with the orientation it has in the file.
    pub rings: Vec<Ring>,
    /// Every edge of every line string (a `LINESTRING` of n points gives n - 1 segments).
    pub segments: Vec<Segment>,
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

/// Reads a file: GeoJSON when its name ends in `.geojson` or `.json`, WKT otherwise. What is
/// dropped in reading is said on standard error.
pub fn read_shapes(path: &Path) -> Result<Shapes, InputError> {
    let text = std::fs::read_to_string(path).map_err(|e| InputError::new(path, format!("cannot read it: {e}")))?;
    let parsed = if is_geojson(path) { parse_geojson(&text) } else { parse_wkt(&text) }
        .map_err(|problem| InputError::new(path, problem))?;
    // An empty geometry (`MULTIPOLYGON EMPTY`) is the empty region, a valid operand.
    let shapes = shapes_of(&parsed.geometries).map_err(|problem| InputError::new(path, problem))?;
    for note in &parsed.dropped {
        console::note(format_args!("{}: {note}", path.display()));
    }
    Ok(shapes)
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
    validate_segments(&shapes.segments).map_err(|e| InputError::new(path, e.to_string()))?;
    Ok(shapes.segments)
}

fn is_geojson(path: &Path) -> bool {
    matches!(
        path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref(),
        Some("geojson" | "json")
    )
}

/// Parses WKT text into a geometry.
pub fn parse_wkt(text: &str) -> Result<Parsed, String> {
    wkt_text::check(text)?;
    let wkt = wkt::Wkt::<f64>::from_str(text.trim()).map_err(|e| format!("not valid WKT: {e}"))?;
    wkt_geometry::check_rings(&wkt, &Place::default())?;
    let dropped = wkt_geometry::dropped(&wkt).into_iter().collect();
    let geometry = Geometry::try_from(wkt).map_err(|e| format!("unusable WKT: {e}"))?;
    Ok(Parsed { geometries: vec![Placed::whole(geometry)], dropped })
}

/// Parses GeoJSON text into its geometries: a FeatureCollection's one per feature with a
/// geometry (a feature whose geometry is null holds nothing), else the one.
fn parse_geojson(text: &str) -> Result<Parsed, String> {
    let json = geojson::GeoJson::from_str(text).map_err(|e| match e.to_string() {
        // serde_json stops at 128 levels rather than overflow the stack: say what the limit is.
        e if e.contains("recursion limit exceeded") => {
            format!("not valid GeoJSON: nested deeper than 128 levels ({e})")
        }
        e => format!("not valid GeoJSON: {e}"),
    })?;
    let found: Vec<(Place, Option<&geojson::Geometry>)> = match &json {
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
        // The conversion indexes positions unchecked: a position `[0]` would panic in it.
        geojson_checks::check_geometry(&g.value, &place, &mut beyond_xy)?;
        let geometry = Geometry::try_from(&g.value).map_err(|e| format!("{place}: unusable GeoJSON: {e}"))?;
        parsed.geometries.push(Placed { place, geometry });
    }
    if beyond_xy {
        parsed.dropped.push("positions' numbers after x and y (z) dropped: clipping is in the plane".into());
    }
    Ok(parsed)
}

/// The rings and segments of some geometries, in order.
pub fn shapes_of(geometries: &[Placed]) -> Result<Shapes, String> {
    let mut shapes = Shapes::default();
    geometries.iter().try_for_each(|g| collect(&g.geometry, &g.place, &mut shapes))?;
    Ok(shapes)
}

/// Adds a geometry's rings and segments; points are refused (they have no area and no length).
fn collect(g: &Geometry<f64>, place: &Place, shapes: &mut Shapes) -> Result<(), String> {
    match g {
        Geometry::Polygon(p) => shapes.rings.extend(Polygons::from(p).rings),
        Geometry::MultiPolygon(mp) => shapes.rings.extend(Polygons::from(mp).rings),
        Geometry::Rect(r) => shapes.rings.extend(Polygons::from(&r.to_polygon()).rings),
        Geometry::Triangle(t) => shapes.rings.extend(Polygons::from(&t.to_polygon()).rings),
        Geometry::LineString(ls) => shapes.segments.extend(ls.lines().map(Segment::from)),
        Geometry::MultiLineString(mls) => {
            shapes.segments.extend(mls.0.iter().flat_map(|ls| ls.lines()).map(Segment::from))
        }
        Geometry::Line(l) => shapes.segments.push(Segment::from(*l)),
        Geometry::GeometryCollection(c) => {
            c.0.iter().enumerate().try_for_each(|(i, g)| collect(g, &place.then(format_args!("member {i}")), shapes))?
        }
        Geometry::Point(_) | Geometry::MultiPoint(_) => {
            return Err(format!("{place} holds points: expected polygons or line strings"));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wkt_rings_keep_their_orientation_and_order() {
        let g = parse_wkt("MULTIPOLYGON(((0 0,0 4,4 4,4 0,0 0)),((1 1,2 1,2 2,1 2,1 1)))").unwrap().geometries;
        let mut shapes = Shapes::default();
        collect(&g[0].geometry, &Place::default(), &mut shapes).unwrap();
        assert_eq!(shapes.rings.len(), 2);
        assert!(shapes.rings[0].signed_area() < 0.0, "clockwise ring read as clockwise");
        assert!(shapes.rings[1].signed_area() > 0.0);
        assert_eq!(shapes.rings[0].len(), 4, "closing vertex dropped");
    }

    #[test]
    fn geojson_feature_collection_and_line_strings() {
        let text = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]}},
            {"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[[0,0],[2,2],[3,0]]}}]}"#;
        let mut shapes = Shapes::default();
        for g in parse_geojson(text).unwrap().geometries {
            collect(&g.geometry, &g.place, &mut shapes).unwrap();
        }
        assert_eq!(shapes.rings.len(), 1);
        assert_eq!(shapes.segments.len(), 2);
    }

    #[test]
    fn broken_text_is_an_error_not_a_panic() {
        assert!(parse_wkt("POLYGON((0 0, 1 1").is_err());
        assert!(parse_wkt("").is_err());
        assert!(parse_geojson("{\"type\": \"Polygon\"").is_err());
        let mut shapes = Shapes::default();
        assert!(
            collect(&parse_wkt("POINT(1 2)").unwrap().geometries[0].geometry, &Place::default(), &mut shapes).is_err()
        );
    }
}
