//! Circles, ellipses, arcs and filled arcs (sectors, chord regions) read from a small text format
//! or from GeoJSON features with a `circle` or `ellipse` property, and written back as text
//! (README: "Curves").

use std::path::Path;

use clip_core::{ArcFill, Ellipse, EllipseArc, FilledArc, Point};
use serde_json::Value;

use crate::cli_error::InputError;

/// One object to clip: an arc or a whole ellipse, and whether to clip it filled or as an outline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveObject {
    /// The arc (sweep 2π for a whole ellipse).
    pub arc: EllipseArc,
    /// Clip the filled shape rather than the outline.
    pub filled: bool,
    /// How a filled arc is closed (two radii or its chord); a whole ellipse ignores it.
    pub fill: ArcFill,
}

impl CurveObject {
    /// An outline.
    pub fn outline(arc: EllipseArc) -> CurveObject {
        CurveObject { arc, filled: false, fill: ArcFill::Sector }
    }

    /// A filled shape: the filled ellipse for a whole one, else the arc closed by `fill`.
    pub fn from_filled(filled: FilledArc) -> CurveObject {
        CurveObject { arc: *filled.arc(), filled: true, fill: filled.fill() }
    }

    /// The filled shape, when the object is clipped filled.
    pub fn filled_arc(&self) -> Option<FilledArc> {
        self.filled.then(|| FilledArc::new(self.arc, self.fill))
    }

    /// The bounding box of what is clipped: the filled shape's (a sector's centre included) or
    /// the outline's.
    pub fn bounds(&self) -> clip_core::Rect {
        self.filled_arc().map_or_else(|| self.arc.bounds(), |f| f.bounds())
    }
}

/// The curves in a file, or `None` when the file holds no curve (then it is read as polygons or
/// line strings). A `.curve` file holds curves, and one that holds none, or a line of another
/// keyword, is an error naming it. Other text: curves when its first keyword is a curve keyword.
/// GeoJSON (`.geojson`, `.json`): some feature has a `circle` or `ellipse` property.
pub fn read_curves(path: &Path) -> Result<Option<Vec<CurveObject>>, InputError> {
    let text = crate::read::read_text(path)?;
    let extension = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let parsed = match extension.as_deref() {
        Some("geojson" | "json") => parse_curve_geojson(&text),
        Some("curve") => parse_curve_file(&text).map(Some),
        _ => parse_curve_text(&text),
    };
    parsed.map_err(|problem| InputError::new(path, problem))
}

/// The keywords of the curve text format.
const KEYWORDS: &str = "circle, ellipse, arc, sector or chord";

/// A `.curve` file's curves: every line a curve, a comment or blank, and at least one curve.
pub fn parse_curve_file(text: &str) -> Result<Vec<CurveObject>, String> {
    let first = text.lines().enumerate().find_map(|(n, raw)| {
        let line = raw.split('#').next().unwrap_or("").trim();
        line.split_whitespace().next().map(|word| (n, word.to_ascii_lowercase()))
    });
    match first {
        None => {
            Err(format!("it holds no curve, only comments or blank lines (a curve file has one {KEYWORDS} a line)"))
        }
        Some((n, word)) if !is_keyword(&word) => Err(format!("line {}: unknown keyword '{word}' ({KEYWORDS})", n + 1)),
        Some(_) => Ok(parse_curve_text(text)?.unwrap_or_default()),
    }
}

fn is_keyword(word: &str) -> bool {
    matches!(word, "circle" | "ellipse" | "arc" | "sector" | "chord")
}

/// An angle in degrees, or in radians with a `rad` suffix (`deg` is also accepted).
fn angle(word: &str) -> Result<f64, String> {
    let (number, radians) = match word.strip_suffix("rad") {
        Some(n) => (n, true),
        None => (word.strip_suffix("deg").unwrap_or(word), false),
    };
    let v: f64 = number.parse().map_err(|_| format!("'{word}' is not an angle (degrees, or radians with 'rad')"))?;
    Ok(if radians { v } else { v.to_radians() })
}

fn number(word: &str) -> Result<f64, String> {
    word.parse().map_err(|_| format!("'{word}' is not a number"))
}

/// Parses the text format; `None` when its first keyword is not a curve keyword.
///
/// ```text
/// # comments and blank lines are skipped; angles in degrees, or radians with 'rad'
/// circle  CX CY R                     [filled|outline]   (default filled)
/// ellipse CX CY RX RY [ROTATION]      [filled|outline]   (default filled)
/// arc     CX CY RX RY ROTATION START SWEEP               (an outline)
/// sector  CX CY RX RY ROTATION START SWEEP               (filled: the arc and two radii)
/// chord   CX CY RX RY ROTATION START SWEEP               (filled: the arc and its chord)
/// ```
pub fn parse_curve_text(text: &str) -> Result<Option<Vec<CurveObject>>, String> {
    let mut objects = Vec::new();
    for (n, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let mut words: Vec<&str> = line.split_whitespace().collect();
        let keyword = words.remove(0).to_ascii_lowercase();
        if !is_keyword(&keyword) {
            if objects.is_empty() {
                return Ok(None);
            }
            return Err(format!("line {}: unknown keyword '{keyword}' ({KEYWORDS})", n + 1));
        }
        let at = |why: String| format!("line {}: {why}", n + 1);
        let mode = match words.last().map(|w| w.to_ascii_lowercase()) {
            Some(w) if w == "filled" || w == "outline" => {
                words.pop();
                Some(w == "filled")
            }
            _ => None,
        };
        let object = match (keyword.as_str(), words.as_slice()) {
            ("circle", [cx, cy, r]) => {
                let e =
                    Ellipse::circle(Point::new(number(cx)?, number(cy)?), number(r)?).map_err(|e| at(e.to_string()))?;
                whole(e, mode.unwrap_or(true))
            }
            ("ellipse", [cx, cy, rx, ry, rest @ ..]) if rest.len() <= 1 => {
                let rotation = rest.first().map_or(Ok(0.0), |w| angle(w)).map_err(at)?;
                let e = Ellipse::new(Point::new(number(cx)?, number(cy)?), number(rx)?, number(ry)?, rotation)
                    .map_err(|e| at(e.to_string()))?;
                whole(e, mode.unwrap_or(true))
            }
            (kind @ ("arc" | "sector" | "chord"), [cx, cy, rx, ry, rotation, start, sweep]) => {
                if mode.is_some() {
                    return Err(at(
                        "'filled'/'outline' apply to circles and ellipses; an arc is an outline, a sector or chord filled"
                            .into(),
                    ));
                }
                let e = Ellipse::new(Point::new(number(cx)?, number(cy)?), number(rx)?, number(ry)?, angle(rotation)?)
                    .map_err(|e| at(e.to_string()))?;
                let arc = EllipseArc::new(e, angle(start)?, angle(sweep)?).map_err(|e| at(e.to_string()))?;
                match kind.parse::<ArcFill>() {
                    Ok(fill) => CurveObject::from_filled(FilledArc::new(arc, fill)),
                    Err(_) => CurveObject::outline(arc),
                }
            }
            (k, w) => {
                return Err(at(format!(
                    "'{k}' with {} value(s): expected circle CX CY R | ellipse CX CY RX RY [ROT] | arc|sector|chord CX CY RX RY ROT START SWEEP",
                    w.len()
                )));
            }
        };
        objects.push(object);
    }
    Ok((!objects.is_empty()).then_some(objects))
}

/// Parses GeoJSON: a Feature or FeatureCollection whose features have a Point geometry (the
/// centre) and a `circle: {radius}` or `ellipse: {rx, ry, rotation}` property, optionally
/// `arc: {start, sweep}` (degrees) with `fill: "sector" | "chord"` to fill it, and `filled`
/// (default true for whole curves). `None` when no feature has a curve property.
pub fn parse_curve_geojson(text: &str) -> Result<Option<Vec<CurveObject>>, String> {
    let json: Value = serde_json::from_str(text).map_err(crate::read::not_valid_geojson)?;
    let features: Vec<&Value> = match json.get("type").and_then(Value::as_str) {
        Some("FeatureCollection") => {
            json.get("features").and_then(Value::as_array).map(|f| f.iter().collect()).unwrap_or_default()
        }
        Some("Feature") => vec![&json],
        _ => return Ok(None),
    };
    let curves: Vec<(usize, &Value)> = features
        .into_iter()
        .enumerate()
        .filter(|(_, f)| f.get("properties").is_some_and(|p| p.get("circle").is_some() || p.get("ellipse").is_some()))
        .collect();
    if curves.is_empty() {
        return Ok(None);
    }
    curves
        .into_iter()
        .map(|(i, f)| feature(f).map_err(|why| format!("feature {i}: {why}")))
        .collect::<Result<Vec<_>, _>>()
        .map(Some)
}

fn feature(f: &Value) -> Result<CurveObject, String> {
    let coords = f
        .get("geometry")
        .filter(|g| g.get("type").and_then(Value::as_str) == Some("Point"))
        .and_then(|g| g.get("coordinates"))
        .and_then(Value::as_array)
        .ok_or("a curve feature needs a Point geometry (its centre)")?;
    let coordinate = |i: usize| coords.get(i).and_then(Value::as_f64).ok_or("the centre needs two numbers");
    let center = Point::new(coordinate(0)?, coordinate(1)?);
    let props = f.get("properties").ok_or("no properties")?;
    if props.get("circle").is_some() && props.get("ellipse").is_some() {
        return Err("it has both 'circle' and 'ellipse': a curve feature is one or the other".into());
    }
    let field = |o: &Value, k: &str| o.get(k).and_then(Value::as_f64).ok_or(format!("missing number '{k}'"));
    let e = if let Some(c) = props.get("circle") {
        Ellipse::circle(center, field(c, "radius")?)
    } else {
        let el = props.get("ellipse").ok_or("no circle or ellipse property")?;
        let rotation = el.get("rotation").and_then(Value::as_f64).unwrap_or(0.0).to_radians();
        Ellipse::new(center, field(el, "rx")?, field(el, "ry")?, rotation)
    }
    .map_err(|e| e.to_string())?;
    let filled = props.get("filled").and_then(Value::as_bool);
    let fill = match props.get("fill") {
        None => None,
        Some(v) => Some(
            v.as_str()
                .ok_or("'fill' must be \"sector\" or \"chord\"")?
                .parse::<ArcFill>()
                .map_err(|e| e.to_string())?,
        ),
    };
    match props.get("arc") {
        Some(a) => {
            let arc = EllipseArc::new(e, field(a, "start")?.to_radians(), field(a, "sweep")?.to_radians())
                .map_err(|e| e.to_string())?;
            match (fill, filled) {
                (Some(fill), Some(true) | None) => Ok(CurveObject::from_filled(FilledArc::new(arc, fill))),
                (None, Some(false) | None) => Ok(CurveObject::outline(arc)),
                (Some(_), Some(false)) => Err("'fill' closes a filled arc, but 'filled' is false".into()),
                (None, Some(true)) => Err("a filled arc needs 'fill': \"sector\" or \"chord\"".into()),
            }
        }
        None if fill.is_some() => Err("'fill' applies to arcs; give an 'arc' or drop it".into()),
        None => Ok(whole(e, filled.unwrap_or(true))),
    }
}

/// A whole ellipse, filled or as an outline.
fn whole(e: Ellipse, filled: bool) -> CurveObject {
    let arc = EllipseArc::full(e);
    if filled { CurveObject::from_filled(FilledArc::whole(e)) } else { CurveObject::outline(arc) }
}

/// The objects in the text format, exactly (radians written with `rad`, shortest round-trip
/// decimals), so a saved case reads back bit for bit.
pub fn curves_to_text(objects: &[CurveObject]) -> String {
    let mut text = String::from("# clipbench curves: ellipse/arc/sector/chord, angles in radians ('rad')\n");
    for o in objects {
        let e = o.arc.ellipse();
        let (c, (rx, ry)) = (e.center(), e.radii());
        let line = if o.arc.is_closed() {
            let mode = if o.filled { "filled" } else { "outline" };
            format!("ellipse {:?} {:?} {rx:?} {ry:?} {:?}rad {mode}", c.x, c.y, e.rotation())
        } else {
            let keyword = if o.filled { o.fill.name() } else { "arc" };
            format!(
                "{keyword} {:?} {:?} {rx:?} {ry:?} {:?}rad {:?}rad {:?}rad",
                c.x,
                c.y,
                e.rotation(),
                o.arc.start(),
                o.arc.sweep()
            )
        };
        text.push_str(&line);
        text.push('\n');
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_reads_and_round_trips() {
        let text = "# a test\ncircle 5 5 2\nellipse 1 2 3 1 30 outline\narc 0 0 2 2 0 -45 90\n";
        let objects = parse_curve_text(text).unwrap().unwrap();
        assert_eq!(objects.len(), 3);
        assert!(objects[0].filled && !objects[1].filled && !objects[2].filled);
        assert!((objects[1].arc.ellipse().rotation() - 30f64.to_radians()).abs() < 1e-15);
        assert!((objects[2].arc.start() - 315f64.to_radians()).abs() < 1e-12);
        let back = parse_curve_text(&curves_to_text(&objects)).unwrap().unwrap();
        assert_eq!(back, objects);
        let filled = parse_curve_text("sector 0 0 2 1 10 30 120\nchord 1 1 3 3 0 -90 270\n").unwrap().unwrap();
        assert_eq!(
            filled.iter().map(|o| o.filled_arc().map(|f| f.fill())).collect::<Vec<_>>(),
            vec![Some(ArcFill::Sector), Some(ArcFill::Chord)]
        );
        assert!((filled[1].arc.sweep() - 1.5 * std::f64::consts::PI).abs() < 1e-12);
        assert_eq!(parse_curve_text(&curves_to_text(&filled)).unwrap().unwrap(), filled);
    }

    #[test]
    fn bad_curves_are_errors_with_line_numbers() {
        assert_eq!(parse_curve_text("POLYGON((0 0,1 0,1 1,0 0))").unwrap(), None);
        let e = parse_curve_text("circle 0 0 1\ncircle 0 0 -1\n").unwrap_err();
        assert!(e.contains("line 2") && e.contains("positive"), "{e}");
        assert!(parse_curve_text("circle 0 0\n").unwrap_err().contains("line 1"));
        assert!(parse_curve_text("circle 0 x 1\n").is_err());
        assert!(parse_curve_text("arc 0 0 1 1 0 0 400\n").is_err());
        assert!(parse_curve_text("arc 0 0 1 1 0 0 90 filled\n").is_err());
        // Filled arcs: empty, negative or over-full sweeps, non-finite angles, bad radii.
        for bad in [
            "sector 0 0 1 1 0 0 0",
            "chord 0 0 1 1 0 0 -10",
            "sector 0 0 1 1 0 0 361",
            "chord 0 0 1 1 0 nan 90",
            "sector 0 0 0 1 0 0 90",
            "chord 0 0 -1 -1 0 0 90",
            "sector 0 0 1 1 0 0 90 filled",
            "chord 0 0 1 1 0 0",
        ] {
            let e = parse_curve_text(bad).unwrap_err();
            assert!(e.contains("line 1"), "{bad}: {e}");
        }
        assert!(parse_curve_text("ellipse 0 0 1 1 nan\n").is_err());
    }

    #[test]
    fn geojson_features_with_curve_properties() {
        let text = r#"{"type":"FeatureCollection","features":[
            {"type":"Feature","geometry":{"type":"Point","coordinates":[5,5]},"properties":{"circle":{"radius":2}}},
            {"type":"Feature","geometry":{"type":"Point","coordinates":[1,1]},
             "properties":{"ellipse":{"rx":3,"ry":1,"rotation":45},"arc":{"start":0,"sweep":90}}}]}"#;
        let objects = parse_curve_geojson(text).unwrap().unwrap();
        assert_eq!(objects.len(), 2);
        assert!(objects[0].filled && !objects[1].filled);
        assert!((objects[1].arc.sweep() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        let polygon = r#"{"type":"Feature","geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,0]]]},"properties":{}}"#;
        assert_eq!(parse_curve_geojson(polygon).unwrap(), None);
        let bad = r#"{"type":"Feature","geometry":{"type":"Point","coordinates":[0,0]},"properties":{"circle":{"radius":0}}}"#;
        assert!(parse_curve_geojson(bad).unwrap_err().contains("positive"));
        let feature = |props: &str| {
            format!(r#"{{"type":"Feature","geometry":{{"type":"Point","coordinates":[0,0]}},"properties":{props}}}"#)
        };
        let chord =
            parse_curve_geojson(&feature(r#"{"circle":{"radius":2},"arc":{"start":0,"sweep":90},"fill":"chord"}"#))
                .unwrap()
                .unwrap();
        assert_eq!(chord[0].filled_arc().map(|f| f.fill()), Some(ArcFill::Chord));
        for bad in [
            r#"{"circle":{"radius":2},"arc":{"start":0,"sweep":90},"fill":"pie"}"#,
            r#"{"circle":{"radius":2},"arc":{"start":0,"sweep":0},"fill":"sector"}"#,
            r#"{"circle":{"radius":2},"arc":{"start":0,"sweep":90},"filled":true}"#,
            r#"{"circle":{"radius":2},"arc":{"start":0,"sweep":90},"fill":"sector","filled":false}"#,
            r#"{"circle":{"radius":2},"fill":"sector"}"#,
        ] {
            assert!(parse_curve_geojson(&feature(bad)).is_err(), "{bad}");
        }
    }
}
