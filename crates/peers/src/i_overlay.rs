//! i_overlay 9's f64 overlay API (`FloatOverlay`) as a polygon clipper.

use clip_core::{
    BoolOp, ClipError, FillRule, Operand, Point, PolygonCapabilities, PolygonClipper, Polygons, Ring, validate_polygons,
};
use i_overlay::core::fill_rule::FillRule as IFill;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::FloatOverlay;

/// i_overlay 9 (the release after the 4.x that geo 0.33 wraps), called directly: every op under
/// every fill rule.
///
/// Input: every ring is one contour, in order and with its orientation; i_overlay reads
/// counter-clockwise loops as +1 under the fill rule, as we do. It uses its default integer
/// engine (`i32`): `FloatOverlay::with_subj_and_clip` fits a grid to the inputs' extent, so
/// coordinates are snapped to about extent x 2^-31 and the output is compared with
/// `clip_oracle::GEO_TOLERANCE`. Output: the default options (outers counter-clockwise, holes
/// clockwise, collinear points removed), each shape's contours converted ring by ring.
#[derive(Clone, Copy, Debug, Default)]
pub struct IOverlayClipper;

impl IOverlayClipper {
    /// The adapter (it holds no state).
    pub fn new() -> IOverlayClipper {
        IOverlayClipper
    }
}

fn contours(p: &Polygons) -> Vec<Vec<[f64; 2]>> {
    p.rings.iter().map(|r| r.points.iter().map(|q| [q.x, q.y]).collect()).collect()
}

fn overlay_rule(op: BoolOp) -> OverlayRule {
    match op {
        BoolOp::Intersection => OverlayRule::Intersect,
        BoolOp::Union => OverlayRule::Union,
        BoolOp::Difference => OverlayRule::Difference,
        BoolOp::Xor => OverlayRule::Xor,
    }
}

fn fill_rule(fill: FillRule) -> IFill {
    match fill {
        FillRule::EvenOdd => IFill::EvenOdd,
        FillRule::NonZero => IFill::NonZero,
        FillRule::Positive => IFill::Positive,
        FillRule::Negative => IFill::Negative,
    }
}

impl PolygonClipper for IOverlayClipper {
    fn name(&self) -> &'static str {
        "i_overlay"
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities::GENERAL
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        let (subject, clip) = (contours(subject), contours(clip));
        let shapes = FloatOverlay::with_subj_and_clip(&subject, &clip).overlay(overlay_rule(op), fill_rule(fill));
        Ok(Polygons::new(
            shapes
                .iter()
                .flatten()
                .map(|contour| Ring::new(contour.iter().map(|&[x, y]| Point::new(x, y)).collect()))
                .collect(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Rect;

    #[test]
    fn every_op_on_overlapping_squares_with_our_orientation() {
        let a = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
        let b = Polygons::from(Rect::new(1.0, 1.0, 3.0, 3.0));
        for (op, area) in
            [(BoolOp::Intersection, 1.0), (BoolOp::Union, 7.0), (BoolOp::Difference, 3.0), (BoolOp::Xor, 6.0)]
        {
            let out = IOverlayClipper.clip(&a, &b, op, FillRule::EvenOdd).unwrap();
            assert!((out.signed_area() - area).abs() < 1e-9, "{op}: {out:?}");
        }
        // A hole comes out clockwise.
        let inner = Polygons::from(Rect::new(0.5, 0.5, 1.5, 1.5));
        let out = IOverlayClipper.clip(&a, &inner, BoolOp::Difference, FillRule::NonZero).unwrap();
        let mut areas: Vec<f64> = out.rings.iter().map(Ring::signed_area).collect();
        areas.sort_by(f64::total_cmp);
        assert_eq!(areas.len(), 2);
        assert!(areas[0] < 0.0 && areas[1] > 0.0, "{areas:?}");
    }

    #[test]
    fn fill_rules_follow_ring_orientation() {
        let cw = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0).to_ring().reversed());
        let far = Polygons::from(Rect::new(5.0, 5.0, 6.0, 6.0));
        let area = |fill| IOverlayClipper.clip(&cw, &far, BoolOp::Difference, fill).unwrap().signed_area();
        assert_eq!(area(FillRule::Positive), 0.0);
        assert!((area(FillRule::Negative) - 1.0).abs() < 1e-9);
    }

    #[test]
    fn bad_input_is_refused() {
        let bad =
            Polygons::from(Ring::new(vec![Point::new(0.0, 0.0), Point::new(f64::NAN, 1.0), Point::new(1.0, 0.0)]));
        assert!(matches!(
            IOverlayClipper.clip(&bad, &Polygons::empty(), BoolOp::Union, FillRule::EvenOdd),
            Err(ClipError::NonFinite { operand: Operand::Subject, .. })
        ));
    }
}
