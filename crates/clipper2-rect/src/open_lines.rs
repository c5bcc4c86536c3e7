//! `Clipper2OpenLines`: Clipper2's general engine clipping open paths (`AddOpenSubject`) behind clip-core's `LineClipper` trait.

use clip_core::{
    ClipError, LineCapabilities, LineClipper, Point, Polygons, PreparedWindow, Rect, Segment, VisiblePiece, WindowKind,
    validate_segments, validate_window,
};

use crate::ffi::{GridPoint, open_intersections};
use crate::grid::IntegerGrid;

/// The registry name of [`Clipper2OpenLines`].
pub const OPEN_LINES_NAME: &str = "clipper2-open";

/// Clipper2's open-path clipping, registered as the line clipper `clipper2-open`: each segment an
/// open subject (`AddOpenSubject`) intersected with the window's rings (`AddClip`, even-odd) by
/// the general `Clipper64` engine, one `Execute` per segment.
///
/// A peer, not exact: Clipper2 computes on integers, so the batch and the window share one grid
/// fitted to their joint bounding box ([`IntegerGrid`], a step of about extent x 2^-30), and its
/// pieces are read back as parameters on the input segment, merged and rebuilt on it. Its rules
/// for boundaries (a segment along an edge, through a vertex) are Clipper2's own, which need not
/// be `docs/DESIGN.md`'s closed-set rule: `verify` reports where they differ.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Clipper2OpenLines;

impl LineClipper for Clipper2OpenLines {
    fn name(&self) -> &'static str {
        OPEN_LINES_NAME
    }

    fn capabilities(&self) -> LineCapabilities {
        LineCapabilities { window: WindowKind::Any }
    }

    fn prepare(&self, window: &Polygons) -> Result<Box<dyn PreparedWindow>, ClipError> {
        validate_window(window)?;
        Ok(Box::new(OpenWindow {
            rings: window.rings.iter().map(|r| r.points.clone()).collect(),
            bounds: window.bounds(),
        }))
    }
}

/// The window's rings and bounding box; the grid depends on the batch, so the rings are put on
/// it per batch.
struct OpenWindow {
    rings: Vec<Vec<Point>>,
    bounds: Rect,
}

impl PreparedWindow for OpenWindow {
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError> {
        validate_segments(segments)?;
        let mut kept = Vec::new();
        self.bounds.keep_meeting(segments, &mut kept);
        if kept.is_empty() {
            return Ok(());
        }
        let bounds = kept.iter().fold(self.bounds, |b, &i| b.union(segments[i].bounds()));
        let grid = IntegerGrid::fitting(bounds);
        let rings: Vec<Vec<GridPoint>> =
            self.rings.iter().map(|r| r.iter().map(|&p| grid.to_grid(p)).collect()).collect();
        let subjects: Vec<[GridPoint; 2]> =
            kept.iter().map(|&i| [grid.to_grid(segments[i].a), grid.to_grid(segments[i].b)]).collect();
        let pieces = open_intersections(&rings, &subjects).ok_or_else(|| ClipError::Unsupported {
            clipper: OPEN_LINES_NAME,
            what: "a clip Clipper2 reported as failed, or an output with more than i32::MAX paths or points".into(),
        })?;
        for (&index, paths) in kept.iter().zip(&pieces) {
            let s = &segments[index];
            let edges = paths.iter().flat_map(|path| path.windows(2));
            for (ta, tb) in s.covered_intervals(edges.map(|e| Segment::new(grid.to_point(e[0]), grid.to_point(e[1])))) {
                out.push(VisiblePiece { segment: index, piece: s.piece(ta, tb) });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Ring;

    #[test]
    fn pieces_of_a_segment_across_a_u() {
        let u = Polygons::from(Ring::from(
            &[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)][..],
        ));
        let segments = [
            Segment::new(Point::new(-1.0, 2.0), Point::new(4.0, 2.0)),
            Segment::new(Point::new(-1.0, 5.0), Point::new(4.0, 5.0)),
            Segment::new(Point::new(0.5, 0.5), Point::new(2.5, 0.5)),
        ];
        let mut out = Vec::new();
        Clipper2OpenLines.prepare(&u).unwrap().clip_batch(&segments, &mut out).unwrap();
        let got: Vec<(usize, f64, f64)> = out.iter().map(|p| (p.segment, p.piece.a.x, p.piece.b.x)).collect();
        let close = |x: f64, y: f64| (x - y).abs() < 1e-6;
        assert_eq!(got.len(), 3, "{got:?}");
        assert!(got[0].0 == 0 && close(got[0].1, 0.0) && close(got[0].2, 1.0), "{got:?}");
        assert!(got[1].0 == 0 && close(got[1].1, 2.0) && close(got[1].2, 3.0), "{got:?}");
        assert!(got[2].0 == 2 && close(got[2].1, 0.5) && close(got[2].2, 2.5), "{got:?}");
    }

    #[test]
    fn a_non_finite_segment_is_an_error() {
        let square = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0).to_ring());
        let bad = [Segment::new(Point::new(f64::NAN, 0.0), Point::new(1.0, 1.0))];
        assert!(Clipper2OpenLines.prepare(&square).unwrap().clip_batch(&bad, &mut Vec::new()).is_err());
    }
}
