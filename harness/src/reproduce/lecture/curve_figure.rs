//! The lecture's Fig. 6-27, "Clipping a filled circle", from a real run: a filled circle over a
//! corner of a rectangular window, the part inside drawn with its exact arcs.

use std::path::Path;

use clip_core::{Ellipse, EllipseArc, Point, Polygons, Rect};
use clip_curve::CurveClipper;
use clip_testkit::case_record::{CurvePicture, curves_svg};

use crate::cli_error::CliError;
use crate::results_files::lecture_curves::FIGURE_6_27;
use crate::write::write_file;

/// The window and circle of the figure: the circle crosses two sides, so the region's boundary
/// has an arc, a piece of each side and the corner between them.
pub fn figure_case() -> Result<(Polygons, Ellipse), CliError> {
    let window = Polygons::from(Rect::new(0.0, 0.0, 120.0, 80.0));
    let circle = Ellipse::circle(Point::new(100.0, 58.0), 36.0).map_err(|e| CliError::failed(e.to_string()))?;
    Ok((window, circle))
}

/// Clips the figure's circle and writes the picture into `out`.
pub fn write(out: &Path) -> Result<(), CliError> {
    let (window, circle) = figure_case()?;
    let prepared = CurveClipper::WITH_TESTS.prepare(&window).map_err(|e| CliError::failed(e.to_string()))?;
    let arc = EllipseArc::full(circle);
    let clipped = prepared.clip_filled(&circle);
    let visible = prepared.visible(&arc).intervals;
    let area = clipped.region.area();
    let title = format!("Fig. 6-27: clipped area {area:.2} of {:.2} ({})", circle.area(), clipped.stage.name());
    let picture = CurvePicture { arc: &arc, visible: &visible, region: Some(&clipped.region) };
    write_file(&out.join(FIGURE_6_27), &curves_svg(&window, &[picture], &title))
}
