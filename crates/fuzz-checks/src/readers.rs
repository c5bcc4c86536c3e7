//! The `readers` target: any bytes as any file the `clipbench` CLI reads (WKT, GeoJSON,
//! Clipper2's suite format, geo's fixtures and `tcases.json`, `verify`'s case files) must give a
//! value or a typed error, never a panic or a hang; and polygons read from WKT must read back the
//! same from the WKT the CLI writes for them.

use std::path::Path;
use std::sync::OnceLock;

use clip_core::{Operand, validate_polygons, validate_segments};
use clip_testkit::case_record::polygons_to_wkt;
use clipbench::conformance::{clipper2_suites, geo_booleanop};
use clipbench::read::shapes_from_text;
use clipbench::registry::{Registry, registry};
use clipbench::verify::replay::read_case;

/// The formats, chosen by the first byte (modulo their number).
pub const FORMATS: [&str; 6] = ["wkt", "geojson", "clipper2", "geo-fixture", "tcases", "case-file"];

/// The name the readers are given for the text, in their messages.
fn path() -> &'static Path {
    Path::new("fuzz-input")
}

fn shared_registry() -> &'static Registry {
    static REGISTRY: OnceLock<Registry> = OnceLock::new();
    REGISTRY.get_or_init(registry)
}

/// The target: the first byte picks the format, the rest is the file's text. Bytes that are not
/// UTF-8 are refused by the CLI before any reader sees them ("cannot read it"), so they pass.
pub fn check_bytes(data: &[u8]) -> Result<(), String> {
    let Some((&format, rest)) = data.split_first() else { return Ok(()) };
    let Ok(text) = std::str::from_utf8(rest) else { return Ok(()) };
    check(FORMATS[usize::from(format) % FORMATS.len()], text)
}

/// Reads `text` as `format` (one of [`FORMATS`]). Any outcome of the readers is fine except a
/// panic (which propagates) and, for WKT, polygons that do not read back the same from the WKT
/// written for them.
pub fn check(format: &str, text: &str) -> Result<(), String> {
    match format {
        "wkt" | "geojson" => {
            let Ok((shapes, _dropped)) = shapes_from_text(text, format == "geojson") else { return Ok(()) };
            let polygons = shapes.polygons();
            let _ = validate_segments(&shapes.segments);
            if format == "wkt" && shapes.segments.is_empty() && validate_polygons(&polygons, Operand::Subject).is_ok() {
                let written = polygons_to_wkt(&polygons, false);
                let (again, _) = shapes_from_text(&written, false)
                    .map_err(|e| format!("the WKT written for what was read does not read back: {e}\n{written}"))?;
                if again.rings != shapes.rings {
                    return Err(format!("read {:?}, wrote {written}, read back {:?}", shapes.rings, again.rings));
                }
            }
        }
        "clipper2" => {
            let _ = clipper2_suites::records(text, path());
        }
        "geo-fixture" => {
            let _ = geo_booleanop::fixture_cases(text, path());
        }
        "tcases" => {
            let _ = geo_booleanop::tcases_of(text, path());
        }
        "case-file" => {
            let _ = read_case(text, path(), shared_registry());
        }
        other => return Err(format!("no reader called {other}")),
    }
    Ok(())
}
