//! The pure-Rust port of Clipper2 (the `clipper2-rust` crate) as a polygon clipper.

use clip_clipper2_rect::IntegerGrid;
use clip_core::{
    BoolOp, ClipError, FillRule, Operand, PolygonCapabilities, PolygonClipper, Polygons, Ring, validate_polygons,
};
use clipper2_rust::{ClipType, FillRule as RFill, Paths64, Point64, boolean_op_64};

/// `clipper2-rust`'s `boolean_op_64`: all four ops under all four fill rules, on the same
/// integer grid as the C++ [`Clipper2Clipper`](crate::Clipper2Clipper) (fitted to each call's
/// inputs, step about extent x 2^-30), so the two are compared on the same integers and a
/// difference between them is the port's. Rings are passed in order with their orientation;
/// the output (outers counter-clockwise, holes clockwise, as in Clipper2) is moved back ring by
/// ring.
#[derive(Clone, Copy, Debug, Default)]
pub struct Clipper2RustClipper;

impl Clipper2RustClipper {
    /// The adapter (it holds no state).
    pub fn new() -> Clipper2RustClipper {
        Clipper2RustClipper
    }
}

fn to_paths(p: &Polygons, grid: IntegerGrid) -> Paths64 {
    p.rings
        .iter()
        .map(|r| {
            r.points
                .iter()
                .map(|&q| {
                    let [x, y] = grid.to_grid(q);
                    Point64::new(x, y)
                })
                .collect()
        })
        .collect()
}

fn clip_type(op: BoolOp) -> ClipType {
    match op {
        BoolOp::Intersection => ClipType::Intersection,
        BoolOp::Union => ClipType::Union,
        BoolOp::Difference => ClipType::Difference,
        BoolOp::Xor => ClipType::Xor,
    }
}

fn fill_rule(fill: FillRule) -> RFill {
    match fill {
        FillRule::EvenOdd => RFill::EvenOdd,
        FillRule::NonZero => RFill::NonZero,
        FillRule::Positive => RFill::Positive,
        FillRule::Negative => RFill::Negative,
    }
}

impl PolygonClipper for Clipper2RustClipper {
    fn name(&self) -> &'static str {
        "clipper2-rust"
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities::GENERAL
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        validate_polygons(clip, Operand::Clip)?;
        let grid = IntegerGrid::fitting(subject.bounds().union(clip.bounds()));
        let out = boolean_op_64(clip_type(op), fill_rule(fill), &to_paths(subject, grid), &to_paths(clip, grid));
        Ok(Polygons::new(
            out.iter().map(|path| Ring::new(path.iter().map(|q| grid.to_point([q.x, q.y])).collect())).collect(),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Clipper2Clipper;
    use clip_core::Rect;

    #[test]
    fn every_op_matches_the_cpp_clipper2_on_the_same_grid() {
        let a = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
        let b = Polygons::from(Ring::from(&[(1.0, 0.5), (3.0, 1.0), (1.5, 3.0)][..]));
        for op in BoolOp::ALL {
            for fill in FillRule::ALL {
                let port = Clipper2RustClipper.clip(&a, &b, op, fill).unwrap();
                let cpp = Clipper2Clipper::new().clip(&a, &b, op, fill).unwrap();
                assert_eq!(port.signed_area(), cpp.signed_area(), "{op} {fill}");
            }
        }
    }

    #[test]
    fn holes_come_out_clockwise() {
        let a = Polygons::from(Rect::new(0.0, 0.0, 4.0, 4.0));
        let b = Polygons::from(Rect::new(1.0, 1.0, 2.0, 2.0));
        let out = Clipper2RustClipper.clip(&a, &b, BoolOp::Difference, FillRule::NonZero).unwrap();
        let mut areas: Vec<f64> = out.rings.iter().map(Ring::signed_area).collect();
        areas.sort_by(f64::total_cmp);
        assert_eq!(areas, vec![-1.0, 16.0]);
    }

    #[test]
    fn bad_input_is_refused() {
        let bad = Polygons::from(Ring::from(&[(0.0, 0.0), (1.0, 0.0), (1.0, 0.0)][..]));
        assert!(matches!(
            Clipper2RustClipper.clip(&Polygons::empty(), &bad, BoolOp::Union, FillRule::EvenOdd),
            Err(ClipError::TooFewPoints { operand: Operand::Clip, .. })
        ));
    }
}
