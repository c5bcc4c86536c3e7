//! clip-curve against the curve oracle on the seeded workloads, the identities, the polygon
//! route (flatten + Vatti) and hand-worked cases.

use core::f64::consts::{FRAC_PI_2, PI, TAU};

use clip_core::{
    BoolOp, ClipError, Ellipse, EllipseArc, FillRule, Point, PolygonClipper, Polygons, Rect, Ring, WindowKind,
};
use clip_curve::{CurveClipper, Stage, flatten_ellipse, flatten_region, flattening_area_bound};
use clip_oracle::curve::{TANGENT_T_TOLERANCE, check_identities, check_region, check_visible, complement_window};
use clip_testkit::workload::{CURVE_WORKLOADS, curve_case};
use clip_vatti::Vatti;

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

#[test]
fn workloads_pass_the_oracle_with_and_without_tests_and_agree() {
    for workload in CURVE_WORKLOADS {
        for kind in [WindowKind::Rectangle, WindowKind::Any, WindowKind::Convex] {
            for index in 0..25 {
                let case = curve_case(workload, 7, index, kind, 24).unwrap();
                let on = CurveClipper::WITH_TESTS.prepare(&case.window).unwrap();
                let off = CurveClipper::WITHOUT_TESTS.prepare(&case.window).unwrap();
                for (k, arc) in case.objects.iter().enumerate() {
                    let what = format!("{workload} {kind:?} case {index} object {k}: {arc:?}");
                    let a = on.visible(arc);
                    let b = off.visible(arc);
                    check_visible(&case.window, arc, &a.intervals).unwrap_or_else(|e| panic!("{what}: {e}"));
                    check_visible(&case.window, arc, &b.intervals).unwrap_or_else(|e| panic!("{what} (no tests): {e}"));
                    assert_eq!(a.intervals.len(), b.intervals.len(), "{what}: {a:?} vs {b:?}");
                    for (x, y) in a.intervals.iter().zip(&b.intervals) {
                        let t = TANGENT_T_TOLERANCE;
                        assert!(close(x.0, y.0, t) && close(x.1, y.1, t), "{what}: {a:?} vs {b:?}");
                    }
                    let rest_window = complement_window(&case.window, &arc.bounds());
                    let c = CurveClipper::WITH_TESTS.prepare(&rest_window).unwrap().visible(arc);
                    if arc.is_closed() {
                        let e = arc.ellipse();
                        let fa = on.clip_filled(e);
                        let fb = off.clip_filled(e);
                        check_region(&case.window, &fa.region).unwrap_or_else(|err| panic!("{what}: {err}"));
                        check_region(&case.window, &fb.region).unwrap_or_else(|err| panic!("{what} (no tests): {err}"));
                        assert!(close(fa.region.area(), fb.region.area(), 1e-9 * e.bounds().area()), "{what}");
                        let out = CurveClipper::WITH_TESTS.prepare(&rest_window).unwrap().clip_filled(e);
                        check_identities(arc, &a.intervals, &c.intervals, Some((fa.region.area(), out.region.area())))
                            .unwrap_or_else(|err| panic!("{what}: {err}"));
                    } else {
                        check_identities(arc, &a.intervals, &c.intervals, None)
                            .unwrap_or_else(|err| panic!("{what}: {err}"));
                    }
                }
            }
        }
    }
}

#[test]
fn the_polygon_route_converges_to_the_exact_area() {
    for workload in CURVE_WORKLOADS {
        for kind in [WindowKind::Rectangle, WindowKind::Any] {
            let case = curve_case(workload, 3, 1, kind, 12).unwrap();
            let prepared = CurveClipper::WITH_TESTS.prepare(&case.window).unwrap();
            for arc in case.objects.iter().filter(|a| a.is_closed()) {
                let e = arc.ellipse();
                let exact = prepared.clip_filled(e).region.area();
                let tolerance = 1e-4 * e.max_radius();
                let ring = flatten_ellipse(e, tolerance).unwrap();
                let clipped = Vatti.clip(&ring, &case.window, BoolOp::Intersection, FillRule::EvenOdd).unwrap();
                let bound =
                    flattening_area_bound(&clip_core::CurveRegion::whole(*e), tolerance) + 1e-9 * e.bounds().area();
                assert!(
                    close(clipped.signed_area(), exact, bound),
                    "{workload} {kind:?}: {} vs {exact}",
                    clipped.signed_area()
                );
                // The region's own flattening lands within its bound too.
                let region = prepared.clip_filled(e).region;
                let flat = flatten_region(&region, tolerance).unwrap();
                assert!(close(
                    flat.signed_area(),
                    exact,
                    flattening_area_bound(&region, tolerance) + 1e-9 * e.bounds().area()
                ));
            }
        }
    }
}

fn square() -> Polygons {
    Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0))
}

#[test]
fn hand_cases_rectangle() {
    let w = square();
    for clipper in [CurveClipper::WITH_TESTS, CurveClipper::WITHOUT_TESTS] {
        let p = clipper.prepare(&w).unwrap();
        // Tangent from outside: a touch point only, nothing visible, nothing filled.
        let t = Ellipse::circle(Point::new(13.0, 5.0), 3.0).unwrap();
        assert!(p.visible(&EllipseArc::full(t)).intervals.is_empty());
        assert_eq!(p.clip_filled(&t).region.area(), 0.0);
        // Tangent from inside: the whole circle, one interval.
        let t = Ellipse::circle(Point::new(7.0, 5.0), 3.0).unwrap();
        assert_eq!(p.visible(&EllipseArc::full(t)).intervals, vec![(0.0, TAU)]);
        assert!(close(p.clip_filled(&t).region.area(), 9.0 * PI, 1e-12));
        // Centred on a corner: a quarter, from 0 to π/2.
        let c = Ellipse::circle(Point::new(0.0, 0.0), 2.0).unwrap();
        let v = p.visible(&EllipseArc::full(c)).intervals;
        assert_eq!(v.len(), 1);
        assert!(close(v[0].0, 0.0, 1e-12) && close(v[0].1, FRAC_PI_2, 1e-12), "{v:?}");
        assert!(close(p.clip_filled(&c).region.area(), PI, 1e-12));
        // The window inside a big circle: the filled result is the window.
        let big = Ellipse::circle(Point::new(5.0, 5.0), 100.0).unwrap();
        assert!(p.visible(&EllipseArc::full(big)).intervals.is_empty());
        assert!(close(p.clip_filled(&big).region.area(), 100.0, 1e-9));
        // A circle over the top edge: the part below y = 10 is a circular segment.
        let s = Ellipse::circle(Point::new(5.0, 9.0), 2.0).unwrap();
        let h: f64 = 1.0;
        let cap = 4.0 * (h / 2.0).acos() - h * (4.0 - h * h).sqrt();
        assert!(close(p.clip_filled(&s).region.area(), 4.0 * PI - cap, 1e-12));
        // An arc across parameter 0 over the right edge.
        let r = Ellipse::circle(Point::new(9.0, 5.0), 2.0).unwrap();
        let arc = EllipseArc::new(r, 1.5 * PI, PI).unwrap();
        let v = p.visible(&arc).intervals;
        assert_eq!(v.len(), 2, "{v:?}");
        assert!(close(v[0].1, 1.5 * PI + PI / 6.0, 1e-12) && close(v[1].0, 1.5 * PI + 5.0 * PI / 6.0, 1e-12), "{v:?}");
    }
}

#[test]
fn hand_cases_polygon_windows() {
    // A square with a square hole, clockwise outer: even-odd ignores orientation.
    let w = Polygons::new(vec![
        Rect::new(0.0, 0.0, 10.0, 10.0).to_ring().reversed(),
        Rect::new(4.0, 4.0, 6.0, 6.0).to_ring(),
    ]);
    let p = CurveClipper::WITH_TESTS.prepare(&w).unwrap();
    let c = Ellipse::circle(Point::new(5.0, 5.0), 3.0).unwrap();
    assert_eq!(p.visible(&EllipseArc::full(c)).intervals, vec![(0.0, TAU)]);
    let f = p.clip_filled(&c);
    assert!(close(f.region.area(), 9.0 * PI - 4.0, 1e-12), "{}", f.region.area());
    check_region(&w, &f.region).unwrap();
    // The same square as a polygon window agrees with the rectangle clipper.
    let sq = square();
    let poly = CurveClipper::WITH_TESTS.prepare_polygon(&sq).unwrap();
    let rect = CurveClipper::WITH_TESTS.prepare(&sq).unwrap();
    let e = Ellipse::new(Point::new(9.0, 2.0), 4.0, 1.5, 0.4).unwrap();
    assert!(close(poly.clip_filled(&e).region.area(), rect.clip_filled(&e).region.area(), 1e-10));
    // A bow-tie window: two triangles of area 25 each.
    let bow = Polygons::from(Ring::new(vec![
        Point::new(0.0, 0.0),
        Point::new(10.0, 10.0),
        Point::new(10.0, 0.0),
        Point::new(0.0, 10.0),
    ]));
    let p = CurveClipper::WITH_TESTS.prepare(&bow).unwrap();
    let big = Ellipse::circle(Point::new(5.0, 5.0), 50.0).unwrap();
    assert!(close(p.clip_filled(&big).region.area(), 50.0, 1e-9));
    // The bounding rectangles settle a far object.
    let far = Ellipse::circle(Point::new(100.0, 100.0), 1.0).unwrap();
    assert_eq!(p.visible(&EllipseArc::full(far)).stage, Stage::BoxReject);
}

#[test]
fn stages_are_the_lectures() {
    let p = CurveClipper::WITH_TESTS.prepare(&Polygons::from(Rect::new(0.0, 0.0, 100.0, 100.0))).unwrap();
    let stage = |c: Point, r: f64| p.visible(&EllipseArc::full(Ellipse::circle(c, r).unwrap())).stage;
    assert_eq!(stage(Point::new(50.0, 50.0), 10.0), Stage::BoxAccept);
    assert_eq!(stage(Point::new(500.0, 50.0), 10.0), Stage::BoxReject);
    // Near a corner, outside: quadrants leave one, its octants settle it.
    assert_eq!(stage(Point::new(108.0, 108.0), 10.0), Stage::Octants);
    // Across an edge: the equations.
    assert_eq!(stage(Point::new(100.0, 50.0), 10.0), Stage::Equations);
    // An ellipse near a corner: quadrants only, then the equations.
    let e = Ellipse::new(Point::new(112.0, 108.0), 14.0, 9.0, 0.0).unwrap();
    assert_eq!(p.visible(&EllipseArc::full(e)).stage, Stage::Equations);
    let e = Ellipse::new(Point::new(130.0, 50.0), 14.0, 9.0, 0.0).unwrap();
    assert_eq!(p.visible(&EllipseArc::full(e)).stage, Stage::BoxReject);
}

#[test]
fn bad_input_is_a_typed_error() {
    assert!(matches!(Ellipse::circle(Point::ZERO, 0.0), Err(ClipError::InvalidCurve { .. })));
    assert!(matches!(Ellipse::circle(Point::ZERO, -2.0), Err(ClipError::InvalidCurve { .. })));
    assert!(matches!(Ellipse::new(Point::new(f64::NAN, 0.0), 1.0, 1.0, 0.0), Err(ClipError::InvalidCurve { .. })));
    let degenerate = Polygons::from(Ring::new(vec![Point::new(0.0, 0.0), Point::new(1.0, 1.0), Point::new(2.0, 2.0)]));
    assert!(matches!(CurveClipper::WITH_TESTS.prepare(&degenerate), Err(ClipError::DegenerateWindow { .. })));
    assert!(CurveClipper::WITH_TESTS.prepare(&Polygons::empty()).is_err());
    let c = Ellipse::circle(Point::ZERO, 1.0).unwrap();
    let region = CurveClipper::WITH_TESTS.prepare(&square()).unwrap().clip_filled(&c).region;
    assert!(matches!(flatten_region(&region, 0.0), Err(ClipError::InvalidCurve { .. })));
}
