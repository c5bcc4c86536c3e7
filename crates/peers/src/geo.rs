//! `geo` 0.33's `BooleanOps` (i_overlay underneath) as a polygon clipper and a line clipper.

use clip_core::{
    BoolOp, ClipError, FillRule, LineCapabilities, LineClipper, Operand, PolygonCapabilities, PolygonClipper, Polygons,
    PreparedWindow, Segment, VisiblePiece, WindowKind, validate_polygons, validate_segments, validate_window,
};
use geo::algorithm::bool_ops::{BooleanOps, FillRule as GeoFill, OpType};
use geo::{LineString, MultiLineString, MultiPolygon, Polygon};

/// `geo`'s boolean operations, every op under every fill rule (`*_with_fill_rule`).
///
/// Input: each of our rings becomes the exterior of its own `geo::Polygon`, in order and with
/// its orientation, so i_overlay sees exactly our ring list: `BooleanOps` hands every ring to
/// i_overlay as it is (it does not reorient rings), and i_overlay reads them under the fill rule
/// with counter-clockwise loops counting +1, as we do. Output: `OverlayOptions::ogc()`, outers
/// counter-clockwise and holes clockwise, converted ring by ring without further change.
/// Coordinates are snapped to i_overlay's integer grid (about extent x 1e-9).
#[derive(Clone, Copy, Debug, Default)]
pub struct GeoClipper;

impl GeoClipper {
    /// The adapter (it holds no state).
    pub fn new() -> GeoClipper {
        GeoClipper
    }
}

/// Our rings, each as the exterior of its own polygon, in order, orientation kept.
fn ring_list(p: &Polygons) -> MultiPolygon<f64> {
    MultiPolygon(p.rings.iter().map(|r| Polygon::new(LineString::from(r), Vec::new())).collect())
}

fn geo_fill(fill: FillRule) -> GeoFill {
    match fill {
        FillRule::EvenOdd => GeoFill::EvenOdd,
        FillRule::NonZero => GeoFill::NonZero,
        FillRule::Positive => GeoFill::Positive,
        FillRule::Negative => GeoFill::Negative,
    }
}

fn geo_op(op: BoolOp) -> OpType {
    match op {
        BoolOp::Intersection => OpType::Intersection,
        BoolOp::Union => OpType::Union,
        BoolOp::Difference => OpType::Difference,
        BoolOp::Xor => OpType::Xor,
    }
}

impl PolygonClipper for GeoClipper {
    fn name(&self) -> &'static str {
        "geo"
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities::GENERAL
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        let result = ring_list(subject).boolean_op_with_fill_rule(&ring_list(clip), geo_op(op), geo_fill(fill));
        Ok(Polygons::from(&result))
    }
}

/// `geo`'s `BooleanOps::clip` (boundary included) as a line clipper, one segment per call.
///
/// One call per segment because i_overlay clips all the lines of a call together, which is very
/// slow for large batches. The window's rings are read under even-odd, as docs/DESIGN.md asks.
///
/// geo's pieces are normalised into our [`VisiblePiece`] form: each output line string is cut
/// into its edges, each edge is re-expressed by the parameters `t` of its end points projected
/// onto the input segment (geo's coordinates are snapped to its grid, so they may sit a grid
/// step off the segment), clamped to `[0, 1]` and turned to increasing `t`; edges of zero length
/// are dropped, the rest sorted by `t` and touching or overlapping ones merged (geo splits a
/// segment where it passes a window vertex). Each merged interval becomes one piece from
/// `P(ta)` to `P(tb)`, the input's own end points at `t = 0` and `t = 1`.
#[derive(Clone, Copy, Debug, Default)]
pub struct GeoLineClipper;

impl GeoLineClipper {
    /// The adapter (it holds no state).
    pub fn new() -> GeoLineClipper {
        GeoLineClipper
    }
}

impl LineClipper for GeoLineClipper {
    fn name(&self) -> &'static str {
        "geo"
    }

    fn capabilities(&self) -> LineCapabilities {
        LineCapabilities { window: WindowKind::Any }
    }

    fn prepare(&self, window: &Polygons) -> Result<Box<dyn PreparedWindow>, ClipError> {
        validate_window(window)?;
        Ok(Box::new(GeoWindow { rings: ring_list(window) }))
    }
}

/// A window as geo rings.
struct GeoWindow {
    rings: MultiPolygon<f64>,
}

impl PreparedWindow for GeoWindow {
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError> {
        validate_segments(segments)?;
        for (index, s) in segments.iter().enumerate() {
            if s.is_degenerate() {
                continue;
            }
            let line = MultiLineString(vec![LineString::from(vec![s.a, s.b])]);
            let clipped = self.rings.clip_with_fill_rule(&line, false, GeoFill::EvenOdd);
            let pieces = clipped.0.iter().flat_map(|ls| ls.lines()).map(|l| Segment::new(l.start.into(), l.end.into()));
            for (ta, tb) in s.covered_intervals(pieces) {
                out.push(VisiblePiece { segment: index, piece: s.piece(ta, tb) });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{Point, Rect, Ring};

    fn square(x0: f64, y0: f64, size: f64) -> Ring {
        Rect::new(x0, y0, x0 + size, y0 + size).to_ring()
    }

    #[test]
    fn intersection_of_overlapping_squares() {
        let a = Polygons::from(square(0.0, 0.0, 2.0));
        let b = Polygons::from(square(1.0, 1.0, 2.0));
        let out = GeoClipper.clip(&a, &b, BoolOp::Intersection, FillRule::NonZero).unwrap();
        assert_eq!(out.rings.len(), 1);
        assert!((out.signed_area() - 1.0).abs() < 1e-9);
    }

    #[test]
    fn fill_rules_follow_ring_orientation() {
        // A counter-clockwise square counts +1 inside; the same square clockwise counts -1.
        let ccw = Polygons::from(square(0.0, 0.0, 1.0));
        let cw = Polygons::from(square(0.0, 0.0, 1.0).reversed());
        let area =
            |p: &Polygons, fill| GeoClipper.clip(p, &Polygons::empty(), BoolOp::Union, fill).unwrap().signed_area();
        assert!((area(&ccw, FillRule::Positive) - 1.0).abs() < 1e-9);
        assert_eq!(area(&ccw, FillRule::Negative), 0.0);
        assert_eq!(area(&cw, FillRule::Positive), 0.0);
        assert!((area(&cw, FillRule::Negative) - 1.0).abs() < 1e-9);
    }

    #[test]
    fn two_nested_same_direction_rings_differ_under_even_odd_and_non_zero() {
        // Both counter-clockwise: non-zero fills the inner square, even-odd makes it a hole.
        let p = Polygons::new(vec![square(0.0, 0.0, 4.0), square(1.0, 1.0, 2.0)]);
        let area = |fill| GeoClipper.clip(&p, &Polygons::empty(), BoolOp::Union, fill).unwrap().signed_area();
        assert!((area(FillRule::NonZero) - 16.0).abs() < 1e-9);
        assert!((area(FillRule::EvenOdd) - 12.0).abs() < 1e-9);
    }

    #[test]
    fn bad_input_is_a_typed_error() {
        let bad =
            Polygons::from(Ring::new(vec![Point::new(0.0, 0.0), Point::new(f64::NAN, 1.0), Point::new(1.0, 0.0)]));
        let ok = Polygons::from(square(0.0, 0.0, 1.0));
        assert!(matches!(
            GeoClipper.clip(&bad, &ok, BoolOp::Union, FillRule::EvenOdd),
            Err(ClipError::NonFinite { operand: Operand::Subject, .. })
        ));
    }

    #[test]
    fn line_pieces_are_merged_across_window_vertices_and_keep_direction() {
        // A window with a vertex at (2, 2) on the segment's path; the segment runs right to left.
        let window = Polygons::from(Ring::from(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, 2.0), (0.0, 4.0)][..]));
        let prepared = GeoLineClipper.prepare(&window).unwrap();
        let seg = Segment::new(Point::new(5.0, 1.0), Point::new(-1.0, 1.0));
        let along_edge = Segment::new(Point::new(0.0, 0.0), Point::new(4.0, 0.0));
        let mut out = Vec::new();
        prepared.clip_batch(&[seg, along_edge], &mut out).unwrap();
        assert_eq!(out.len(), 2, "{out:?}");
        let p = out[0].piece;
        assert_eq!(out[0].segment, 0);
        assert!((p.a.x - 4.0).abs() < 1e-6 && (p.b.x - 0.0).abs() < 1e-6, "{p:?}");
        // The boundary is part of the closed window.
        assert_eq!(out[1].segment, 1);
        assert!((out[1].piece.length() - 4.0).abs() < 1e-6);
    }

    #[test]
    fn concave_window_splits_a_segment_into_ordered_pieces() {
        // A U shape: the segment crosses both arms.
        let window = Polygons::from(Ring::from(
            &[(0.0, 0.0), (6.0, 0.0), (6.0, 4.0), (4.0, 4.0), (4.0, 2.0), (2.0, 2.0), (2.0, 4.0), (0.0, 4.0)][..],
        ));
        let prepared = GeoLineClipper.prepare(&window).unwrap();
        let seg = Segment::new(Point::new(-1.0, 3.0), Point::new(7.0, 3.0));
        let mut out = Vec::new();
        prepared.clip_batch(&[seg], &mut out).unwrap();
        let xs: Vec<(f64, f64)> = out.iter().map(|v| (v.piece.a.x, v.piece.b.x)).collect();
        assert_eq!(xs.len(), 2, "{xs:?}");
        assert!((xs[0].0 - 0.0).abs() < 1e-6 && (xs[0].1 - 2.0).abs() < 1e-6, "{xs:?}");
        assert!((xs[1].0 - 4.0).abs() < 1e-6 && (xs[1].1 - 6.0).abs() < 1e-6, "{xs:?}");
    }
}
