//! Failure records: inputs and outputs as WKT text and as SVG pictures, so every failure can be
//! read, reproduced and looked at.

mod curve_svg;
mod failure_svg;
mod svg;
mod wkt;

pub use curve_svg::{CurvePicture, curves_svg};
pub use failure_svg::{FailureMark, line_failure_svg, polygon_failure_svg};
pub use svg::{lines_svg, polygons_svg, polygons_svg_with_fill};
pub use wkt::{format_coordinate, pieces_to_wkt, polygons_to_wkt, segments_to_wkt};
