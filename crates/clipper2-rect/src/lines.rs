//! `Clipper2RectLines`: Clipper2's `RectClipLines` behind clip-core's `LineClipper` trait.

use clip_core::{
    ClipError, LineCapabilities, LineClipper, Polygons, PreparedWindow, Rect, Segment, VisiblePiece, WindowKind,
    rect_window, validate_segments,
};

use crate::NAME;
use crate::ffi::{GridRect, rect_clip_lines};
use crate::grid::IntegerGrid;

/// Clipper2's `RectClipLines`, registered as the line clipper `clipper2-rect`: the pieces of
/// each segment inside an axis-aligned rectangle.
///
/// Each segment is clipped on its own grid, fitted to the segment: the rectangle is first cut
/// down to the segment's bounding box grown by half its larger side (the segment cannot reach
/// what lies beyond), so a short segment in a large window keeps full precision. Clipper2's
/// pieces are then read back as parameters on the input segment, merged, and rebuilt on it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Clipper2RectLines;

impl LineClipper for Clipper2RectLines {
    fn name(&self) -> &'static str {
        NAME
    }

    fn capabilities(&self) -> LineCapabilities {
        LineCapabilities { window: WindowKind::Rectangle }
    }

    fn prepare(&self, window: &Polygons) -> Result<Box<dyn PreparedWindow>, ClipError> {
        Ok(Box::new(RectWindow { rect: rect_window(window, NAME)? }))
    }
}

/// The window, as its rectangle.
struct RectWindow {
    rect: Rect,
}

impl PreparedWindow for RectWindow {
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError> {
        validate_segments(segments)?;
        for (index, s) in segments.iter().enumerate() {
            if s.is_degenerate() || self.rect.rejects_segment(s.a, s.b) {
                continue;
            }
            for (ta, tb) in visible_intervals(&self.rect, s)? {
                out.push(VisiblePiece { segment: index, piece: s.piece(ta, tb) });
            }
        }
        Ok(())
    }
}

/// Clipper2's pieces of `s` inside `rect` as sorted, merged parameter intervals of positive
/// length. `s` is not degenerate and not trivially rejected, so the cut-down rectangle has area.
fn visible_intervals(rect: &Rect, s: &Segment) -> Result<Vec<(f64, f64)>, ClipError> {
    let b = s.bounds();
    let margin = b.extent() / 2.0;
    let near = Rect::new(
        rect.min.x.max(b.min.x - margin),
        rect.min.y.max(b.min.y - margin),
        rect.max.x.min(b.max.x + margin),
        rect.max.y.min(b.max.y + margin),
    );
    let grid = IntegerGrid::fitting(near.union(b));
    let window = GridRect { min: grid.to_grid(near.min), max: grid.to_grid(near.max) };
    let pieces = rect_clip_lines(window, &[vec![grid.to_grid(s.a), grid.to_grid(s.b)]]).ok_or_else(|| {
        ClipError::Unsupported { clipper: NAME, what: "an output with more than i32::MAX paths or points".into() }
    })?;
    let edges = pieces.iter().flat_map(|path| path.windows(2));
    Ok(s.covered_intervals(edges.map(|e| Segment::new(grid.to_point(e[0]), grid.to_point(e[1])))))
}
