//! clip-core's tests: exact predicates, point location under each fill rule, area, validation.

use clip_core::predicates::{crossing_point, on_segment, orient2d};
use clip_core::{
    ClipError, FillRule, Location, Operand, Orientation, Point, Polygons, Rect, Ring, Segment, SegmentIntersection,
    convex_window, locate, nest, orient, rect_window, segment_intersection, validate_polygons, validate_segments,
    validate_window, winding_number, window_covers,
};
use proptest::prelude::*;

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

fn ring(pts: &[(f64, f64)]) -> Ring {
    Ring::from(pts)
}

fn naive_orient(a: Point, b: Point, c: Point) -> f64 {
    (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)
}

// ---- predicates ----

#[test]
fn orient_is_exact_a_few_ulps_off_a_line() {
    // Points one or a few ulps above the line y = x (the ulp of 24 is 2^-48).
    let a = p(0.5, 0.5);
    let b = p(12.0, 12.0);
    for i in 0..256 {
        let off = (i as f64) * 2f64.powi(-48);
        let c = p(24.0, 24.0 + off);
        let exact = if off > 0.0 { Orientation::CounterClockwise } else { Orientation::Collinear };
        assert_eq!(orient(a, b, c), exact, "offset {off:e}");
    }
}

#[test]
fn orient_classic_near_collinear_grid() {
    // Kettner et al.'s classroom example: points near (0.5, 0.5) on a 2^-53 grid against the line
    // through (12, 12) and (24, 24). Exact answer: the sign of (y - x) for the grid point. The
    // naive determinant evaluated from the grid point gets many of them wrong.
    let b = p(12.0, 12.0);
    let c = p(24.0, 24.0);
    let ulp = 2f64.powi(-53);
    let mut naive_wrong = 0;
    for i in 0..64 {
        for j in 0..64 {
            let a = p(0.5 + i as f64 * ulp, 0.5 + j as f64 * ulp);
            let expected = match j.cmp(&i) {
                std::cmp::Ordering::Greater => Orientation::CounterClockwise,
                std::cmp::Ordering::Less => Orientation::Clockwise,
                std::cmp::Ordering::Equal => Orientation::Collinear,
            };
            // a is left of b -> c exactly when a lies above the line y = x.
            assert_eq!(orient(b, c, a), expected, "i={i} j={j}");
            assert_eq!(orient(a, b, c), expected, "i={i} j={j}");
            let naive = naive_orient(a, b, c);
            naive_wrong += usize::from(naive.signum() as i32 * i32::from(naive != 0.0) != expected.sign());
        }
    }
    assert!(naive_wrong > 0, "the grid must include cases naive f64 gets wrong");
}

proptest! {
    #[test]
    fn orient_antisymmetric(ax in -1e6..1e6f64, ay in -1e6..1e6f64, bx in -1e6..1e6f64,
                            by in -1e6..1e6f64, cx in -1e6..1e6f64, cy in -1e6..1e6f64) {
        let (a, b, c) = (p(ax, ay), p(bx, by), p(cx, cy));
        let o = orient(a, b, c);
        prop_assert_eq!(orient(b, a, c), o.reversed());
        prop_assert_eq!(orient(a, c, b), o.reversed());
        prop_assert_eq!(orient(b, c, a), o);
        prop_assert_eq!(orient(c, a, b), o);
    }

    #[test]
    fn orient_matches_naive_when_far_from_zero(ax in -1e3..1e3f64, ay in -1e3..1e3f64, bx in -1e3..1e3f64,
                                               by in -1e3..1e3f64, cx in -1e3..1e3f64, cy in -1e3..1e3f64) {
        let (a, b, c) = (p(ax, ay), p(bx, by), p(cx, cy));
        let naive = naive_orient(a, b, c);
        prop_assume!(naive.abs() > 1e-6);
        prop_assert_eq!(orient(a, b, c).sign() as f64, naive.signum());
    }

    #[test]
    fn point_on_a_collinear_grid_line_is_collinear(k in -1000i64..1000, t in -1000i64..1000) {
        // Integer points on the line through (0,0) and (3,7): exactly collinear.
        let a = p(0.0, 0.0);
        let b = p(3.0 * k as f64, 7.0 * k as f64);
        let c = p(3.0 * t as f64, 7.0 * t as f64);
        prop_assume!(k != 0);
        prop_assert_eq!(orient(a, b, c), Orientation::Collinear);
        prop_assert!(orient2d(a, b, c) == 0.0);
    }

    #[test]
    fn crossing_point_stays_in_both_boxes(ax in -1e3..1e3f64, ay in -1e3..1e3f64, bx in -1e3..1e3f64,
                                          by in -1e3..1e3f64, cx in -1e3..1e3f64, cy in -1e3..1e3f64,
                                          dx in -1e3..1e3f64, dy in -1e3..1e3f64) {
        let s = Segment::new(p(ax, ay), p(bx, by));
        let t = Segment::new(p(cx, cy), p(dx, dy));
        if let SegmentIntersection::Crossing(q) = segment_intersection(s, t) {
            prop_assert!(s.bounds().contains(q) && t.bounds().contains(q));
            prop_assert_eq!(crossing_point(s, t), q);
        }
    }

    #[test]
    fn segment_intersection_is_symmetric_in_kind(ax in -20i32..20, ay in -20i32..20, bx in -20i32..20,
                                                 by in -20i32..20, cx in -20i32..20, cy in -20i32..20,
                                                 dx in -20i32..20, dy in -20i32..20) {
        let s = Segment::new(p(ax.into(), ay.into()), p(bx.into(), by.into()));
        let t = Segment::new(p(cx.into(), cy.into()), p(dx.into(), dy.into()));
        let kind = |r: SegmentIntersection| std::mem::discriminant(&r);
        prop_assert_eq!(kind(segment_intersection(s, t)), kind(segment_intersection(t, s)));
    }
}

#[test]
fn segment_intersection_kinds() {
    let s = Segment::new(p(0.0, 0.0), p(4.0, 4.0));
    assert_eq!(
        segment_intersection(s, Segment::new(p(0.0, 4.0), p(4.0, 0.0))),
        SegmentIntersection::Crossing(p(2.0, 2.0))
    );
    assert_eq!(
        segment_intersection(s, Segment::new(p(2.0, 2.0), p(4.0, 0.0))),
        SegmentIntersection::Touching(p(2.0, 2.0))
    );
    assert_eq!(
        segment_intersection(s, Segment::new(p(4.0, 4.0), p(5.0, 0.0))),
        SegmentIntersection::Touching(p(4.0, 4.0))
    );
    assert_eq!(segment_intersection(s, Segment::new(p(5.0, 5.0), p(6.0, 6.0))), SegmentIntersection::None);
    assert_eq!(
        segment_intersection(s, Segment::new(p(4.0, 4.0), p(6.0, 6.0))),
        SegmentIntersection::Touching(p(4.0, 4.0))
    );
    assert_eq!(
        segment_intersection(s, Segment::new(p(6.0, 6.0), p(1.0, 1.0))),
        SegmentIntersection::Overlap(Segment::new(p(1.0, 1.0), p(4.0, 4.0)))
    );
    assert_eq!(segment_intersection(s, Segment::new(p(1.0, 0.0), p(5.0, 4.0))), SegmentIntersection::None);
    // Degenerate segments: a point on the other segment touches it.
    assert_eq!(
        segment_intersection(s, Segment::new(p(1.0, 1.0), p(1.0, 1.0))),
        SegmentIntersection::Touching(p(1.0, 1.0))
    );
    assert_eq!(segment_intersection(s, Segment::new(p(1.0, 2.0), p(1.0, 2.0))), SegmentIntersection::None);
    assert!(on_segment(p(3.0, 3.0), s) && !on_segment(p(5.0, 5.0), s));
}

// ---- point location under each fill rule ----

/// Two nested counter-clockwise squares plus one clockwise square: winding numbers 0, 1, 2, -1.
fn nested_squares() -> Polygons {
    Polygons::new(vec![
        Rect::new(0.0, 0.0, 10.0, 10.0).to_ring(),
        Rect::new(2.0, 2.0, 6.0, 6.0).to_ring(),
        Rect::new(20.0, 0.0, 30.0, 10.0).to_ring().reversed(),
    ])
}

#[test]
fn winding_numbers_of_nested_rings() {
    let polys = nested_squares();
    assert_eq!(winding_number(p(-1.0, 5.0), &polys), Some(0));
    assert_eq!(winding_number(p(8.0, 8.0), &polys), Some(1));
    assert_eq!(winding_number(p(3.0, 3.0), &polys), Some(2));
    assert_eq!(winding_number(p(25.0, 5.0), &polys), Some(-1));
    assert_eq!(winding_number(p(10.0, 5.0), &polys), None);
    assert_eq!(winding_number(p(2.0, 2.0), &polys), None);
}

#[test]
fn transposed_keeps_every_winding_number_at_the_mirrored_point() {
    let polys = nested_squares();
    // The squares and a bow-tie, so both ways round and a crossing are mirrored.
    let mut both = polys.clone();
    both.rings.push(ring(&[(40.0, 0.0), (44.0, 4.0), (44.0, 0.0), (40.0, 4.0)]));
    let t = both.transposed();
    for q in [p(-1.0, 5.0), p(8.0, 8.0), p(3.0, 3.0), p(25.0, 5.0), p(41.0, 2.0), p(43.0, 2.0), p(10.0, 5.0)] {
        assert_eq!(winding_number(Point::new(q.y, q.x), &t), winding_number(q, &both), "at {q:?}");
    }
    assert_eq!(t.signed_area(), both.signed_area());
    assert_eq!(t.transposed(), both, "its own inverse");
}

#[test]
fn locate_under_each_fill_rule() {
    use Location::*;
    let polys = nested_squares();
    let probes = [p(-1.0, 5.0), p(8.0, 8.0), p(3.0, 3.0), p(25.0, 5.0)]; // w = 0, 1, 2, -1
    let expect = |fill| match fill {
        FillRule::EvenOdd => [Outside, Inside, Outside, Inside],
        FillRule::NonZero => [Outside, Inside, Inside, Inside],
        FillRule::Positive => [Outside, Inside, Inside, Outside],
        FillRule::Negative => [Outside, Outside, Outside, Inside],
    };
    for fill in FillRule::ALL {
        let got: Vec<_> = probes.iter().map(|&q| locate(q, &polys, fill)).collect();
        assert_eq!(got, expect(fill), "{fill}");
        assert_eq!(locate(p(0.0, 7.0), &polys, fill), Boundary);
    }
}

#[test]
fn bow_tie_winds_both_ways() {
    // A figure-eight: the left lobe is walked counter-clockwise (+1), the right lobe clockwise (-1).
    let tie = Polygons::from(ring(&[(0.0, 0.0), (4.0, 4.0), (4.0, 0.0), (0.0, 4.0)]));
    assert_eq!(winding_number(p(1.0, 2.0), &tie), Some(1));
    assert_eq!(winding_number(p(3.0, 2.0), &tie), Some(-1));
    assert_eq!(locate(p(2.0, 2.0), &tie, FillRule::EvenOdd), Location::Boundary);
    assert_eq!(locate(p(1.0, 2.0), &tie, FillRule::Positive), Location::Inside);
    assert_eq!(locate(p(3.0, 2.0), &tie, FillRule::Positive), Location::Outside);
    assert_eq!(locate(p(3.0, 2.0), &tie, FillRule::Negative), Location::Inside);
}

proptest! {
    #[test]
    fn winding_of_a_triangle_is_its_orientation(ax in -100i32..100, ay in -100i32..100, bx in -100i32..100,
                                                by in -100i32..100, cx in -100i32..100, cy in -100i32..100,
                                                qx in -100i32..100, qy in -100i32..100) {
        let (a, b, c) = (p(ax.into(), ay.into()), p(bx.into(), by.into()), p(cx.into(), cy.into()));
        let q = p(f64::from(qx) + 0.5, f64::from(qy) + 0.25);
        let tri = Polygons::from(Ring::new(vec![a, b, c]));
        let o = orient(a, b, c);
        // Strictly inside iff q is strictly left (ccw) or strictly right (cw) of all three edges.
        let sides = [orient(a, b, q), orient(b, c, q), orient(c, a, q)];
        let w = winding_number(q, &tri);
        if sides.contains(&Orientation::Collinear) {
            prop_assert!(w.is_none() || w == Some(0));
        } else if o != Orientation::Collinear && sides.iter().all(|&s| s == o) {
            prop_assert_eq!(w, Some(o.sign()));
        } else {
            prop_assert_eq!(w, Some(0));
        }
    }
}

// ---- area ----

#[test]
fn signed_area_orientation_and_holes() {
    let sq = Rect::new(0.0, 0.0, 3.0, 2.0).to_ring();
    assert_eq!(sq.signed_area(), 6.0);
    assert_eq!(sq.reversed().signed_area(), -6.0);
    let with_hole = Polygons::new(vec![sq.clone(), Rect::new(1.0, 0.5, 2.0, 1.5).to_ring().reversed()]);
    assert_eq!(with_hole.signed_area(), 5.0);
    // Far from the origin the area keeps its precision (coordinates relative to the first vertex).
    let far = Ring::new(sq.points.iter().map(|q| p(q.x + 1e9, q.y + 1e9)).collect());
    assert_eq!(far.signed_area(), 6.0);
    assert_eq!(ring(&[(0.0, 0.0), (1.0, 1.0)]).signed_area(), 0.0);
}

proptest! {
    #[test]
    fn signed_area_invariants(pts in prop::collection::vec((-1e3..1e3f64, -1e3..1e3f64), 3..40),
                              dx in -1e4..1e4f64, dy in -1e4..1e4f64, shift in 0usize..40) {
        let r = Ring::new(pts.iter().map(|&(x, y)| p(x, y)).collect());
        let a = r.signed_area();
        let tol = 1e-7 * (1.0 + a.abs());
        prop_assert!((r.reversed().signed_area() + a).abs() <= tol);
        let moved = Ring::new(r.points.iter().map(|q| p(q.x + dx, q.y + dy)).collect());
        prop_assert!((moved.signed_area() - a).abs() <= 1e-6 * (1.0 + a.abs()));
        let mut rotated = r.points.clone();
        let k = shift % rotated.len();
        rotated.rotate_left(k);
        prop_assert!((Ring::new(rotated).signed_area() - a).abs() <= tol);
    }
}

// ---- validation ----

#[test]
fn validation_errors_are_typed() {
    let nan = Polygons::from(ring(&[(0.0, 0.0), (f64::NAN, 1.0), (1.0, 0.0)]));
    assert!(matches!(
        validate_polygons(&nan, Operand::Subject),
        Err(ClipError::NonFinite { operand: Operand::Subject, part: 0, vertex: 1, .. })
    ));
    let inf = Polygons::new(vec![
        Rect::new(0.0, 0.0, 1.0, 1.0).to_ring(),
        ring(&[(0.0, 0.0), (f64::INFINITY, 1.0), (1.0, 0.0)]),
    ]);
    assert!(matches!(validate_polygons(&inf, Operand::Clip), Err(ClipError::NonFinite { part: 1, .. })));
    let huge = Polygons::from(ring(&[(0.0, 0.0), (1e200, 1.0), (1.0, 0.0)]));
    assert!(matches!(validate_polygons(&huge, Operand::Subject), Err(ClipError::OutOfRange { .. })));
    // Found by the line_clippers fuzz target: a segment 8e-317 long has a squared length of 0.
    let tiny = [Segment::new(p(8.2782315e-317, 0.0), p(0.0, 0.0))];
    assert!(matches!(validate_segments(&tiny), Err(ClipError::OutOfRange { part: 0, vertex: 0, .. })));
    let small = Polygons::from(ring(&[(0.0, 0.0), (1e-100, 0.0), (0.0, -1e-100)]));
    assert!(validate_polygons(&small, Operand::Subject).is_ok(), "MIN_COORDINATE itself and zero are accepted");
    let two = Polygons::from(ring(&[(0.0, 0.0), (1.0, 1.0), (0.0, 0.0), (1.0, 1.0)]));
    assert!(matches!(validate_polygons(&two, Operand::Subject), Err(ClipError::TooFewPoints { distinct: 2, .. })));
    // Collinear rings with three distinct points are valid operands (they cover nothing).
    assert!(validate_polygons(&Polygons::from(ring(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)])), Operand::Subject).is_ok());
    assert!(validate_polygons(&Polygons::empty(), Operand::Subject).is_ok());
    assert!(validate_segments(&[Segment::new(p(0.0, 0.0), p(0.0, 0.0))]).is_ok());
    assert!(matches!(
        validate_segments(&[Segment::new(p(0.0, 0.0), p(1.0, 1.0)), Segment::new(p(0.0, f64::NAN), p(1.0, 1.0))]),
        Err(ClipError::NonFinite { operand: Operand::Segments, part: 1, vertex: 0, .. })
    ));
    let msg = validate_polygons(&nan, Operand::Subject).unwrap_err().to_string();
    assert!(msg.contains("subject 0, vertex 1") && msg.contains("not finite"), "{msg}");
}

#[test]
fn windows_are_checked() {
    assert!(matches!(validate_window(&Polygons::empty()), Err(ClipError::DegenerateWindow { .. })));
    let flat = Polygons::from(ring(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0)]));
    assert!(matches!(validate_window(&flat), Err(ClipError::DegenerateWindow { .. })));
    let diagonal = Polygons::from(ring(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]));
    assert!(matches!(validate_window(&diagonal), Err(ClipError::DegenerateWindow { .. })));

    let square = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
    assert_eq!(rect_window(&square, "t"), Ok(Rect::new(0.0, 0.0, 2.0, 2.0)));
    assert_eq!(rect_window(&Polygons::from(square.rings[0].reversed()), "t"), Ok(Rect::new(0.0, 0.0, 2.0, 2.0)));
    let (cw, o) = convex_window(&Polygons::from(square.rings[0].reversed()), "t").unwrap();
    assert_eq!((cw.len(), o), (4, Orientation::Clockwise));

    let diamond = Polygons::from(ring(&[(1.0, 0.0), (2.0, 1.0), (1.0, 2.0), (0.0, 1.0)]));
    assert!(matches!(rect_window(&diamond, "t"), Err(ClipError::WindowNotRectangle { clipper: "t" })));
    assert!(convex_window(&diamond, "t").is_ok());
    // A spike out and back along two sides visits three corners with axis edges only.
    let spike = ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (1.0, 0.0)]);
    assert_eq!(spike.as_rect(), None);

    let concave = Polygons::from(ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, 1.0), (0.0, 4.0)]));
    assert!(matches!(convex_window(&concave, "t"), Err(ClipError::WindowNotConvex { .. })));
    let pentagram: Vec<(f64, f64)> = (0..5)
        .map(|i| {
            let a = std::f64::consts::TAU * (2 * i) as f64 / 5.0;
            (a.cos(), a.sin())
        })
        .collect();
    assert!(matches!(convex_window(&Polygons::from(ring(&pentagram)), "t"), Err(ClipError::WindowNotConvex { .. })));
    // Collinear extra vertices on a side keep a window convex; folding back does not.
    let with_mid = Polygons::from(ring(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]));
    assert!(convex_window(&with_mid, "t").is_ok());
    let folded = Polygons::from(ring(&[(0.0, 0.0), (2.0, 0.0), (1.0, 0.0), (2.0, 2.0), (0.0, 2.0)]));
    assert!(convex_window(&folded, "t").is_err());
    let two_rings = Polygons::new(vec![square.rings[0].clone(), Rect::new(5.0, 5.0, 6.0, 6.0).to_ring()]);
    assert!(convex_window(&two_rings, "t").is_err() && rect_window(&two_rings, "t").is_err());
}

// ---- nesting ----

#[test]
fn holes_go_to_the_smallest_outer_holding_them() {
    let big = Rect::new(0.0, 0.0, 10.0, 10.0).to_ring();
    let big_hole = Rect::new(1.0, 1.0, 9.0, 9.0).to_ring().reversed();
    let island = Rect::new(2.0, 2.0, 8.0, 8.0).to_ring();
    let island_hole = Rect::new(3.0, 3.0, 4.0, 4.0).to_ring().reversed();
    // A hole touching its outer at a vertex still nests.
    let touching_hole = ring(&[(8.0, 8.0), (6.0, 5.0), (5.0, 6.0)]);
    assert!(touching_hole.signed_area() < 0.0);
    let nested = nest(&Polygons::new(vec![
        island_hole.clone(),
        big.clone(),
        touching_hole.clone(),
        island.clone(),
        big_hole.clone(),
    ]));
    assert_eq!(nested.len(), 2);
    let outer_big = nested.iter().find(|n| n.outer == big).unwrap();
    assert_eq!(outer_big.holes, vec![big_hole]);
    let outer_island = nested.iter().find(|n| n.outer == island).unwrap();
    assert_eq!(outer_island.holes, vec![island_hole, touching_hole]);
}

#[test]
fn cohen_sutherland_codes_and_trivial_reject() {
    let r = Rect::new(0.0, 0.0, 4.0, 2.0);
    assert_eq!(r.outcode(p(2.0, 1.0)), 0);
    assert_eq!(r.outcode(p(4.0, 2.0)), 0, "the boundary is inside");
    assert_eq!(r.outcode(p(-1.0, 1.0)), 1);
    assert_eq!(r.outcode(p(5.0, 3.0)), 2 | 8);
    assert_eq!(r.outcode(p(-1.0, -1.0)), 1 | 4);
    assert!(r.rejects_segment(p(-1.0, -1.0), p(-2.0, 5.0)), "both left");
    assert!(!r.rejects_segment(p(-1.0, 1.0), p(5.0, 1.0)), "crosses the box");
    // Beyond different sides but missing the box: not a trivial reject.
    assert!(!r.rejects_segment(p(-1.0, 1.0), p(1.0, 5.0)));
    assert!(!r.rejects_segment(p(4.0, 3.0), p(4.0, 2.0)), "ends on the corner");
}

#[test]
fn a_window_covers_its_inside_unless_its_orientation_winds_the_wrong_way_for_the_rule() {
    let ccw = Polygons::from(Rect::new(0.0, 0.0, 2.0, 1.0));
    let cw = Polygons::from(Rect::new(0.0, 0.0, 2.0, 1.0).to_ring().reversed());
    for fill in [FillRule::EvenOdd, FillRule::NonZero] {
        assert!(window_covers(&ccw, fill) && window_covers(&cw, fill), "{fill}");
    }
    assert!(window_covers(&ccw, FillRule::Positive) && !window_covers(&cw, FillRule::Positive));
    assert!(!window_covers(&ccw, FillRule::Negative) && window_covers(&cw, FillRule::Negative));
    assert!(!window_covers(&Polygons::empty(), FillRule::NonZero));
}

#[test]
fn boxes_grow_and_hold_boxes() {
    let r = Rect::new(0.0, 0.0, 2.0, 1.0);
    assert_eq!(r.expanded(0.5), Rect::new(-0.5, -0.5, 2.5, 1.5));
    assert!(r.expanded(1.0).contains_rect(&r) && r.contains_rect(&r));
    assert!(!r.contains_rect(&Rect::new(1.0, 0.0, 2.5, 1.0)));
    assert!(Rect::EMPTY.expanded(1.0).is_empty() && r.contains_rect(&Rect::EMPTY));
}

#[test]
fn covered_intervals_merge_pieces_and_pieces_keep_exact_end_points() {
    let s = Segment::new(Point::new(0.1, 0.2), Point::new(10.3, 7.7));
    // Pieces out of order, one reversed, two touching, one of zero length, one past the end.
    let pieces = [s.piece(0.5, 0.75), s.piece(0.2, 0.1), s.piece(0.75, 0.9), s.piece(0.3, 0.3), s.piece(0.95, 1.0)];
    let beyond = Segment::new(s.at(0.95), s.at(1.5));
    let got = s.covered_intervals(pieces.into_iter().chain([beyond]));
    let expected = [(0.1, 0.2), (0.5, 0.9), (0.95, 1.0)];
    assert_eq!(got.len(), expected.len(), "{got:?}");
    for ((a, b), (c, d)) in got.iter().zip(expected) {
        assert!((a - c).abs() < 1e-12 && (b - d).abs() < 1e-12, "{got:?}");
    }
    assert_eq!(s.piece(0.0, 1.0), s, "end points exactly");
}

#[test]
fn distinct_points_up_to_a_limit_agree_with_the_full_count() {
    let ring = Ring::new(
        [(0.0, 0.0), (-0.0, 0.0), (1.0, 0.0), (0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (2.0, 2.0)]
            .map(|(x, y)| Point::new(x, y))
            .to_vec(),
    );
    assert_eq!(ring.distinct_points(), 4);
    for limit in 0..6 {
        assert_eq!(ring.distinct_points_up_to(limit), limit.min(4), "{limit}");
    }
}

/// Found by the `window_clippers` fuzz target: against a boundary 2.2e-16 long, Shewchuk's
/// adaptive orient2d has a certain sign but a magnitude 4% off, which moved Sutherland-Hodgman's
/// crossing by 0.003. The magnitude is now accurate to a few ulps.
#[test]
fn orient2d_magnitude_is_accurate_on_a_short_edge() {
    let (a, b) = (Point::new(3.1, 1.7), Point::new(3.1, 1.7000000000000002));
    let c = Point::new(3.391044776119403, 1.7970149253731345);
    let exact = -(b.y - a.y) * (c.x - a.x);
    let got = clip_core::predicates::orient2d(a, b, c);
    assert!((got - exact).abs() <= 4.0 * f64::EPSILON * exact.abs(), "{got:e} vs {exact:e}");
    // Far from degenerate, the plain determinant, with its exact sign.
    assert_eq!(clip_core::predicates::orient2d(Point::new(0.0, 0.0), Point::new(2.0, 0.0), Point::new(0.0, 3.0)), 6.0);
}

/// Found by the `line_clippers` fuzz target: a window edge near the origin and a segment end at
/// 6.4e25. The determinant's terms (4e51) cancel to 2.4e25; a compensated sum left it 1e-4 off,
/// which moved the line oracle's crossing by 1e-7 of the segment. Exactly: 0.875 x 6.4e25 - ...
#[test]
fn orient2d_magnitude_survives_heavy_cancellation() {
    let (p, q) = (Point::new(0.1, 0.7), Point::new(0.6, 1.575));
    let far = Point::new(6.428640832156875e25, 6.428640829009557e25);
    // cross(q - p, far - p), with q - p = (0.5, 0.875) to within an ulp of 0.6 and 1.575.
    let (dx, dy) = (q.x - p.x, q.y - p.y);
    let expected = dx * (far.y - p.y) - dy * (far.x - p.x);
    let got = clip_core::predicates::orient2d(p, q, far);
    assert!((got - expected).abs() <= 1e-12 * expected.abs(), "{got:e} vs {expected:e}");
}

/// Found by the `line_clippers` fuzz target: a ring that turns back at (3e140, 3e140) by 1e74 and
/// winds twice passed as convex, because the rounded cross product of that nearly 180° turn was 0
/// and counted as -π. Cyrus-Beck then clipped against half-planes that are not the window.
#[test]
fn a_ring_winding_twice_through_a_hairpin_is_not_convex() {
    let ring = Ring::new(vec![
        p(1e149, -1e149),
        p(2.9230032746618055e48, 1.1063927031522055e74),
        p(3.0000000000000004e140, 3.0000000000000004e140),
        p(5.0074178554068125e-33, 4.8458379975725604e-33),
        p(3.0000000000000004e140, 5e140),
    ]);
    assert_eq!(ring.convex_orientation(), None);
}
