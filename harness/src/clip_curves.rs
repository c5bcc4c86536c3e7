//! `clipbench clip` on circles, ellipses and arcs: the visible arcs and clipped filled regions,
//! written as an SVG picture with exact arcs, or flattened within a tolerance as WKT or GeoJSON.

use std::path::Path;

use clip_core::{CurveRegion, Operand, Point, Polygons};
use clip_curve::{flatten_intervals, flatten_region};
use clip_testkit::case_record::{CurvePicture, curves_svg, format_coordinate, polygons_to_wkt};
use geo::{LineString, MultiLineString, MultiPolygon};

use crate::cli_error::CliError;
use crate::curve_input::CurveObject;
use crate::read::read_polygons;
use crate::registry::Registry;
use crate::write::OutputFormat;

/// Default flattening tolerance, relative to the window's extent.
pub const DEFAULT_TOLERANCE: f64 = 1e-4;

/// Clips `objects` against the window in `clip` with the curve clipper called `clipper`, and
/// returns the output text in `format`.
pub fn clip_curves(
    registry: &Registry,
    clipper: &str,
    objects: &[CurveObject],
    clip: &Path,
    tolerance: Option<f64>,
    format: OutputFormat,
) -> Result<String, CliError> {
    let entry = registry.curve.iter().find(|e| e.clipper.name() == clipper).ok_or_else(|| {
        let valid: Vec<&str> = registry.curve.iter().map(|e| e.clipper.name()).collect();
        CliError::usage(format!(
            "the subject holds curves: '{clipper}' is not a curve clipper (curve clippers: {})",
            valid.join(", ")
        ))
    })?;
    let window = read_polygons(clip, Operand::Window)?;
    let prepared = entry.clipper.prepare(&window).map_err(|e| CliError::usage(format!("{}: {e}", clip.display())))?;
    let tolerance = tolerance.unwrap_or(DEFAULT_TOLERANCE * window.bounds().extent());
    clip_curve::check_tolerance(tolerance).map_err(|e| CliError::usage(format!("--tolerance: {e}")))?;
    let visible: Vec<Vec<(f64, f64)>> = objects.iter().map(|o| prepared.visible(&o.arc).intervals).collect();
    let regions: Vec<Option<CurveRegion>> =
        objects.iter().map(|o| o.filled_arc().map(|f| prepared.clip_filled_arc(&f).region)).collect();
    if format == OutputFormat::Svg {
        let pictures: Vec<CurvePicture<'_>> = objects
            .iter()
            .zip(&visible)
            .zip(&regions)
            .map(|((o, v), r)| CurvePicture {
                arc: &o.arc,
                // A filled object shows its region; its outline is drawn by the region's edge.
                visible: if o.filled { &[] } else { v.as_slice() },
                region: r.as_ref(),
            })
            .collect();
        return Ok(curves_svg(&window, &pictures, &format!("{} (exact arcs)", entry.clipper.name())));
    }
    let fail = |e: clip_core::ClipError| CliError::usage(format!("--tolerance {tolerance}: {e}"));
    let mut rings = Polygons::empty();
    let mut lines: Vec<Vec<Point>> = Vec::new();
    for ((o, v), r) in objects.iter().zip(&visible).zip(&regions) {
        match r {
            Some(region) => rings.rings.extend(flatten_region(region, tolerance).map_err(fail)?.rings),
            None => lines.extend(flatten_intervals(o.arc.ellipse(), v, tolerance).map_err(fail)?),
        }
    }
    Ok(match format {
        OutputFormat::Wkt => wkt(&rings, &lines) + "\n",
        _ => {
            let polygons = geojson::Geometry::new(geojson::GeometryValue::from(&MultiPolygon::from(&rings)));
            let strings = MultiLineString(lines.iter().map(|l| LineString::from(l.clone())).collect());
            let lines = geojson::Geometry::new(geojson::GeometryValue::from(&strings));
            let collection = geojson::GeometryValue::GeometryCollection { geometries: vec![polygons, lines] };
            geojson::Geometry::new(collection).to_string() + "\n"
        }
    })
}

/// The filled regions as a `MULTIPOLYGON`, the outlines as a `MULTILINESTRING`, both in a
/// `GEOMETRYCOLLECTION` when there are both.
fn wkt(rings: &Polygons, lines: &[Vec<Point>]) -> String {
    let polygons = polygons_to_wkt(rings, true);
    let strings = if lines.is_empty() {
        "MULTILINESTRING EMPTY".to_owned()
    } else {
        let parts: Vec<String> = lines
            .iter()
            .map(|l| {
                let pts: Vec<String> =
                    l.iter().map(|p| format!("{} {}", format_coordinate(p.x), format_coordinate(p.y))).collect();
                format!("({})", pts.join(", "))
            })
            .collect();
        format!("MULTILINESTRING ({})", parts.join(", "))
    };
    match (rings.is_empty(), lines.is_empty()) {
        (false, true) => polygons,
        (true, false) => strings,
        _ => format!("GEOMETRYCOLLECTION ({polygons}, {strings})"),
    }
}
