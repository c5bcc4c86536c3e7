//! The polygon oracle: exact areas on known shapes, and deliberately wrong answers caught.

use clip_core::{BoolOp, FillRule, Point, Polygons, Rect, Ring, WindowKind};
use clip_oracle::polygon::*;
use clip_testkit::workload::polygon_case;
use proptest::prelude::*;

fn ring(points: &[(f64, f64)]) -> Ring {
    Ring::from(points)
}

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Polygons {
    Polygons::from(Rect::new(x0, y0, x1, y1))
}

fn area(p: &Polygons, fill: FillRule) -> f64 {
    region_area(&[(p, fill)], |i| i[0])
}

const EXACT: OutputRules =
    OutputRules { conventional: true, output_fill: FillRule::NonZero, relative_tolerance: REGION_TOLERANCE };

/// Subject [0,2]², clip [1,3]², and the four right answers.
fn squares() -> (Polygons, Polygons, [(BoolOp, Polygons); 4]) {
    let (a, b) = (rect(0.0, 0.0, 2.0, 2.0), rect(1.0, 1.0, 3.0, 3.0));
    let union = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 3.0), (1.0, 2.0), (0.0, 2.0)]);
    let difference = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)]);
    let other = ring(&[(2.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 3.0), (1.0, 2.0), (2.0, 2.0)]);
    let answers = [
        (BoolOp::Intersection, rect(1.0, 1.0, 2.0, 2.0)),
        (BoolOp::Union, union.into()),
        (BoolOp::Difference, difference.clone().into()),
        (BoolOp::Xor, vec![difference, other].into()),
    ];
    (a, b, answers)
}

#[test]
fn region_area_is_exact_on_known_shapes() {
    let (a, b, _) = squares();
    assert_eq!(area(&rect(0.0, 0.0, 2.0, 3.0), FillRule::NonZero), 6.0);
    let both =
        |p: fn(bool, bool) -> bool| region_area(&[(&a, FillRule::NonZero), (&b, FillRule::NonZero)], |i| p(i[0], i[1]));
    assert_eq!(both(|x, y| x || y), 7.0);
    assert_eq!(both(|x, y| x && y), 1.0);
    assert_eq!(both(|x, y| x != y), 6.0);
    assert_eq!(both(|x, y| x && !y), 3.0);
    // A bow-tie: a counter-clockwise and a clockwise triangle of area 25 each.
    let bow = Polygons::from(ring(&[(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 10.0)]));
    assert_eq!(area(&bow, FillRule::EvenOdd), 50.0);
    assert_eq!(area(&bow, FillRule::NonZero), 50.0);
    assert_eq!(area(&bow, FillRule::Positive), 25.0);
    assert_eq!(area(&bow, FillRule::Negative), 25.0);
    // A ring and its copy: cancelled under even-odd, doubled (still the square) under non-zero.
    let twice = Polygons::new(vec![Rect::new(0.0, 0.0, 4.0, 4.0).to_ring(), Rect::new(0.0, 0.0, 4.0, 4.0).to_ring()]);
    assert_eq!(area(&twice, FillRule::EvenOdd), 0.0);
    assert_eq!(area(&twice, FillRule::NonZero), 16.0);
    assert_eq!(area(&twice, FillRule::Negative), 0.0);
    // A clockwise square is inside under non-zero and negative only.
    let cw = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0).to_ring().reversed());
    assert_eq!((area(&cw, FillRule::Positive), area(&cw, FillRule::Negative)), (0.0, 4.0));
    // A square with a hole; a pentagram, whose centre winds twice.
    let holed = Polygons::new(vec![
        Rect::new(0.0, 0.0, 10.0, 10.0).to_ring(),
        Rect::new(3.0, 3.0, 7.0, 7.0).to_ring().reversed(),
    ]);
    assert_eq!(area(&holed, FillRule::NonZero), 84.0);
    let star: Vec<Point> = (0..5)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2 + 4.0 * std::f64::consts::PI * f64::from(k) / 5.0;
            Point::new(a.cos(), a.sin())
        })
        .collect();
    let star = Polygons::from(Ring::new(star));
    let (eo, nz) = (area(&star, FillRule::EvenOdd), area(&star, FillRule::NonZero));
    // Non-zero covers the pentagon too; the pentagon is the star's centre, winding 2.
    let pentagon_area = nz - eo;
    let (s36, s72) = (36f64.to_radians().sin(), 72f64.to_radians().sin());
    let inner = 72f64.to_radians().cos() / 36f64.to_radians().cos(); // the pentagon's circumradius
    assert!((nz - 5.0 * inner * s36).abs() < 1e-12, "{nz}");
    assert!((pentagon_area - 2.5 * inner * inner * s72).abs() < 1e-12, "{pentagon_area}");
    assert_eq!(area(&Polygons::empty(), FillRule::NonZero), 0.0);
}

#[test]
fn right_answers_pass() {
    let (a, b, answers) = squares();
    for (op, out) in &answers {
        check_polygon_result(&a, &b, *op, FillRule::NonZero, out, &EXACT).unwrap_or_else(|e| panic!("{op}: {e}"));
        check_polygon_result(&a, &b, *op, FillRule::EvenOdd, out, &EXACT).unwrap_or_else(|e| panic!("{op}: {e}"));
    }
    let outs: Vec<(BoolOp, &Polygons)> = answers.iter().map(|(o, p)| (*o, p)).collect();
    check_area_identities(&a, &b, FillRule::NonZero, &outs, &EXACT).unwrap();
}

#[test]
fn a_dropped_ring_is_caught() {
    let (a, b, answers) = squares();
    let mut xor = answers[3].1.clone();
    xor.rings.pop();
    let e = check_polygon_result(&a, &b, BoolOp::Xor, FillRule::NonZero, &xor, &EXACT).unwrap_err();
    assert!(matches!(e, PolygonFailure::WrongPoint { expected: true, got: false, .. }), "{e}");
}

#[test]
fn a_flipped_op_is_caught() {
    let (a, b, answers) = squares();
    for (op, out) in &answers {
        for (other, _) in &answers {
            if other != op {
                assert!(
                    check_polygon_result(&a, &b, *other, FillRule::NonZero, out, &EXACT).is_err(),
                    "{op} passed as {other}"
                );
            }
        }
    }
    // And the identities notice a union standing in for an intersection.
    let outs = [(BoolOp::Intersection, &answers[1].1), (BoolOp::Union, &answers[1].1)];
    assert!(matches!(
        check_area_identities(&a, &b, FillRule::NonZero, &outs, &EXACT),
        Err(PolygonFailure::AreaIdentity(_))
    ));
}

#[test]
fn a_shifted_vertex_is_caught_even_between_sample_points() {
    let (a, b, answers) = squares();
    let mut union = answers[1].1.clone();
    union.rings[0].points[4].x += 1e-3; // (3, 3) -> (3.001, 3): a sliver of area 1e-3
    let e = check_polygon_result(&a, &b, BoolOp::Union, FillRule::NonZero, &union, &EXACT).unwrap_err();
    assert!(matches!(e, PolygonFailure::WrongRegion { .. }), "{e}");
    // Within the tolerance it passes: 1e-12 of an ulp-sized shift.
    let mut close = answers[1].1.clone();
    close.rings[0].points[4].x += 1e-12;
    check_polygon_result(&a, &b, BoolOp::Union, FillRule::NonZero, &close, &EXACT).unwrap();
}

#[test]
fn a_reversed_hole_is_caught() {
    let holed = Polygons::new(vec![
        Rect::new(0.0, 0.0, 10.0, 10.0).to_ring(),
        Rect::new(3.0, 3.0, 7.0, 7.0).to_ring().reversed(),
    ]);
    let big = rect(-1.0, -1.0, 11.0, 11.0);
    check_polygon_result(&holed, &big, BoolOp::Intersection, FillRule::NonZero, &holed, &EXACT).unwrap();
    let mut wrong = holed.clone();
    wrong.rings[1] = wrong.rings[1].reversed();
    let e = check_polygon_result(&holed, &big, BoolOp::Intersection, FillRule::NonZero, &wrong, &EXACT).unwrap_err();
    assert!(matches!(&e, PolygonFailure::Invalid(m) if m.contains("hole")), "{e}");
    // Read as bridged output (no form check), the region is wrong.
    let loose = OutputRules::bridged(FillRule::NonZero, REGION_TOLERANCE);
    assert!(check_polygon_result(&holed, &big, BoolOp::Intersection, FillRule::NonZero, &wrong, &loose).is_err());
}

#[test]
fn crossing_output_is_caught() {
    let bow = Polygons::from(ring(&[(0.0, 0.0), (10.0, 10.0), (10.0, 0.0), (0.0, 10.0)]));
    assert!(matches!(check_valid_output(&bow), Err(PolygonFailure::Invalid(m)) if m.contains("crosses")));
    // Two rings crossing only where one's edge runs through the other's vertices.
    let square = Rect::new(0.0, 0.0, 2.0, 2.0).to_ring();
    let through = ring(&[(-1.0, -1.0), (3.0, 3.0), (4.0, 0.0), (0.0, -2.0)]);
    let e = check_valid_output(&Polygons::new(vec![square.clone(), through])).unwrap_err();
    assert!(e.to_string().contains("shared point"), "{e}");
    // Touching at corners is fine, and so is a hole touching its outer at a vertex.
    let corners = Polygons::new(vec![square.clone(), Rect::new(2.0, 2.0, 4.0, 4.0).to_ring()]);
    check_valid_output(&corners).unwrap();
    let touching_hole =
        Polygons::new(vec![Rect::new(0.0, 0.0, 10.0, 10.0).to_ring(), ring(&[(5.0, 0.0), (3.0, 5.0), (7.0, 5.0)])]);
    check_valid_output(&touching_hole).unwrap();
}

#[test]
fn form_defects_are_caught() {
    let cases: [(&str, Polygons); 5] = [
        ("repeats", ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 0.0), (1.0, 1.0)]).into()),
        ("zero area", ring(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]).into()),
        ("spike", ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (3.0, 1.0), (2.0, 1.0), (2.0, 2.0), (0.0, 2.0)]).into()),
        ("outer ring", Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0).to_ring().reversed())),
        ("not finite", ring(&[(0.0, 0.0), (f64::NAN, 0.0), (1.0, 1.0)]).into()),
    ];
    for (what, p) in cases {
        let e = check_valid_output(&p).unwrap_err();
        assert!(e.to_string().contains(what), "{what}: {e}");
    }
    // Collinear vertices that keep going forward are allowed.
    check_valid_output(&ring(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 2.0)]).into()).unwrap();
}

#[test]
fn bridges_are_counted_and_compared_by_region() {
    // Two squares joined by a zero-width bridge along y = 0, as Sutherland-Hodgman leaves them.
    let bridged = Polygons::from(ring(&[
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 1.0),
        (3.0, 1.0),
        (3.0, 0.0),
        (1.0, 0.0),
        (1.0, 1.0),
        (0.0, 1.0),
    ]));
    assert_eq!(bridge_count(&bridged), 1);
    let apart = Polygons::new(vec![Rect::new(0.0, 0.0, 1.0, 1.0).to_ring(), Rect::new(3.0, 0.0, 4.0, 1.0).to_ring()]);
    assert_eq!(bridge_count(&apart), 0);
    same_region((&bridged, FillRule::NonZero), (&apart, FillRule::NonZero), 1e-12).unwrap();
    assert_eq!(
        same_region((&bridged, FillRule::NonZero), (&rect(0.0, 0.0, 1.0, 1.0), FillRule::NonZero), 1e-12),
        Err(1.0)
    );
}

#[test]
fn rings_sharing_an_edge_must_run_it_both_ways() {
    // Two squares side by side share x = 1, one going up and one down: fine.
    let side_by_side =
        Polygons::new(vec![Rect::new(0.0, 0.0, 1.0, 1.0).to_ring(), Rect::new(1.0, 0.0, 2.0, 1.0).to_ring()]);
    check_valid_output(&side_by_side).unwrap();
    // Two overlapping squares sharing the bottom edge the same way overlap without crossing.
    let overlapping =
        Polygons::new(vec![Rect::new(0.0, 0.0, 2.0, 1.0).to_ring(), Rect::new(0.0, 0.0, 1.0, 2.0).to_ring()]);
    let Err(PolygonFailure::Invalid(why)) = check_valid_output(&overlapping) else {
        panic!("accepted overlapping rings")
    };
    assert!(why.contains("same way"), "{why}");
}

#[test]
fn bridges_along_the_window_exclude_the_subjects_own_spikes() {
    // The bridge of the test above lies along the window's bottom side; a spike inside is not one.
    let bridged_with_spike = Polygons::from(ring(&[
        (0.0, 0.0),
        (4.0, 0.0),
        (4.0, 1.0),
        (3.0, 1.0),
        (3.0, 0.0),
        (1.0, 0.0),
        (1.0, 0.5),
        (2.0, 0.5),
        (1.0, 0.5),
        (1.0, 1.0),
        (0.0, 1.0),
    ]));
    let window = rect(-1.0, 0.0, 5.0, 2.0);
    assert_eq!(bridge_count(&bridged_with_spike), 2);
    assert_eq!(bridge_count_along(&bridged_with_spike, &window, 0.0), 1);
    assert_eq!(bridge_count_along(&bridged_with_spike, &rect(-1.0, -1.0, 5.0, 2.0), 0.0), 0);
    assert_eq!(bridge_count_along(&bridged_with_spike, &window, 1e-9), 1);
}

#[test]
fn tolerance_scales_with_the_inputs_box() {
    let (a, b, _) = squares();
    // 1e-9 of the [0,3]² box, on top of the rounding term (tested below).
    assert!((tolerance(&a, &b, 1e-9) - tolerance(&a, &b, 0.0) - 9e-9).abs() < 1e-20);
}

#[test]
fn identity_on_generated_cases() {
    // A ∩ A = A ∪ A = A and A − A = A ⊕ A = ∅ for simple counter-clockwise stars.
    for i in 0..10 {
        let case = polygon_case("star", 11, i, WindowKind::Any).unwrap();
        let a = &case.subject;
        let empty = Polygons::empty();
        for (op, out) in
            [(BoolOp::Intersection, a), (BoolOp::Union, a), (BoolOp::Difference, &empty), (BoolOp::Xor, &empty)]
        {
            check_polygon_result(a, a, op, FillRule::NonZero, out, &EXACT).unwrap_or_else(|e| panic!("{op}: {e}"));
        }
        assert!(check_polygon_result(a, a, BoolOp::Intersection, FillRule::NonZero, &empty, &EXACT).is_err());
        let shoelace = a.signed_area();
        assert!((area(a, FillRule::NonZero) - shoelace).abs() < 1e-9 * shoelace);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Two random rectangles: their intersection is a rectangle, which the oracle accepts; the
    /// same rectangle moved by a visible amount it rejects.
    #[test]
    fn rectangle_intersections(x0 in -100i32..100, y0 in -100i32..100, w0 in 1i32..80, h0 in 1i32..80,
                               x1 in -100i32..100, y1 in -100i32..100, w1 in 1i32..80, h1 in 1i32..80,
                               scale in 0.001f64..1000.0) {
        let f = |v: i32| f64::from(v) * scale;
        let a = rect(f(x0), f(y0), f(x0 + w0), f(y0 + h0));
        let b = rect(f(x1), f(y1), f(x1 + w1), f(y1 + h1));
        let (lx, ly, hx, hy) = (x0.max(x1), y0.max(y1), (x0 + w0).min(x1 + w1), (y0 + h0).min(y1 + h1));
        let out = if lx < hx && ly < hy { rect(f(lx), f(ly), f(hx), f(hy)) } else { Polygons::empty() };
        prop_assert!(check_polygon_result(&a, &b, BoolOp::Intersection, FillRule::NonZero, &out, &EXACT).is_ok());
        prop_assert!(check_polygon_result(&a, &b, BoolOp::Intersection, FillRule::EvenOdd, &out, &EXACT).is_ok());
        if lx < hx && ly < hy {
            let moved = rect(f(lx) + scale * 0.5, f(ly), f(hx) + scale * 0.5, f(hy));
            prop_assert!(check_polygon_result(&a, &b, BoolOp::Intersection, FillRule::NonZero, &moved, &EXACT).is_err());
        }
    }

    /// Inclusion-exclusion holds for region_area on random self-intersecting rings under every rule.
    #[test]
    fn region_area_inclusion_exclusion(seed in 0u64..1000, rule in 0usize..4) {
        let case = polygon_case("scribble", seed, 0, WindowKind::Any).unwrap();
        let fill = FillRule::ALL[rule];
        let layers = [(&case.subject, fill), (&case.clip, fill)];
        let by = |p: fn(bool, bool) -> bool| region_area(&layers, |i| p(i[0], i[1]));
        let (a, b) = (area(&case.subject, fill), area(&case.clip, fill));
        let (u, i, x, d) = (by(|x, y| x || y), by(|x, y| x && y), by(|x, y| x != y), by(|x, y| x && !y));
        let tol = 1e-9 * 1e6;
        prop_assert!((u + i - a - b).abs() < tol);
        prop_assert!((x - (u - i)).abs() < tol);
        prop_assert!((d + i - a).abs() < tol);
    }

    /// Even-odd and non-zero agree on simple rings; a ring's area under non-zero is |shoelace|,
    /// whichever way it runs.
    #[test]
    fn region_area_matches_shoelace_on_stars(seed in 0u64..1000, reverse: bool) {
        let case = polygon_case("star", seed, 1, WindowKind::Any).unwrap();
        let mut s = case.subject.clone();
        if reverse { s.rings[0] = s.rings[0].reversed(); }
        let shoelace = s.signed_area().abs();
        prop_assert!((area(&s, FillRule::NonZero) - shoelace).abs() < 1e-9 * shoelace);
        prop_assert!((area(&s, FillRule::EvenOdd) - shoelace).abs() < 1e-9 * shoelace);
    }
}

#[test]
fn a_vertex_rounded_across_an_edge_it_touches_is_tolerated_within_the_snap() {
    // A triangle whose apex should touch the square's top edge at (5, 10) but was rounded
    // 1e-12 below it: a crossing by rounding, not by topology.
    let square = Rect::new(0.0, 0.0, 10.0, 10.0).to_ring();
    let apex = ring(&[(2.0, 20.0), (5.0, 10.0 - 1e-12), (8.0, 20.0)]);
    let out = Polygons::new(vec![square, apex]);
    assert!(check_valid_output(&out).is_err());
    check_valid_output_within(&out, 1e-9).unwrap();
    // A real crossing stays one.
    let deep =
        Polygons::new(vec![Rect::new(0.0, 0.0, 10.0, 10.0).to_ring(), ring(&[(2.0, 20.0), (5.0, 9.0), (8.0, 20.0)])]);
    assert!(check_valid_output_within(&deep, 1e-9).is_err());
}

/// The polygon set turned a quarter turn, (x, y) -> (-y, x): exact in floating point, and it
/// makes the slab decomposition cut the plane the other way.
fn quarter_turn(p: &Polygons) -> Polygons {
    Polygons::new(p.rings.iter().map(|r| Ring::new(r.points.iter().map(|q| Point::new(-q.y, q.x)).collect())).collect())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// Horizontal and vertical slabs give the same area for every op on self-intersecting
    /// inputs (thousands of crossings, swapped neighbours, coincident edges from the grid).
    #[test]
    fn region_area_is_the_same_cut_either_way(seed in 0u64..10_000, rule in 0usize..4, grid: bool) {
        let case = polygon_case(if grid { "grid" } else { "scribble" }, seed, 0, WindowKind::Any).unwrap();
        let fill = FillRule::ALL[rule];
        let (ts, tc) = (quarter_turn(&case.subject), quarter_turn(&case.clip));
        for op in BoolOp::ALL {
            let flat = region_area(&[(&case.subject, fill), (&case.clip, fill)], |i| op.apply(i[0], i[1]));
            let turned = region_area(&[(&ts, fill), (&tc, fill)], |i| op.apply(i[0], i[1]));
            let tol = 1e-9 * case.subject.bounds().union(case.clip.bounds()).area();
            prop_assert!((flat - turned).abs() <= tol, "{} {op}: {flat} vs {turned}", case.description);
        }
    }
}

#[test]
fn dense_output_checks_every_close_pair() {
    // A 60 x 60 checkerboard: 1800 squares touching at corners is valid output...
    let case = clip_testkit::workload::polygon_case_sized("large", 1, 1, 7200, WindowKind::Any).unwrap();
    check_valid_output(&case.subject).unwrap();
    assert_eq!(bridge_count(&case.subject), 0);
    // ...until one square is nudged across its neighbour's corner.
    let mut nudged = case.subject.clone();
    let p = &mut nudged.rings[900].points[2];
    p.x += 1e-3;
    p.y += 1e-3;
    let e = check_valid_output(&nudged).unwrap_err();
    assert!(e.to_string().contains("cross"), "{e}");
}

/// Clipper2's union of grid seed 1 case 3 (shrunk): a triangle whose apex (10, 12) Clipper2
/// rounded onto the edge of the big ring it touches. The apex is not exactly on that edge, so a
/// nesting test at the apex alone reads the outside triangle as a hole; within the snap
/// distance the rings touch there, and the triangle's other points say it is outside.
#[test]
fn a_ring_touching_another_at_a_rounded_vertex_is_not_read_as_its_hole() {
    let big = ring(&[
        (11.571428567171097, 12.69841268658638),
        (11.0, 12.0),
        (19.0, 12.0),
        (20.0, 23.0),
        (16.614678889513016, 18.86238531768322),
        (14.0, 22.0),
        (6.978102192282677, 10.656934320926666),
    ]);
    let triangle = ring(&[(10.0, 12.0), (6.727272734045982, 8.0), (12.0, 8.0)]);
    let output = Polygons::new(vec![big, triangle]);
    let snap = output.bounds().extent() * GEO_TOLERANCE;
    assert!(check_valid_output_within(&output, snap).is_ok(), "{:?}", check_valid_output_within(&output, snap));
    assert!(check_valid_output(&output).is_err(), "exactly, the apex is off the edge");
}

#[test]
fn a_bridge_on_a_slanted_side_is_counted_within_rounding() {
    // The same two squares rotated by 30 degrees: the bridge's two edges end at points rotated
    // (so rounded) separately, collinear only to within ulps.
    let (sin, cos) = 30f64.to_radians().sin_cos();
    let turn = |(x, y): (f64, f64)| (x * cos - y * sin, x * sin + y * cos);
    let points = [(0.0, 0.0), (4.0, 0.0), (4.0, 1.0), (3.0, 1.0), (3.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
    let bridged = Polygons::from(ring(&points.map(turn)));
    assert_eq!(bridge_count_within(&bridged, 1e-9), 1);
    // Edges that are merely close and antiparallel, farther apart than the snap, are not a bridge.
    let apart =
        ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 1.0), (3.0, 1.0), (3.0, 1e-6), (1.0, 1e-6), (1.0, 1.0), (0.0, 1.0)]);
    assert_eq!(bridge_count_within(&Polygons::from(apart), 1e-9), 0);
}

/// Clipper2's union of multi seed 1 case 1104 left a hole of area 2e-10 touching its outer at a
/// vertex, smaller than the snap distance: its nesting is decided exactly, not guessed.
#[test]
fn a_sliver_hole_within_the_snap_distance_is_read_by_its_exact_position() {
    let outer = Rect::new(0.0, 0.0, 100.0, 100.0).to_ring();
    let inside = ring(&[(50.0, 100.0), (50.00002, 99.99999), (49.99999, 99.99998)]);
    let outside = ring(&[(50.0, 100.0), (49.99999, 100.00002), (50.00002, 100.00001)]);
    let snap = 1e-4;
    // Clockwise inside: a hole. Clockwise outside: a wrongly oriented outer.
    assert!(inside.signed_area() < 0.0 && outside.signed_area() < 0.0);
    let hole = Polygons::new(vec![outer.clone(), inside.clone()]);
    assert!(check_valid_output_within(&hole, snap).is_ok(), "{:?}", check_valid_output_within(&hole, snap));
    let stray = Polygons::new(vec![outer.clone(), outside]);
    assert!(check_valid_output_within(&stray, snap).is_err());
    let island = Polygons::new(vec![outer, inside.reversed()]);
    assert!(check_valid_output_within(&island, snap).is_err(), "counter-clockwise inside is not a hole");
}

/// Clipper2's difference of grid seed 1 case 100 (shrunk): a hole touches its outer at a
/// rounded crossing point, one hole edge running along an outer edge from there; rounding tilts
/// it by 1e-8, which an exact side test reads as the rings crossing at the shared point.
#[test]
fn a_hole_running_along_its_outer_from_a_rounded_shared_point_does_not_cross_it() {
    let p = (12.66666665673256, 5.66666667163372);
    let outer = ring(&[p, (16.0, 4.0), (7.0, 11.0), (0.0, 11.0), (14.0, 3.0)]);
    let hole = ring(&[(12.0, 6.0), p, (13.0, 5.0)]);
    let output = Polygons::new(vec![outer, hole]);
    let snap = output.bounds().extent() * GEO_TOLERANCE;
    assert!(check_valid_output_within(&output, snap).is_ok(), "{:?}", check_valid_output_within(&output, snap));
    let exact = check_valid_output(&output).unwrap_err();
    assert!(exact.to_string().contains("shared point"), "{exact}");
}

/// `star-far` case 0's subject: a star of a few hundred units' extent at (1e9, 1e9).
fn far_star() -> Polygons {
    let case = polygon_case("star-far", 1, 0, WindowKind::Any).unwrap();
    assert!(case.subject.bounds().min.x > 9e8, "star-far lies far from the origin");
    case.subject
}

/// `p` with every vertex moved by `units` f64 steps at its magnitude, in alternating directions:
/// what rounding every vertex of a correct answer looks like far from the origin.
fn rounded_by(p: &Polygons, units: i32) -> Polygons {
    let step = |v: f64, k: usize| {
        let mut v = v;
        for _ in 0..units {
            v = if k.is_multiple_of(2) { v.next_up() } else { v.next_down() };
        }
        v
    };
    let rings = p.rings.iter().map(|r| {
        Ring::new(r.points.iter().enumerate().map(|(k, q)| Point::new(step(q.x, k), step(q.y, k + 1))).collect())
    });
    Polygons::new(rings.collect())
}

#[test]
fn far_from_the_origin_rounding_to_f64_is_no_failure() {
    let a = far_star();
    let rounded = rounded_by(&a, 2);
    assert_ne!(rounded, a);
    // The bounding-box term alone (the tolerance before the rounding term) calls it wrong...
    let xor = region_area(&[(&a, FillRule::NonZero), (&rounded, FillRule::NonZero)], |i| i[0] != i[1]);
    let box_term = REGION_TOLERANCE * a.bounds().area();
    assert!(xor > box_term, "the rounding moved {xor:e}, within the box term {box_term:e}: no test");
    // ...the tolerance that knows the coordinates' magnitude does not.
    let verdict = check_polygon_result(&a, &a, BoolOp::Intersection, FillRule::NonZero, &rounded, &EXACT);
    assert!(verdict.is_ok(), "{verdict:?}");
}

#[test]
fn far_from_the_origin_a_vertex_moved_by_a_millionth_of_the_box_is_caught() {
    let a = far_star();
    let moved_by = 1e-6 * a.bounds().extent();
    // Move the tip of the longest spike outward along its own direction.
    let pts = &a.rings[0].points;
    let b = a.bounds();
    let c = Point::new(0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y));
    let tip = (0..pts.len()).max_by(|&i, &j| pts[i].distance(c).total_cmp(&pts[j].distance(c))).unwrap();
    let mut moved = pts.clone();
    let out = (pts[tip] - c) * (moved_by / pts[tip].distance(c));
    moved[tip] = pts[tip] + out;
    let wrong = Polygons::from(Ring::new(moved));
    let verdict = check_polygon_result(&a, &a, BoolOp::Intersection, FillRule::NonZero, &wrong, &EXACT);
    assert!(matches!(verdict, Err(PolygonFailure::WrongRegion { .. })), "{verdict:?}");
}

#[test]
fn the_rounding_term_is_negligible_near_the_origin() {
    let (a, b, _) = squares();
    // [0,3]² near the origin: rounding allows about 1e-14 beside the box term's 9e-9.
    let rounding = tolerance(&a, &b, 0.0);
    assert!(rounding > 0.0 && rounding < 1e-13, "{rounding:e}");
}

/// Found by the `vatti` fuzz target: a thin triangle near 1e140 whose shoelace sum cancels to 0
/// is counter-clockwise (exact turn at its lowest vertex), so as its own union it is valid; the
/// same ring reversed is still caught.
#[test]
fn orientation_is_exact_where_the_shoelace_cancels() {
    let t = Polygons::from(ring(&[(6.000000000000001e140, 2e140), (-1e15, 1e15), (3.0000000000000004e140, 1e140)]));
    assert_eq!(t.signed_area(), 0.0);
    let empty = Polygons::default();
    assert_eq!(check_valid_output(&t), Ok(()));
    let reversed = Polygons::from(t.rings[0].reversed());
    assert!(check_valid_output(&reversed).is_err());
    let rules = OutputRules::conventional(REGION_TOLERANCE);
    assert!(check_polygon_result(&t, &empty, BoolOp::Union, FillRule::NonZero, &t, &rules).is_ok());
}

/// Found by the `vatti` fuzz target: a ring of rounded crossings may come out inside out when its
/// area is within the snap distance times its perimeter; a ring of input vertices may not.
#[test]
fn only_rings_of_rounded_crossings_may_run_either_way() {
    let input = Polygons::from(ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]));
    let snap = 1e-3;
    // Clockwise, 1e-4 wide: one vertex is not an input vertex.
    let sliver = Polygons::from(ring(&[(0.0, 0.0), (2.0, 1e-4), (4.0, 0.0)]));
    assert!(check_valid_result_within(&sliver, snap, [&input, &Polygons::default()]).is_ok());
    assert!(check_valid_output_within(&sliver, snap).is_err());
    // The same ring made of input vertices and edges only is caught; with one edge along no input
    // edge it is not.
    let thin_input = Polygons::from(ring(&[(0.0, 0.0), (4.0, 0.0), (2.0, 1e-4)]));
    let two_edges = Polygons::from(ring(&[(0.0, 0.0), (2.0, 1e-4), (4.0, 0.0), (2.0, -1.0)]));
    assert!(check_valid_result_within(&sliver, snap, [&two_edges, &Polygons::default()]).is_ok());
    assert!(check_valid_result_within(&sliver, snap, [&thin_input, &Polygons::default()]).is_err());
    // Wide enough to matter: caught.
    let wide = Polygons::from(ring(&[(0.0, 0.0), (2.0, 1.0), (4.0, 0.0)]));
    assert!(check_valid_result_within(&wide, snap, [&input, &Polygons::default()]).is_err());
}

/// `k` bars 10^6 wide and 1 high, 2 apart: half their edges span the whole width.
fn stacked_bars(k: usize) -> Polygons {
    Polygons::new((0..k).map(|i| Rect::new(0.0, 2.0 * i as f64, 1e6, 2.0 * i as f64 + 1.0).to_ring()).collect())
}

#[test]
fn form_check_work_is_near_linear_for_short_edges_and_quadratic_for_long_shared_ones() {
    // 4000 unit squares on a grid: each edge meets a few others.
    let square = |i: usize| {
        let (x, y) = (2.0 * (i % 64) as f64, 2.0 * (i / 64) as f64);
        Rect::new(x, y, x + 1.0, y + 1.0).to_ring()
    };
    let grid = Polygons::new((0..4000).map(square).collect());
    let edges = 16_000u64;
    assert!(check_valid_work(&grid) < 100 * edges, "{}", check_valid_work(&grid));
    // 4000 bars as wide as the whole: every long edge shares its cells with every other.
    let bars = stacked_bars(4000);
    assert!(check_valid_work(&bars) > edges * edges / 20, "{}", check_valid_work(&bars));
    assert_eq!(check_valid_work(&Polygons::default()), 0);
}
