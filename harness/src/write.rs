//! Writes results as WKT, GeoJSON or an SVG picture, chosen by the output file's extension.

use std::path::Path;

use clip_core::{Polygons, Segment, VisiblePiece};
use clip_testkit::case_record::{lines_svg, polygons_svg, polygons_to_wkt, segments_to_wkt};
use geo::{LineString, MultiLineString, MultiPolygon};

use crate::cli_error::CliError;

/// The output formats `clip` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputFormat {
    /// Well-known text.
    Wkt,
    /// A GeoJSON geometry.
    GeoJson,
    /// An SVG picture of the inputs and the result.
    Svg,
}

impl OutputFormat {
    /// The format for a file name: `.wkt`, `.geojson` or `.json`, `.svg`.
    pub fn of(path: &Path) -> Result<OutputFormat, CliError> {
        match path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase).as_deref() {
            Some("wkt") => Ok(OutputFormat::Wkt),
            Some("geojson" | "json") => Ok(OutputFormat::GeoJson),
            Some("svg") => Ok(OutputFormat::Svg),
            _ => Err(CliError::usage(format!(
                "{}: unknown output format (use a .wkt, .geojson, .json or .svg file name)",
                path.display()
            ))),
        }
    }
}

/// A polygon result in `format`; the picture shows `subject` and `clip` beneath it.
pub fn polygon_result(
    format: OutputFormat,
    clipper: &str,
    subject: &Polygons,
    clip: &Polygons,
    result: &Polygons,
) -> String {
    match format {
        OutputFormat::Wkt => polygons_to_wkt(result, true) + "\n",
        OutputFormat::GeoJson => {
            let value = geojson::GeometryValue::from(&MultiPolygon::from(result));
            geojson::Geometry::new(value).to_string() + "\n"
        }
        OutputFormat::Svg => polygons_svg(subject, clip, &[(clipper, result)]),
    }
}

/// A line result (visible pieces) in `format`; the picture shows the window and the segments.
pub fn line_result(
    format: OutputFormat,
    clipper: &str,
    window: &Polygons,
    segments: &[Segment],
    pieces: &[VisiblePiece],
) -> String {
    match format {
        OutputFormat::Wkt => segments_to_wkt(&pieces.iter().map(|p| p.piece).collect::<Vec<_>>()) + "\n",
        OutputFormat::GeoJson => {
            let lines = MultiLineString(pieces.iter().map(|p| LineString::from(vec![p.piece.a, p.piece.b])).collect());
            geojson::Geometry::new(geojson::GeometryValue::from(&lines)).to_string() + "\n"
        }
        OutputFormat::Svg => lines_svg(window, segments, &[(clipper, pieces)]),
    }
}

/// Writes `text` to `path`, or a one-line error naming the file.
pub fn write_file(path: &Path, text: &str) -> Result<(), CliError> {
    #[cfg(test)]
    files_written::count(path);
    std::fs::write(path, text).map_err(|e| CliError::failed(format!("{}: cannot write it: {e}", path.display())))
}

/// How often this thread wrote each file through [`write_file`], so a test can prove a run writes
/// each derived file once.
#[cfg(test)]
pub mod files_written {
    use std::cell::RefCell;
    use std::collections::BTreeMap;
    use std::path::{Path, PathBuf};

    thread_local! {
        static WRITES: RefCell<BTreeMap<PathBuf, usize>> = const { RefCell::new(BTreeMap::new()) };
    }

    /// Counts one write of `path`.
    pub fn count(path: &Path) {
        WRITES.with(|w| *w.borrow_mut().entry(path.to_owned()).or_default() += 1);
    }

    /// The writes of files under `dir` so far, by path.
    pub fn under(dir: &Path) -> BTreeMap<PathBuf, usize> {
        WRITES.with(|w| w.borrow().iter().filter(|(p, _)| p.starts_with(dir)).map(|(p, n)| (p.clone(), *n)).collect())
    }
}
