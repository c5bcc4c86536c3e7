//! Sutherland-Hodgman on the notes' examples, on bad input, and both forms against each other.

use clip_core::{BoolOp, ClipError, FillRule, Point, PolygonClipper, Polygons, Rect, Ring, WindowKind};
use clip_sutherland_hodgman::{ConvexWindow, Form, Pipeline, SutherlandHodgman, bridge_count, clip_list};
use clip_testkit::workload::polygon_case;

fn ring(points: &[(f64, f64)]) -> Ring {
    Ring::from(points)
}

fn pts(points: &[(f64, f64)]) -> Vec<Point> {
    points.iter().map(|&p| p.into()).collect()
}

/// True when `a` is `b` started at another vertex (each stage starts its list one edge later).
fn same_cycle(a: &[Point], b: &[Point]) -> bool {
    a.len() == b.len() && (a.is_empty() || (0..b.len()).any(|k| b[k..].iter().chain(&b[..k]).eq(a.iter())))
}

fn clip(subject: &Polygons, window: &Polygons) -> Result<Polygons, ClipError> {
    SutherlandHodgman::default().clip(subject, window, BoolOp::Intersection, FillRule::NonZero)
}

/// Fig. 6-21: vertices 1 and 2 outside the left boundary, 3, 4, 5 inside, 6 outside. The stage
/// saves the crossing on 2-3, vertices 3, 4 and 5, and the crossing on 5-6: five points. The
/// window is wide enough that only its left boundary (x = 0) cuts.
#[test]
fn figure_6_21_left_boundary_saves_five_points() {
    let subject = pts(&[(-2.0, 1.0), (-3.0, 4.0), (2.0, 6.0), (4.0, 3.0), (3.0, 0.0), (-1.0, -1.0)]);
    let window = ConvexWindow::new(&Polygons::from(Rect::new(0.0, -100.0, 100.0, 100.0))).unwrap();
    let out = clip_list(&subject, &window);
    let saved = pts(&[(0.0, 5.2), (2.0, 6.0), (4.0, 3.0), (3.0, 0.0), (0.0, -0.75)]);
    assert!(same_cycle(&out, &saved), "{out:?}");
}

#[test]
fn list_and_pipeline_forms_give_identical_vertices() {
    let mut rings = 0;
    for workload in ["vatti-t3", "star", "grid", "scribble", "holes"] {
        for kind in [WindowKind::Convex, WindowKind::Rectangle] {
            for index in 0..40 {
                let case = polygon_case(workload, 4, index, kind).unwrap();
                let window = ConvexWindow::new(&case.clip).unwrap();
                for r in &case.subject.rings {
                    let mut pipeline = Pipeline::new(&window);
                    r.points.iter().for_each(|&p| pipeline.push(p));
                    assert_eq!(pipeline.finish(), clip_list(&r.points, &window), "{}", case.description);
                    rings += 1;
                }
            }
        }
    }
    assert!(rings >= 400);
}

#[test]
fn a_pipeline_can_be_reused_ring_after_ring() {
    let window = ConvexWindow::new(&Polygons::from(Rect::new(0.0, 0.0, 4.0, 4.0))).unwrap();
    let tri = pts(&[(-1.0, 1.0), (6.0, 1.0), (2.0, 6.0)]);
    let mut pipeline = Pipeline::new(&window);
    for _ in 0..3 {
        tri.iter().for_each(|&p| pipeline.push(p));
        assert_eq!(pipeline.finish(), clip_list(&tri, &window));
    }
}

#[test]
fn subject_inside_is_kept_outside_is_dropped_and_enclosing_gives_the_window() {
    let window = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
    let inside = Polygons::from(ring(&[(1.0, 1.0), (3.0, 1.0), (2.0, 4.0)]));
    let kept = clip(&inside, &window).unwrap();
    assert_eq!(kept.rings.len(), 1);
    assert!(same_cycle(&kept.rings[0].points, &inside.rings[0].points));
    let outside = Polygons::from(ring(&[(11.0, 1.0), (13.0, 1.0), (12.0, 4.0)]));
    assert!(clip(&outside, &window).unwrap().is_empty());
    let around = Polygons::from(Rect::new(-5.0, -5.0, 15.0, 15.0));
    let out = clip(&around, &window).unwrap();
    assert_eq!(out.rings.len(), 1);
    assert_eq!(out.signed_area(), 100.0);
}

#[test]
fn either_window_orientation_and_any_edge_count() {
    let subject = Polygons::from(ring(&[(0.0, 0.0), (8.0, 1.0), (9.0, 9.0), (4.0, 3.0), (1.0, 8.0)]));
    let octagon: Vec<Point> = (0..8)
        .map(|k| {
            let a = std::f64::consts::PI * (0.125 + 0.25 * f64::from(k));
            Point::new(5.0 + 4.0 * a.cos(), 5.0 + 4.0 * a.sin())
        })
        .collect();
    let ccw = Polygons::from(Ring::new(octagon.clone()));
    let cw = Polygons::from(Ring::new(octagon).reversed());
    let (a, b) = (clip(&subject, &ccw).unwrap(), clip(&subject, &cw).unwrap());
    assert!((a.signed_area() - b.signed_area()).abs() < 1e-12);
    assert!(a.signed_area() > 0.0);
    // A collinear extra vertex on the window changes nothing.
    let square = Polygons::from(ring(&[(0.0, 0.0), (5.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]));
    let plain = Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0));
    assert_eq!(clip(&subject, &square).unwrap(), clip(&subject, &plain).unwrap());
}

#[test]
fn output_keeps_each_rings_orientation() {
    let window = Polygons::from(Rect::new(0.0, 0.0, 4.0, 4.0));
    let outer = Rect::new(-1.0, -1.0, 3.0, 3.0).to_ring();
    let hole = Rect::new(1.0, 1.0, 2.0, 2.0).to_ring().reversed();
    let out = clip(&Polygons::new(vec![outer, hole]), &window).unwrap();
    assert_eq!(out.rings.len(), 2);
    assert_eq!(out.rings[0].signed_area(), 9.0);
    assert_eq!(out.rings[1].signed_area(), -1.0);
}

#[test]
fn bridges_are_counted_where_the_result_falls_apart() {
    let window = Polygons::from(Rect::new(-1.0, 2.0, 20.0, 4.0));
    let prepared = ConvexWindow::new(&window).unwrap();
    let u = Polygons::from(ring(&[
        (0.0, 0.0),
        (3.0, 0.0),
        (3.0, 3.0),
        (2.0, 3.0),
        (2.0, 1.0),
        (1.0, 1.0),
        (1.0, 3.0),
        (0.0, 3.0),
    ]));
    assert_eq!(bridge_count(&u, &prepared), 1);
    // A comb of three teeth: three pieces, two bridges.
    let comb = Polygons::from(ring(&[
        (0.0, 0.0),
        (5.0, 0.0),
        (5.0, 3.0),
        (4.0, 3.0),
        (4.0, 1.0),
        (3.0, 1.0),
        (3.0, 3.0),
        (2.0, 3.0),
        (2.0, 1.0),
        (1.0, 1.0),
        (1.0, 3.0),
        (0.0, 3.0),
    ]));
    assert_eq!(bridge_count(&comb, &prepared), 2);
    let (out, bridges) = SutherlandHodgman::default().clip_counting_bridges(&comb, &window).unwrap();
    assert_eq!((out.rings.len(), bridges), (1, 2));
    assert_eq!(out.signed_area(), 3.0);
    // Nothing falls apart: no bridge.
    let block = Polygons::from(Rect::new(0.0, 0.0, 5.0, 3.0));
    assert_eq!(bridge_count(&block, &prepared), 0);
    // The same comb against a slanted convex window still gets its bridges counted exactly.
    let slanted = Polygons::from(ring(&[(-1.0, 2.5), (20.0, 1.5), (20.0, 6.0), (-1.0, 6.0)]));
    assert_eq!(bridge_count(&comb, &ConvexWindow::new(&slanted).unwrap()), 2);
}

#[test]
fn bad_input_gets_a_typed_error() {
    let subject = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
    let sh = SutherlandHodgman::default();
    let concave = Polygons::from(ring(&[(0.0, 0.0), (4.0, 0.0), (2.0, 1.0), (4.0, 4.0), (0.0, 4.0)]));
    assert!(matches!(clip(&subject, &concave), Err(ClipError::WindowNotConvex { .. })));
    let two = Polygons::new(vec![Rect::new(0.0, 0.0, 1.0, 1.0).to_ring(), Rect::new(2.0, 2.0, 3.0, 3.0).to_ring()]);
    assert!(matches!(clip(&subject, &two), Err(ClipError::WindowNotConvex { .. })));
    let flat = Polygons::from(ring(&[(0.0, 0.0), (4.0, 0.0), (2.0, 0.0)]));
    assert!(matches!(clip(&subject, &flat), Err(ClipError::DegenerateWindow { .. } | ClipError::TooFewPoints { .. })));
    let line = Polygons::from(ring(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0)]));
    assert!(matches!(clip(&subject, &line), Err(ClipError::DegenerateWindow { .. })));
    assert!(matches!(clip(&subject, &Polygons::empty()), Err(ClipError::DegenerateWindow { .. })));
    let nan = Polygons::from(ring(&[(0.0, 0.0), (f64::NAN, 1.0), (1.0, 1.0)]));
    assert!(matches!(clip(&nan, &subject), Err(ClipError::NonFinite { .. })));
    assert!(matches!(clip(&subject, &nan), Err(ClipError::NonFinite { .. })));
    let two_points = Polygons::from(ring(&[(0.0, 0.0), (1.0, 1.0), (0.0, 0.0), (1.0, 1.0)]));
    assert!(matches!(clip(&two_points, &subject), Err(ClipError::TooFewPoints { .. })));
    for op in [BoolOp::Union, BoolOp::Difference, BoolOp::Xor] {
        assert!(matches!(sh.clip(&subject, &subject, op, FillRule::EvenOdd), Err(ClipError::Unsupported { .. })));
    }
    assert!(clip(&Polygons::empty(), &subject).unwrap().is_empty());
}

#[test]
fn capabilities_say_what_it_does() {
    let caps = SutherlandHodgman::new(Form::Pipeline).capabilities();
    assert_eq!(caps.ops, &[BoolOp::Intersection]);
    assert_eq!(caps.window, WindowKind::Convex);
    assert!(caps.bridges && !caps.trapezoids);
    assert!(FillRule::ALL.iter().all(|f| caps.supports(BoolOp::Intersection, *f)));
    assert_eq!(SutherlandHodgman::default().name(), "sutherland-hodgman");
}
