//! Clipper2's rectangle clipper on hand-made cases: overlap, a result that falls apart, bad input.

use clip_clipper2_rect::Clipper2RectClipper;
use clip_core::{BoolOp, ClipError, FillRule, Operand, Point, PolygonClipper, Polygons, Rect, Ring};

fn window() -> Polygons {
    Polygons::from(Rect::new(0.0, 0.0, 10.0, 6.0).to_ring())
}

fn clip(subject: &Polygons, window: &Polygons, fill: FillRule) -> Result<Polygons, ClipError> {
    Clipper2RectClipper.clip(subject, window, BoolOp::Intersection, fill)
}

#[test]
fn a_square_over_the_corner_keeps_the_overlap_on_the_sides() {
    let subject = Polygons::from(Rect::new(7.0, 4.0, 12.0, 9.0).to_ring());
    let out = clip(&subject, &window(), FillRule::NonZero).unwrap();
    assert_eq!(out.rings.len(), 1, "{out:?}");
    // The cut points sit exactly on the window's sides, and the area is exact.
    assert_eq!(out.signed_area(), 6.0, "{out:?}");
    let bounds = out.bounds();
    assert_eq!((bounds.min, bounds.max), (Point::new(7.0, 4.0), Point::new(10.0, 6.0)));
}

#[test]
fn orientation_is_kept_and_the_rectangle_is_read_under_the_fill_rule() {
    let cw = Polygons::from(Rect::new(-2.0, -2.0, 3.0, 3.0).to_ring().reversed());
    let ccw_window = window();
    let cw_window = Polygons::from(window().rings[0].reversed());
    // RectClip keeps each ring's orientation, whatever the window's.
    assert_eq!(clip(&cw, &ccw_window, FillRule::NonZero).unwrap().signed_area(), -9.0);
    assert_eq!(clip(&cw, &cw_window, FillRule::Negative).unwrap().signed_area(), -9.0);
    // Under positive a clockwise window covers nothing; under negative a counter-clockwise one.
    let ccw = Polygons::from(cw.rings[0].reversed());
    assert_eq!(clip(&ccw, &ccw_window, FillRule::Positive).unwrap().signed_area(), 9.0);
    assert!(clip(&ccw, &cw_window, FillRule::Positive).unwrap().is_empty());
    assert!(clip(&cw, &ccw_window, FillRule::Negative).unwrap().is_empty());
}

#[test]
fn a_concave_u_falls_apart_into_two_rings_without_bridges() {
    // A U whose bottom lies below the window: inside it only the two arms are left.
    let u = Polygons::from(Ring::from(
        &[(1.0, -4.0), (9.0, -4.0), (9.0, 8.0), (7.0, 8.0), (7.0, -1.0), (3.0, -1.0), (3.0, 8.0), (1.0, 8.0)][..],
    ));
    let out = clip(&u, &window(), FillRule::EvenOdd).unwrap();
    assert_eq!(out.rings.len(), 2, "{out:?}");
    let mut areas: Vec<f64> = out.rings.iter().map(Ring::signed_area).collect();
    areas.sort_by(f64::total_cmp);
    assert_eq!(areas, vec![12.0, 12.0]);
}

#[test]
fn rings_inside_outside_and_around_the_window() {
    let inside = Rect::new(1.0, 1.0, 2.0, 2.0).to_ring();
    let outside = Rect::new(20.0, 20.0, 21.0, 21.0).to_ring();
    let around = Rect::new(-5.0, -5.0, 15.0, 15.0).to_ring();
    let subject = Polygons::new(vec![inside.clone(), outside, around]);
    let out = clip(&subject, &window(), FillRule::NonZero).unwrap();
    assert_eq!(out.rings.len(), 2, "{out:?}");
    assert_eq!(out.rings[0], inside);
    assert_eq!(out.rings[1].signed_area(), 60.0);
    assert!(clip(&Polygons::empty(), &window(), FillRule::NonZero).unwrap().is_empty());
}

#[test]
fn far_from_the_origin_the_grid_follows_the_extent() {
    let subject = Polygons::from(Rect::new(500_000.0, 4_000_000.0, 500_000.003, 4_000_000.003).to_ring());
    let window = Polygons::from(Rect::new(500_000.001, 4_000_000.001, 500_000.004, 4_000_000.004).to_ring());
    let out = clip(&subject, &window, FillRule::NonZero).unwrap();
    assert!((out.signed_area() - 4e-6).abs() < 1e-12, "{out:?}");
}

#[test]
fn bad_input_gets_typed_errors() {
    let square = Polygons::from(Rect::new(1.0, 1.0, 2.0, 2.0).to_ring());
    let infinite =
        Polygons::from(Ring::new(vec![Point::new(0.0, 0.0), Point::new(f64::NAN, 1.0), Point::new(1.0, 0.0)]));
    assert!(matches!(
        clip(&infinite, &window(), FillRule::NonZero),
        Err(ClipError::NonFinite { operand: Operand::Subject, part: 0, vertex: 1, .. })
    ));
    let huge = Polygons::from(Ring::new(vec![Point::new(0.0, 0.0), Point::new(1e200, 1.0), Point::new(1.0, 0.0)]));
    assert!(matches!(clip(&huge, &window(), FillRule::NonZero), Err(ClipError::OutOfRange { .. })));
    let line = Polygons::from(Ring::new(vec![Point::new(0.0, 0.0), Point::new(1.0, 1.0), Point::new(0.0, 0.0)]));
    assert!(matches!(clip(&line, &window(), FillRule::NonZero), Err(ClipError::TooFewPoints { .. })));
    let triangle = Polygons::from(Ring::from(&[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)][..]));
    assert!(matches!(clip(&square, &triangle, FillRule::NonZero), Err(ClipError::WindowNotRectangle { .. })));
    let two = Polygons::new(vec![window().rings[0].clone(), Rect::new(20.0, 0.0, 30.0, 6.0).to_ring()]);
    assert!(matches!(clip(&square, &two, FillRule::NonZero), Err(ClipError::WindowNotRectangle { .. })));
    let flat = Polygons::from(Ring::from(&[(0.0, 0.0), (4.0, 0.0), (4.0, 0.0), (0.0, 0.0)][..]));
    assert!(clip(&square, &flat, FillRule::NonZero).is_err());
    assert!(matches!(
        Clipper2RectClipper.clip(&square, &window(), BoolOp::Union, FillRule::NonZero),
        Err(ClipError::Unsupported { .. })
    ));
}
