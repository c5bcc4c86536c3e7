//! clip-curve against the curve oracle on the seeded workloads, the identities, the polygon
//! route (flatten + Vatti) and hand-worked cases.

use core::f64::consts::{FRAC_PI_2, PI, TAU};

use clip_core::{
    ArcFill, BoolOp, ClipError, Ellipse, EllipseArc, FillRule, FilledArc, Point, PolygonClipper, Polygons, Rect, Ring,
    WindowKind,
};
use clip_curve::{CurveClipper, Stage, flatten_filled_arc, flatten_region, flattening_area_bound};
use clip_oracle::curve::{
    TANGENT_T_TOLERANCE, check_filled_region, check_identities, check_region, check_visible, complement_window,
};
use clip_testkit::workload::{CURVE_WORKLOADS, curve_case, filled_object};
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
                    // Around the filled arc too (a sector's centre may lie beyond its arc's box).
                    let rest_window = complement_window(&case.window, &filled_object(*arc, k).bounds());
                    let c = CurveClipper::WITH_TESTS.prepare(&rest_window).unwrap().visible(arc);
                    // Every object filled too: whole ellipses, sectors and chord regions.
                    let filled = filled_object(*arc, k);
                    let e = arc.ellipse();
                    let fa = on.clip_filled_arc(&filled);
                    let fb = off.clip_filled_arc(&filled);
                    check_filled_region(&case.window, &filled, &fa.region)
                        .unwrap_or_else(|err| panic!("{what}: {err}"));
                    check_filled_region(&case.window, &filled, &fb.region)
                        .unwrap_or_else(|err| panic!("{what} (no tests): {err}"));
                    assert!(close(fa.region.area(), fb.region.area(), 1e-9 * e.bounds().area()), "{what}");
                    let out = CurveClipper::WITH_TESTS.prepare(&rest_window).unwrap().clip_filled_arc(&filled);
                    check_identities(
                        arc,
                        &a.intervals,
                        &c.intervals,
                        Some((&filled, fa.region.area(), out.region.area())),
                    )
                    .unwrap_or_else(|err| panic!("{what}: {err}"));
                    if arc.is_closed() {
                        assert_eq!(on.clip_filled(e), fa, "{what}: a whole ellipse is the filled ellipse");
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
            for (k, arc) in case.objects.iter().enumerate() {
                let filled = filled_object(*arc, k);
                let e = arc.ellipse();
                let exact = prepared.clip_filled_arc(&filled).region.area();
                let tolerance = 1e-4 * e.max_radius();
                let ring = flatten_filled_arc(&filled, tolerance).unwrap();
                let clipped = Vatti.clip(&ring, &case.window, BoolOp::Intersection, FillRule::EvenOdd).unwrap();
                let bound = flattening_area_bound(&filled.region(), tolerance) + 1e-9 * e.bounds().area();
                assert!(
                    close(clipped.signed_area(), exact, bound),
                    "{workload} {kind:?} object {k} ({:?}): {} vs {exact}",
                    filled.fill(),
                    clipped.signed_area()
                );
                // The region's own flattening lands within its bound too.
                let region = prepared.clip_filled_arc(&filled).region;
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
    // Filled arcs: empty, negative, over-full and non-finite sweeps or starts are refused when the
    // arc is built, so no FilledArc can hold them.
    for (start, sweep) in [(0.0, 0.0), (0.0, -0.5), (0.0, 7.0), (0.0, f64::NAN), (f64::NAN, 1.0), (f64::INFINITY, 1.0)]
    {
        assert!(matches!(EllipseArc::new(c, start, sweep), Err(ClipError::InvalidCurve { .. })), "{start} {sweep}");
    }
    let sector = FilledArc::new(EllipseArc::new(c, 0.0, 1.0).unwrap(), ArcFill::Sector);
    for tol in [0.0, -1.0, f64::NAN, 1e-300] {
        assert!(matches!(flatten_filled_arc(&sector, tol), Err(ClipError::InvalidCurve { .. })), "{tol}");
    }
}

#[test]
fn hand_cases_filled_arcs() {
    let w = square();
    let poly = CurveClipper::WITH_TESTS.prepare_polygon(&w).unwrap();
    for clipper in [CurveClipper::WITH_TESTS, CurveClipper::WITHOUT_TESTS] {
        let p = clipper.prepare(&w).unwrap();
        // A half disc centred on the bottom edge, upward: the sector and the chord region are the
        // same half disc, wholly in the window.
        let c = Ellipse::circle(Point::new(5.0, 0.0), 2.0).unwrap();
        let up = EllipseArc::new(c, 0.0, PI).unwrap();
        for fill in ArcFill::ALL {
            let got = p.clip_filled_arc(&FilledArc::new(up, fill));
            assert!(close(got.region.area(), 2.0 * PI, 1e-12), "{fill}: {}", got.region.area());
        }
        // The lower half: outside, nothing.
        let down = FilledArc::new(EllipseArc::new(c, PI, PI).unwrap(), ArcFill::Chord);
        assert!(p.clip_filled_arc(&down).region.area().abs() < 1e-12);
        // Three quarters of a disc centred on the corner (0, 0), missing the quarter x, y < 0 ...
        // of which only the quarter x, y > 0 is in the window.
        let corner = Ellipse::circle(Point::ZERO, 3.0).unwrap();
        let three = FilledArc::new(EllipseArc::new(corner, 0.0, 1.5 * PI).unwrap(), ArcFill::Sector);
        assert!(close(p.clip_filled_arc(&three).region.area(), 2.25 * PI, 1e-12));
        // ... and its chord region (the arc with the chord from (0, -3) to (3, 0)): the window
        // keeps the same quarter disc.
        let three_chord = FilledArc::new(*three.arc(), ArcFill::Chord);
        assert!(close(p.clip_filled_arc(&three_chord).region.area(), 2.25 * PI, 1e-12));
        // A rotated elliptic segment across the top edge agrees with the polygon clipper's answer.
        let e = Ellipse::new(Point::new(4.0, 9.0), 5.0, 2.0, 0.5).unwrap();
        for fill in ArcFill::ALL {
            let f = FilledArc::new(EllipseArc::new(e, 2.5, 3.5).unwrap(), fill);
            let (r, q) = (p.clip_filled_arc(&f).region, poly.clip_filled_arc(&f).region);
            assert!(close(r.area(), q.area(), 1e-10), "{fill}: {} vs {}", r.area(), q.area());
            check_filled_region(&w, &f, &r).unwrap();
        }
    }
}
