//! The singular cases of Wang et al., pinned with hand-computed pieces for New1 and New2 (and, as
//! a cross-check, Liu and Cyrus-Beck), both window orientations and both segment directions.

mod common;

use clip_core::{ClipError, LineClipper, Polygons};
use clip_cyrus_beck::{CyrusBeck, Liu};
use clip_virtual_box::VirtualBox;
use common::{assert_intervals, clip, reversed, seg, window};

const SQUARE: &[(f64, f64)] = &[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)];
/// A U: two arms x in [0,1] and [2,3], joined by the bottom y in [0,1]; the notch between the arms.
const U: &[(f64, f64)] =
    &[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)];
/// An L: a step at (2,2) where the edge (4,2)-(2,2) joins a convex and a concave vertex.
const L: &[(f64, f64)] = &[(0.0, 0.0), (4.0, 0.0), (4.0, 2.0), (2.0, 2.0), (2.0, 4.0), (0.0, 4.0)];

/// Checks `expected` for the segment and the reversed pieces for the reversed segment, with the
/// window in both orientations, on every clipper that takes the window.
fn check(points: &[(f64, f64)], s: clip_core::Segment, expected: &[(f64, f64)], what: &str) {
    let w = window(points);
    let convex = w.rings[0].convex_orientation().is_some();
    let mut clippers: Vec<&dyn LineClipper> = vec![&VirtualBox::NEW2, &VirtualBox::NEW1, &Liu];
    if convex {
        clippers.push(&CyrusBeck);
    }
    let flipped: Vec<(f64, f64)> = expected.iter().rev().map(|&(a, b)| (1.0 - b, 1.0 - a)).collect();
    for c in clippers {
        for win in [w.clone(), reversed(&w)] {
            let tag = format!("{what} ({}, window {:?})", c.name(), win.rings[0].signed_area() > 0.0);
            assert_intervals(&clip(c, &win, s), expected, 1e-12, &tag);
            assert_intervals(&clip(c, &win, s.reversed()), &flipped, 1e-12, &format!("{tag} reversed"));
        }
    }
}

#[test]
fn crossing_the_interior() {
    check(SQUARE, seg(-1.0, 2.0, 5.0, 2.0), &[(1.0 / 6.0, 5.0 / 6.0)], "horizontal through");
    check(SQUARE, seg(2.0, -1.0, 2.0, 5.0), &[(1.0 / 6.0, 5.0 / 6.0)], "vertical through");
    check(SQUARE, seg(1.0, 1.0, 3.0, 2.0), &[(0.0, 1.0)], "inside");
}

#[test]
fn through_a_convex_vertex() {
    check(SQUARE, seg(2.0, 6.0, 6.0, 2.0), &[], "touching the corner from outside");
    check(SQUARE, seg(-2.0, -2.0, 6.0, 6.0), &[(0.25, 0.75)], "diagonal through two corners");
    // The U's top-left corner (0,3) entering, the concave (2,1) crossing (Eq. 4), (3,0) leaving.
    check(U, seg(-1.0, 4.0, 4.0, -1.0), &[(0.2, 0.4), (0.6, 0.8)], "corner, concave vertex, corner");
}

#[test]
fn through_a_concave_vertex() {
    // Through (1,1) with both neighbours above the line (Eq. 5): inside on both sides, one piece.
    check(U, seg(-1.0, 3.0, 3.0, -1.0), &[(0.25, 0.75)], "touching a concave vertex from inside");
    // Through the concave (2,1) of the L's step... the L has (2,2): neighbours (4,2) and (2,4).
    check(L, seg(0.0, 4.0, 4.0, 0.0), &[(0.0, 1.0)], "through the step's concave vertex");
}

#[test]
fn along_an_edge() {
    check(SQUARE, seg(-1.0, 0.0, 5.0, 0.0), &[(1.0 / 6.0, 5.0 / 6.0)], "along the bottom, beyond both ends");
    check(SQUARE, seg(2.0, 0.0, 6.0, 0.0), &[(0.0, 0.5)], "along the bottom from its middle");
    check(SQUARE, seg(1.0, 4.0, 3.0, 4.0), &[(0.0, 1.0)], "inside the top edge");
    // The notch's bottom between two concave vertices: inside, boundary, inside: one piece (Fig. 7c).
    check(U, seg(-1.0, 1.0, 4.0, 1.0), &[(0.2, 0.8)], "along the notch bottom");
    // The arms' tops, both ends convex (Fig. 7a): two pieces, the notch opening between them.
    check(U, seg(-1.0, 3.0, 4.0, 3.0), &[(0.2, 0.4), (0.6, 0.8)], "along the arms' tops");
    // The step of the L, one convex and one concave end (Fig. 7b).
    check(L, seg(-1.0, 2.0, 5.0, 2.0), &[(1.0 / 6.0, 5.0 / 6.0)], "along the step");
    check(L, seg(3.0, 2.0, 5.0, 2.0), &[(0.0, 0.5)], "along the step from its middle, leaving");
}

#[test]
fn endpoints_on_the_boundary() {
    check(SQUARE, seg(0.0, 2.0, 2.0, 2.0), &[(0.0, 1.0)], "start on an edge, going in");
    check(SQUARE, seg(0.0, 2.0, -2.0, 2.0), &[], "start on an edge, going out");
    check(SQUARE, seg(2.0, 2.0, 4.0, 2.0), &[(0.0, 1.0)], "end on an edge");
    check(SQUARE, seg(0.0, 0.0, 2.0, 2.0), &[(0.0, 1.0)], "start on a vertex, going in");
    check(SQUARE, seg(0.0, 0.0, -1.0, 2.0), &[], "start on a vertex, going out");
    check(SQUARE, seg(4.0, 4.0, 0.0, 0.0), &[(0.0, 1.0)], "vertex to vertex through the interior");
    check(U, seg(1.0, 2.0, 2.0, 2.0), &[], "across the notch, edge to edge");
    check(U, seg(1.0, 1.0, 2.0, 2.0), &[], "from a concave vertex into the notch");
}

#[test]
fn inside_the_box_but_outside_the_window() {
    // The paper's segment e: within the MEB, in the notch.
    check(U, seg(1.2, 2.0, 1.8, 2.5), &[], "in the notch");
    check(U, seg(1.5, 1.5, 1.5, 4.0), &[], "vertical in the notch, leaving the box");
}

#[test]
fn rejected_by_the_bounding_box() {
    check(SQUARE, seg(5.0, 5.0, 6.0, 1.0), &[], "right of the box");
    check(SQUARE, seg(-3.0, -1.0, 9.0, -0.5), &[], "below the box");
    check(SQUARE, seg(3.0, 6.0, 6.0, 3.0), &[], "across the corner of the box");
}

#[test]
fn several_rings_under_even_odd() {
    let square = |x: f64, y: f64, s: f64| common::ring(&[(x, y), (x + s, y), (x + s, y + s), (x, y + s)]);
    let holed = Polygons::new(vec![square(0.0, 0.0, 10.0), square(3.0, 3.0, 4.0)]);
    let cases = [
        (seg(-1.0, 5.0, 11.0, 5.0), vec![(1.0 / 12.0, 4.0 / 12.0), (8.0 / 12.0, 11.0 / 12.0)]),
        (seg(-1.0, 3.0, 11.0, 3.0), vec![(1.0 / 12.0, 11.0 / 12.0)]),
        (seg(4.0, 4.0, 6.0, 6.0), vec![]),
        (seg(7.0, 5.0, 8.0, 5.0), vec![(0.0, 1.0)]),
    ];
    for w in [holed.clone(), reversed(&holed), Polygons::new(vec![holed.rings[0].clone(), holed.rings[1].reversed()])] {
        for (s, expected) in &cases {
            assert_intervals(&clip(&VirtualBox::NEW2, &w, *s), expected, 1e-12, &format!("holed square, {s:?}"));
        }
    }
    let apart = Polygons::new(vec![square(0.0, 0.0, 2.0), square(4.0, 0.0, 2.0)]);
    assert_intervals(
        &clip(&VirtualBox::NEW1, &apart, seg(-1.0, 1.0, 7.0, 1.0)),
        &[(0.125, 0.375), (0.625, 0.875)],
        1e-12,
        "apart",
    );
    // Two squares sharing an edge: the shared edge is boundary, so the pieces merge.
    let sharing = Polygons::new(vec![square(0.0, 0.0, 2.0), square(2.0, 0.0, 2.0)]);
    assert_intervals(
        &clip(&VirtualBox::NEW1, &sharing, seg(-1.0, 1.0, 5.0, 1.0)),
        &[(1.0 / 6.0, 5.0 / 6.0)],
        1e-12,
        "sharing",
    );
    // Two copies cancel under even-odd, but their edges stay boundary.
    let twice = Polygons::new(vec![square(0.0, 0.0, 2.0), square(0.0, 0.0, 2.0)]);
    assert_intervals(&clip(&VirtualBox::NEW1, &twice, seg(-1.0, 1.0, 3.0, 1.0)), &[], 1e-12, "cancelled");
    assert_intervals(
        &clip(&VirtualBox::NEW1, &twice, seg(-1.0, 0.0, 3.0, 0.0)),
        &[(0.25, 0.75)],
        1e-12,
        "cancelled edge",
    );
}

#[test]
fn bad_input_is_an_error_or_nothing() {
    let w = window(SQUARE);
    for c in [&VirtualBox::NEW2 as &dyn LineClipper, &VirtualBox::NEW1] {
        let prepared = c.prepare(&w).unwrap();
        let mut out = Vec::new();
        let nan = seg(0.0, f64::NAN, 1.0, 1.0);
        let err = prepared.clip_batch(&[seg(1.0, 1.0, 2.0, 2.0), nan], &mut out).unwrap_err();
        assert!(matches!(err, ClipError::NonFinite { part: 1, .. }), "{}: {err:?}", c.name());
        assert!(out.is_empty(), "{}: nothing written before the error", c.name());
        prepared.clip_batch(&[seg(2.0, 2.0, 2.0, 2.0), seg(9.0, 9.0, 9.0, 9.0)], &mut out).unwrap();
        assert!(out.is_empty(), "{}: zero-length segments show nothing", c.name());
        let inf = seg(f64::INFINITY, 0.0, 1.0, 1.0);
        assert!(prepared.clip_batch(&[inf], &mut out).is_err());
        for bad in [
            Polygons::empty(),
            window(&[(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)]),
            window(&[(0.0, 0.0), (1.0, f64::NAN), (2.0, 0.0)]),
        ] {
            assert!(c.prepare(&bad).is_err(), "{}: degenerate window {bad:?} accepted", c.name());
        }
    }
}

#[test]
fn a_convex_window_with_collinear_vertices() {
    // Extra vertices in the middle of edges do not change anything.
    let w = &[(0.0, 0.0), (2.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, 4.0), (0.0, 4.0), (0.0, 2.0)];
    check(w, seg(-1.0, 0.0, 5.0, 0.0), &[(1.0 / 6.0, 5.0 / 6.0)], "along an edge with a middle vertex");
    check(w, seg(-2.0, 2.0, 6.0, -2.0), &[(0.25, 0.5)], "in at (0,1), out through the middle vertex (2,0)");
    check(w, seg(2.0, 0.0, 2.0, -3.0), &[], "from the middle vertex (2,0) outwards");
    check(w, seg(-2.0, 2.0, 6.0, 2.0), &[(0.25, 0.75)], "through the middle vertex (0,2)");
}
