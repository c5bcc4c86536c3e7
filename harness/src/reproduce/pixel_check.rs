//! Table 3's precondition: Method 1 (Vatti's trapezoids, trapezoid fill) and Method 2
//! (Sutherland-Hodgman, scanline fill) light exactly the same pixels, or nothing is timed.

use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons, Trapezoid};
use clip_raster::{FrameBuffer, fill_polygons, fill_trapezoids};
use clip_sutherland_hodgman::SutherlandHodgman;
use clip_vatti::Vatti;

use crate::cli_error::CliError;
use crate::results_files::vatti_table3::PixelRecord;

/// The fill rule both methods read the subject and their output under (the paper's parity).
pub const FILL: FillRule = FillRule::EvenOdd;

/// Both methods' clipped output for one case, checked to light the same pixels.
pub struct Agreed {
    /// Method 1's clip output.
    pub trapezoids: Vec<Trapezoid>,
    /// Method 2's clip output.
    pub polygons: Polygons,
    /// Checksum of the frame either method draws.
    pub checksum: u64,
    /// What was checked, for the pixel-check CSV.
    pub record: PixelRecord,
}

/// Clips `subject` by `window` with both methods, fills both into cleared frames and compares
/// them pixel by pixel; a difference is an error naming the case and the pixel counts.
pub fn agree(
    subject: &Polygons,
    window: &Polygons,
    (size, case): (usize, usize),
    frames: &mut [FrameBuffer; 2],
) -> Result<Agreed, CliError> {
    let what = format!("Table 3 at {size} edges, case {case}");
    let trapezoids = Vatti
        .clip_trapezoids(subject, window, BoolOp::Intersection, FILL)
        .map_err(|e| CliError::failed(format!("{what}: vatti refused the case: {e}")))?;
    let polygons = SutherlandHodgman::default()
        .clip(subject, window, BoolOp::Intersection, FILL)
        .map_err(|e| CliError::failed(format!("{what}: sutherland-hodgman refused the case: {e}")))?;
    let [m1, m2] = frames;
    m1.clear();
    m2.clear();
    fill_trapezoids(m1, &trapezoids, 1).map_err(|e| CliError::failed(format!("{what}: trapezoid fill: {e}")))?;
    fill_polygons(m2, &polygons, FILL, 1).map_err(|e| CliError::failed(format!("{what}: scanline fill: {e}")))?;
    compare_frames(&what, m1, m2)?;
    let checksum = m1.checksum();
    let record = PixelRecord {
        size,
        case,
        trapezoids: trapezoids.len(),
        polygon_vertices: polygons.vertex_count(),
        lit_pixels: m1.lit_count(),
        checksum: format!("{checksum:016x}"),
    };
    Ok(Agreed { trapezoids, polygons, checksum, record })
}

/// An error unless the two frames hold the same pixels.
fn compare_frames(what: &str, m1: &FrameBuffer, m2: &FrameBuffer) -> Result<(), CliError> {
    if m1 == m2 {
        return Ok(());
    }
    let differing = m1.pixels().iter().zip(m2.pixels()).filter(|(a, b)| a != b).count();
    Err(CliError::failed(format!(
        "{what}: the pipelines light different pixels ({differing} differ; Method 1 lit {}, Method 2 lit {}), so \
         their timings would not compare like with like; nothing was timed",
        m1.lit_count(),
        m2.lit_count()
    )))
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::WindowKind;
    use clip_testkit::workload::polygon_case_sized;

    #[test]
    fn both_methods_agree_on_a_table3_case() {
        let case = polygon_case_sized("vatti-t3", 1, 0, 20, WindowKind::Convex).unwrap();
        let mut frames = [FrameBuffer::default(), FrameBuffer::default()];
        let agreed = agree(&case.subject, &case.clip, (20, 0), &mut frames).unwrap();
        assert!(agreed.record.lit_pixels > 0);
        assert!(agreed.record.trapezoids > 0);
    }

    #[test]
    fn a_different_rendering_is_reported() {
        let mut frames = [FrameBuffer::default(), FrameBuffer::default()];
        let pixel = Polygons::from(clip_core::Rect::new(0.0, 0.0, 1.0, 1.0));
        fill_polygons(&mut frames[0], &pixel, FILL, 1).unwrap();
        let err = compare_frames("case", &frames[0], &frames[1]).unwrap_err();
        assert!(err.message.contains("1 differ; Method 1 lit 1, Method 2 lit 0"), "{}", err.message);
        assert!(compare_frames("case", &frames[0], &frames[0].clone()).is_ok());
    }
}
