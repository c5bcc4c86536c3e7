//! Intersected edges from products of adjacent vertex codes, and the singular cases (Eqs. 1-6).

use core::ops::Range;

use clip_core::{LineCrossings, LineFrame, Point};

use crate::vertex_codes::EXACT;

/// Records in `display` every valid intersection of the segment's line with the window's edges,
/// from the vertex codes (each ring stored closed: `points[ring.end]` repeats its first vertex).
///
/// An edge whose end codes multiply to -1 (Eq. 2) crosses the line: its intersection is computed.
/// A product of +1 (Eq. 1) means no intersection. A product of 0 (Eq. 3) involves a vertex on the
/// line, settled by [`singular`] once per ring.
pub(crate) fn intersect(
    points: &[Point],
    rings: &[Range<usize>],
    codes: &[i8],
    sides: &[f64],
    frame: &LineFrame,
    display: &mut LineCrossings,
) {
    display.clear();
    for ring in rings {
        let mut on_line = false;
        for i in ring.clone() {
            let (cp, cq) = (codes[i], codes[i + 1]);
            on_line |= cp == 0;
            if cp * cq < 0 {
                let (p, q) = (points[i], points[i + 1]);
                let (place, t) = if cp.abs() == EXACT && cq.abs() == EXACT {
                    frame.edge_crossing(p, q, sides[i], sides[i + 1])
                } else {
                    frame.edge_crossing_by_edge(p, q, cp > 0)
                };
                display.record(place, t);
            }
        }
        if on_line {
            singular(points, ring.clone(), codes, frame, display);
        }
    }
}

/// The singular cases of one ring: each maximal run of consecutive vertices on the line (code 0),
/// between neighbours with codes `f_before` and `f_after`.
///
/// - One vertex `V_i` (Eqs. 4, 5): `f_(i-1) f_(i+1) = -1`, the ring crosses the line at `V_i`,
///   which is recorded; `+1`, it touches the line there and `V_i` is ignored.
/// - Several vertices (Eq. 6, an edge along the line): the edges of the run are boundary lying on
///   the segment's line, recorded as such (visible under the closed-set rule). The run counts as
///   one crossing, at its first vertex, when its neighbours lie on opposite sides, and as none
///   when on the same side. This replaces the paper's convex/concave vertex test (see the crate
///   documentation).
/// - A ring lying wholly on the line: every edge is boundary along it.
fn singular(points: &[Point], ring: Range<usize>, codes: &[i8], frame: &LineFrame, display: &mut LineCrossings) {
    let (start, n) = (ring.start, ring.len());
    let code = |i: usize| codes[start + i % n].signum();
    let point = |i: usize| points[start + i % n];
    let on_line = |p: Point| (frame.place(p), frame.param(p));
    let Some(first_off) = (0..n).find(|&i| code(i) != 0) else {
        for i in 0..n {
            display.along(on_line(point(i)), on_line(point(i + 1)));
        }
        return;
    };
    let mut i = first_off + 1;
    while i < first_off + n {
        if code(i) != 0 {
            i += 1;
            continue;
        }
        let run = i;
        // Ends at `first_off + n` at the latest, whose code is not 0.
        while code(i) == 0 {
            i += 1;
        }
        for j in run..i - 1 {
            display.along(on_line(point(j)), on_line(point(j + 1)));
        }
        if code(run - 1) != code(i) {
            let (place, t) = on_line(point(run));
            display.record(place, t);
        }
    }
}
