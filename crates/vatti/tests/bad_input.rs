//! Bad input gives typed errors; empty operands give empty or the other operand, as each
//! operation defines.

use clip_core::{BoolOp, ClipError, FillRule, Operand, PolygonClipper, Polygons, Rect, Ring};
use clip_oracle::polygon::same_region;
use clip_testkit::workload::invalid_inputs;
use clip_vatti::Vatti;

/// The operand a validation error names, if it is one.
fn operand(e: Option<ClipError>) -> Option<Operand> {
    match e? {
        ClipError::NonFinite { operand, .. }
        | ClipError::OutOfRange { operand, .. }
        | ClipError::TooFewPoints { operand, .. } => Some(operand),
        _ => None,
    }
}

#[test]
fn invalid_inputs_are_typed_errors() {
    let good = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0));
    for (name, bad) in invalid_inputs() {
        for op in BoolOp::ALL {
            let as_subject = Vatti.clip(&bad, &good, op, FillRule::NonZero);
            let as_clip = Vatti.clip(&good, &bad, op, FillRule::EvenOdd);
            let traps = Vatti.clip_trapezoids(&bad, &good, op, FillRule::Positive);
            assert_eq!(operand(as_subject.err()), Some(Operand::Subject), "{name} {op} as subject");
            assert_eq!(operand(as_clip.err()), Some(Operand::Clip), "{name} {op} as clip");
            assert_eq!(operand(traps.err()), Some(Operand::Subject), "{name} {op} trapezoids");
        }
    }
}

#[test]
fn too_few_points_reports_the_count() {
    let two = Polygons::from(Ring::from(&[(0.0, 0.0), (1.0, 1.0)][..]));
    let err = Vatti.clip(&two, &Polygons::empty(), BoolOp::Union, FillRule::NonZero).unwrap_err();
    assert_eq!(err, ClipError::TooFewPoints { operand: Operand::Subject, part: 0, distinct: 2 });
}

#[test]
fn empty_operands() {
    // A concave ring with a hole, so "the other operand" is not trivially one rectangle.
    let a = Polygons::new(vec![
        Ring::from(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, 2.0), (0.0, 4.0)][..]),
        Ring::from(&[(1.0, 1.0), (1.0, 1.5), (1.5, 1.0)][..]),
    ]);
    let none = Polygons::empty();
    for fill in FillRule::ALL {
        let read = |p: &Polygons| (p.clone(), fill);
        for (subject, clip, op, expect_a) in [
            (&a, &none, BoolOp::Intersection, false),
            (&none, &a, BoolOp::Intersection, false),
            (&a, &none, BoolOp::Union, true),
            (&none, &a, BoolOp::Union, true),
            (&a, &none, BoolOp::Difference, true),
            (&none, &a, BoolOp::Difference, false),
            (&a, &none, BoolOp::Xor, true),
            (&none, &a, BoolOp::Xor, true),
        ] {
            let out = Vatti.clip(subject, clip, op, fill).unwrap();
            let (expected, expected_fill) = if expect_a { read(&a) } else { (none.clone(), fill) };
            assert!(
                same_region((&out, FillRule::NonZero), (&expected, expected_fill), 1e-12).is_ok(),
                "{op} {fill}: {out:?}"
            );
            if !expect_a {
                assert!(out.is_empty());
            }
        }
    }
    let both = Vatti.clip(&none, &none, BoolOp::Union, FillRule::NonZero).unwrap();
    assert!(both.is_empty());
    assert!(Vatti.clip_trapezoids(&none, &none, BoolOp::Xor, FillRule::NonZero).unwrap().is_empty());
}
