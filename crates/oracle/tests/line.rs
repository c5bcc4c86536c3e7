//! The line oracle on hand cases, against Liang-Barsky on rectangles, and catching wrong pieces.

use clip_core::{Point, Polygons, Rect, Ring, Segment, VisiblePiece, WindowKind};
use clip_oracle::line::*;
use clip_testkit::workload::line_case;
use proptest::prelude::*;

fn seg(ax: f64, ay: f64, bx: f64, by: f64) -> Segment {
    Segment::new(Point::new(ax, ay), Point::new(bx, by))
}

fn square() -> Polygons {
    Polygons::from(Rect::new(0.0, 0.0, 10.0, 10.0))
}

fn diamond() -> Polygons {
    Polygons::from(Ring::from(&[(0.0, -10.0), (10.0, 0.0), (0.0, 10.0), (-10.0, 0.0)][..]))
}

/// A U: the notch is x in [10, 20], y above 10.
fn u_shape() -> Polygons {
    Polygons::from(Ring::from(
        &[(0.0, 0.0), (30.0, 0.0), (30.0, 30.0), (20.0, 30.0), (20.0, 10.0), (10.0, 10.0), (10.0, 30.0), (0.0, 30.0)][..],
    ))
}

#[test]
fn hand_cases() {
    let v = visible_intervals;
    // Across, and the same reversed: t counts from the segment's own start.
    assert_eq!(v(&square(), seg(-5.0, 5.0, 15.0, 5.0)), vec![(0.25, 0.75)]);
    assert_eq!(v(&square(), seg(15.0, 5.0, -5.0, 5.0)), vec![(0.25, 0.75)]);
    // Through two vertices of the diamond.
    assert_eq!(v(&diamond(), seg(-20.0, 0.0, 20.0, 0.0)), vec![(0.25, 0.75)]);
    // Along an edge: the boundary is visible.
    assert_eq!(v(&square(), seg(-5.0, 0.0, 15.0, 0.0)), vec![(0.25, 0.75)]);
    assert_eq!(v(&diamond(), seg(-15.0, -5.0, 5.0, 15.0)), vec![(0.25, 0.75)]);
    // Endpoint on the boundary, going out: only a point, dropped; going in: all of it.
    assert_eq!(v(&square(), seg(10.0, 5.0, 20.0, 5.0)), vec![]);
    assert_eq!(v(&square(), seg(10.0, 5.0, 5.0, 5.0)), vec![(0.0, 1.0)]);
    // Touching at a vertex only: dropped.
    assert_eq!(v(&diamond(), seg(10.0, -5.0, 10.0, 5.0)), vec![]);
    assert_eq!(v(&square(), seg(5.0, 15.0, 15.0, 5.0)), vec![]);
    // A concave window gives two pieces...
    assert_eq!(v(&u_shape(), seg(-10.0, 20.0, 40.0, 20.0)), vec![(0.2, 0.4), (0.6, 0.8)]);
    // ...and one where the segment runs along the notch's floor (boundary in between).
    assert_eq!(v(&u_shape(), seg(-10.0, 10.0, 40.0, 10.0)), vec![(0.2, 0.8)]);
    // Two triangles meeting at a vertex (a bow-tie): merged at the vertex.
    let bow = Polygons::from(Ring::from(&[(0.0, 0.0), (20.0, 20.0), (20.0, 0.0), (0.0, 20.0)][..]));
    assert_eq!(v(&bow, seg(-10.0, 10.0, 30.0, 10.0)), vec![(0.25, 0.75)]);
    // Even-odd: a hole splits the segment; a ring and its copy cancel.
    let holed =
        Polygons::new(vec![Rect::new(0.0, 0.0, 10.0, 10.0).to_ring(), Rect::new(4.0, 0.0, 6.0, 10.0).to_ring()]);
    assert_eq!(v(&holed, seg(0.0, 5.0, 10.0, 5.0)), vec![(0.0, 0.4), (0.6, 1.0)]);
    let twice =
        Polygons::new(vec![Rect::new(0.0, 0.0, 10.0, 10.0).to_ring(), Rect::new(0.0, 0.0, 10.0, 10.0).to_ring()]);
    assert_eq!(v(&twice, seg(-5.0, 5.0, 15.0, 5.0)), vec![]);
    // Zero length: nothing, even inside.
    assert_eq!(v(&square(), seg(5.0, 5.0, 5.0, 5.0)), vec![]);
    // Entirely inside or outside.
    assert_eq!(v(&square(), seg(1.0, 1.0, 9.0, 2.0)), vec![(0.0, 1.0)]);
    assert_eq!(v(&square(), seg(11.0, 1.0, 19.0, 2.0)), vec![]);
}

fn pieces(s: &[Segment], intervals: &[&[(f64, f64)]]) -> Vec<VisiblePiece> {
    intervals
        .iter()
        .enumerate()
        .flat_map(|(i, iv)| {
            iv.iter().map(move |&(a, b)| VisiblePiece { segment: i, piece: Segment::new(s[i].at(a), s[i].at(b)) })
        })
        .collect()
}

#[test]
fn batch_check_accepts_right_pieces_and_catches_wrong_ones() {
    let w = u_shape();
    let segs = [seg(-10.0, 20.0, 40.0, 20.0), seg(5.0, 5.0, 25.0, 5.0), seg(50.0, 0.0, 60.0, 0.0)];
    let right = pieces(&segs, &[&[(0.2, 0.4), (0.6, 0.8)], &[(0.0, 1.0)], &[]]);
    check_line_batch(&w, &segs, &right, LINE_T_TOLERANCE).unwrap();
    assert_eq!(
        pieces_to_intervals(&w.bounds(), &segs, &right),
        vec![vec![(0.2, 0.4), (0.6, 0.8)], vec![(0.0, 1.0)], vec![]]
    );

    // A missing piece.
    let missing = pieces(&segs, &[&[(0.2, 0.4)], &[(0.0, 1.0)], &[]]);
    assert!(matches!(
        check_line_batch(&w, &segs, &missing, LINE_T_TOLERANCE),
        Err(LineFailure::WrongPieces { segment: 0, .. })
    ));
    // A piece that crosses the notch.
    let bridged = pieces(&segs, &[&[(0.2, 0.8)], &[(0.0, 1.0)], &[]]);
    assert!(check_line_batch(&w, &segs, &bridged, LINE_T_TOLERANCE).is_err());
    // A piece walked backwards.
    let mut reversed = right.clone();
    reversed[2].piece = reversed[2].piece.reversed();
    assert!(
        matches!(check_line_batch(&w, &segs, &reversed, LINE_T_TOLERANCE), Err(LineFailure::BadPiece(m)) if m.contains("against"))
    );
    // A piece off its segment.
    let mut off = right.clone();
    off[0].piece.a.y += 0.5;
    assert!(
        matches!(check_line_batch(&w, &segs, &off, LINE_T_TOLERANCE), Err(LineFailure::BadPiece(m)) if m.contains("not on"))
    );
    // Split where it should be merged.
    let split = pieces(&segs, &[&[(0.2, 0.4), (0.6, 0.8)], &[(0.0, 0.5), (0.5, 1.0)], &[]]);
    assert!(
        matches!(check_line_batch(&w, &segs, &split, LINE_T_TOLERANCE), Err(LineFailure::BadPiece(m)) if m.contains("one"))
    );
    // Out of order.
    let mut swapped = right.clone();
    swapped.swap(0, 1);
    assert!(check_line_batch(&w, &segs, &swapped, LINE_T_TOLERANCE).is_err());
    // A zero-length piece for a touch point.
    let touch = [seg(5.0, 15.0, 15.0, 5.0)];
    let point = [VisiblePiece { segment: 0, piece: Segment::new(Point::new(10.0, 10.0), Point::new(10.0, 10.0)) }];
    check_line_batch(&square(), &touch, &[], LINE_T_TOLERANCE).unwrap();
    assert!(check_line_batch(&square(), &touch, &point, LINE_T_TOLERANCE).is_err());
    // Rounding-sized differences are tolerated.
    let mut nudged = right.clone();
    nudged[0].piece.a = segs[0].at(0.2 + 1e-12);
    check_line_batch(&w, &segs, &nudged, LINE_T_TOLERANCE).unwrap();
}

#[test]
fn degenerate_workload_runs() {
    // Convex windows give at most one interval per segment; every interval is proper.
    for i in 0..20 {
        let c = line_case("lines-degenerate", 2, i, WindowKind::Convex, 100).unwrap();
        for s in &c.segments {
            let v = visible_intervals(&c.window, *s);
            assert!(v.len() <= 1, "{}: {s:?} -> {v:?}", c.description);
            assert!(v.iter().all(|&(a, b)| 0.0 <= a && a < b && b <= 1.0));
        }
    }
}

/// Liang-Barsky on a closed rectangle: the parameter range inside it, if of positive length.
fn liang_barsky(r: &Rect, s: Segment) -> Vec<(f64, f64)> {
    let d = s.b - s.a;
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-d.x, s.a.x - r.min.x), (d.x, r.max.x - s.a.x), (-d.y, s.a.y - r.min.y), (d.y, r.max.y - s.a.y)] {
        if p == 0.0 {
            if q < 0.0 {
                return vec![];
            }
        } else if p < 0.0 {
            t0 = t0.max(q / p);
        } else {
            t1 = t1.min(q / p);
        }
    }
    if t0 < t1 { vec![(t0, t1)] } else { vec![] }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// On small integer coordinates (so touching and collinear cases are common) the oracle
    /// agrees with Liang-Barsky on rectangles.
    #[test]
    fn agrees_with_liang_barsky(x0 in -5i32..5, y0 in -5i32..5, w in 1i32..6, h in 1i32..6,
                                ax in -8i32..8, ay in -8i32..8, bx in -8i32..8, by in -8i32..8) {
        let r = Rect::new(x0.into(), y0.into(), (x0 + w).into(), (y0 + h).into());
        let s = seg(ax.into(), ay.into(), bx.into(), by.into());
        let got = visible_intervals(&Polygons::from(r), s);
        let want = if s.is_degenerate() { vec![] } else { liang_barsky(&r, s) };
        prop_assert_eq!(got.len(), want.len(), "{:?} {:?}", got, want);
        for (g, e) in got.iter().zip(&want) {
            prop_assert!((g.0 - e.0).abs() < 1e-12 && (g.1 - e.1).abs() < 1e-12, "{:?} {:?}", got, want);
        }
    }

    /// Reversing a segment mirrors its intervals: t -> 1 - t.
    #[test]
    fn reversal_mirrors(ax in -8i32..8, ay in -8i32..8, bx in -8i32..8, by in -8i32..8) {
        let s = seg(ax.into(), ay.into(), bx.into(), by.into());
        let w = Polygons::from(Ring::from(&[(-6.0, -6.0), (6.0, -6.0), (6.0, 6.0), (0.0, 0.0), (-6.0, 6.0)][..]));
        let f: Vec<(f64, f64)> = visible_intervals(&w, s);
        let mut r: Vec<(f64, f64)> = visible_intervals(&w, s.reversed()).iter().map(|&(a, b)| (1.0 - b, 1.0 - a)).collect();
        r.reverse();
        prop_assert_eq!(f.len(), r.len());
        for (x, y) in f.iter().zip(&r) {
            prop_assert!((x.0 - y.0).abs() < 1e-12 && (x.1 - y.1).abs() < 1e-12);
        }
    }
}

/// Found by the `line_clippers` fuzz target: at 1e9 an ulp is 1.2e-7, so a piece of a segment
/// 2e-5 long ends up to a few percent of it off the exact crossing, whatever the clipper does.
#[test]
fn short_segments_far_from_the_origin_are_judged_at_their_rounding() {
    let (o, d) = (1e9, 1e-5);
    let window = Polygons::from(Rect::new(o, o, o + 2.0 * d, o + 2.0 * d));
    let s = Segment::new(Point::new(o - d, o + d), Point::new(o + d, o + d));
    let rounded = |x: f64| Point::new(x, o + d);
    // The exact piece starts at t = 0.5; an ulp later is still right, 20% later is not.
    let near = [VisiblePiece { segment: 0, piece: Segment::new(rounded((o).next_up()), s.b) }];
    assert_eq!(check_line_batch(&window, &[s], &near, LINE_T_TOLERANCE), Ok(()));
    let far = [VisiblePiece { segment: 0, piece: Segment::new(rounded(o + 0.4 * d), s.b) }];
    assert!(check_line_batch(&window, &[s], &far, LINE_T_TOLERANCE).is_err());
    assert!(parameter_tolerance(&window.bounds(), s, LINE_T_TOLERANCE) > 0.01);
    let near_origin = Segment::new(Point::new(0.0, 0.0), Point::new(1.0, 0.0));
    assert_eq!(parameter_tolerance(&Rect::new(0.0, 0.0, 1.0, 1.0), near_origin, LINE_T_TOLERANCE), LINE_T_TOLERANCE);
}

/// Found by the `line_clippers` fuzz target: intervals of 0.083 (expected) and 0.099 (got)
/// around a tolerance of 0.087 agree; they used to be compared after each side dropped its
/// intervals shorter than the tolerance, so one counted and the other did not.
#[test]
fn intervals_near_the_tolerance_agree_both_ways() {
    let window = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0));
    let s = Segment::new(Point::new(-1.0, 0.5), Point::new(1.0, 0.5));
    // Exact: t in [0.5, 1]. A piece ending a little early is fine within a loose tolerance
    // and wrong within a tight one; a missing half is wrong at both.
    let short = [VisiblePiece { segment: 0, piece: s.piece(0.5, 0.95) }];
    assert_eq!(check_line_batch(&window, &[s], &short, 0.06), Ok(()));
    assert!(check_line_batch(&window, &[s], &short, 0.01).is_err());
    assert!(check_line_batch(&window, &[s], &[], 0.06).is_err());
}

/// Found by the `line_clippers` fuzz target: a sliver window 5e-17 wide that a segment crosses
/// lengthwise between t = 1/6 and t = 1/2. A rounded point inside that run falls outside the
/// sliver, so runs are now classified by the parity of the edges the line crosses beyond them.
#[test]
fn a_segment_inside_a_sliver_thinner_than_an_ulp_is_visible() {
    let window = Polygons::from(Ring::new(vec![
        Point::new(0.975, 1.575),
        Point::new(1.8500000000000005, 2.4499999999999997),
        Point::new(1.85, 2.45),
    ]));
    let s = Segment::new(Point::new(2.06875, 2.66875), Point::new(0.75625, 1.35625));
    let got = visible_intervals(&window, s);
    assert_eq!(got.len(), 1, "{got:?}");
    assert!((got[0].0 - 1.0 / 6.0).abs() < 1e-9 && (got[0].1 - 0.5).abs() < 1e-9, "{got:?}");
    // Reversed, the same run from the other end.
    let back = visible_intervals(&window, s.reversed());
    assert!((back[0].0 - 0.5).abs() < 1e-9 && (back[0].1 - 5.0 / 6.0).abs() < 1e-9, "{back:?}");
}

/// Found by the `line_clippers` fuzz target: a segment ending on a window vertex and running
/// 1e-17 inside the window's edge is visible whole (its ends on the boundary left only a rounded
/// midpoint to decide, and it fell outside); moved an ulp across the edge, it is not.
#[test]
fn a_segment_an_ulp_inside_an_edge_is_visible() {
    let window = Polygons::from(Ring::new(vec![
        Point::new(1.85, 2.45),
        Point::new(5.35, 5.2),
        Point::new(6.225, 4.575),
        Point::new(-0.024999999999999994, 0.575),
    ]));
    let inside = Segment::new(Point::new(0.44375, 1.04375), Point::new(-0.024999999999999994, 0.575));
    assert_eq!(visible_intervals(&window, inside), vec![(0.0, 1.0)]);
    let outside = Segment::new(Point::new(0.44375, 1.04375_f64.next_up().next_up()), inside.b);
    assert_eq!(visible_intervals(&window, outside), vec![]);
}
