//! Removes repeated and collinear vertices from a ring, zero-area spikes included.

use clip_core::Point;
use clip_core::predicates::{Orientation, orient};

/// The ring without repeated consecutive vertices and without vertices whose neighbours are
/// collinear with them (straight-through vertices and the tips of zero-area spikes). Neither
/// changes the winding number of any point off the ring, so the region is the same. Returns an
/// empty list when fewer than three vertices remain (the ring encloses nothing).
pub(crate) fn simplify_ring(points: &[Point]) -> Vec<Point> {
    let mut out: Vec<Point> = Vec::with_capacity(points.len());
    simplify_ring_keeping(points, &mut out, false);
    out
}

/// [`simplify_ring`] into `out` (cleared first, so a caller can reuse one buffer), keeping
/// straight-through vertices when `straight` (repeats and spike tips still go). For snap-rounded operands, whose edges meet only at vertices: dropping a
/// straight-through vertex where an edge of the other operand passes would make a crossing
/// there, and the sweep would round it.
pub(crate) fn simplify_ring_keeping(points: &[Point], out: &mut Vec<Point>, straight: bool) {
    out.clear();
    for &p in points {
        push_vertex(out, p, straight);
    }
    // The closing edge: drop vertices at the seam while they repeat or are collinear there.
    // Every pass removes a vertex or stops, so this ends.
    loop {
        let n = out.len();
        if n < 3 {
            out.clear();
            return;
        }
        if out[n - 1] == out[0] || drops(out[n - 2], out[n - 1], out[0], straight) {
            out.pop();
        } else if drops(out[n - 1], out[0], out[1], straight) {
            out.remove(0);
        } else {
            return;
        }
    }
}

/// Whether vertex `b` between `a` and `c` goes: collinear with them, and with `straight` only
/// a spike's tip (the ring turns back at `b`) or a vertex inside a horizontal run (the sweep
/// takes a bound's horizontals as one run; a slanted edge through it keeps its own vertex).
fn drops(a: Point, b: Point, c: Point, straight: bool) -> bool {
    orient(a, b, c) == Orientation::Collinear && (!straight || (a - b).dot(c - b) > 0.0 || a.y == c.y)
}

/// Appends `p`, first popping every vertex that `p` makes collinear (a spike's tip only, with
/// `straight`) or repeated.
fn push_vertex(out: &mut Vec<Point>, p: Point, straight: bool) {
    loop {
        let n = out.len();
        if n >= 1 && out[n - 1] == p {
            return;
        }
        if n >= 2 && drops(out[n - 2], out[n - 1], p, straight) {
            out.pop();
            continue;
        }
        out.push(p);
        return;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(v: &[(f64, f64)]) -> Vec<Point> {
        v.iter().map(|&p| p.into()).collect()
    }

    #[test]
    fn drops_collinear_spikes_and_repeats() {
        let ring =
            pts(&[(0.0, 0.0), (1.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 2.0), (2.0, 3.0), (2.0, 1.0), (0.0, 2.0)]);
        assert_eq!(simplify_ring(&ring), pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 2.0)]));
    }

    #[test]
    fn straight_through_vertices_stay_when_asked() {
        let ring =
            pts(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 2.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.5), (0.0, 2.0)]);
        let mut out = Vec::new();
        simplify_ring_keeping(&ring, &mut out, true);
        // (1, 1.5) stays; (1, 0) inside a horizontal run goes, and so do the spike's tip (2, 3)
        // and then (2, 2), where the ring turns back.
        assert_eq!(out, pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.5), (0.0, 2.0)]));
        assert_eq!(simplify_ring(&ring), pts(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 2.0)]));
    }

    #[test]
    fn collinear_ring_vanishes() {
        assert!(simplify_ring(&pts(&[(0.0, 0.0), (1.0, 1.0), (3.0, 3.0)])).is_empty());
    }

    #[test]
    fn seam_vertex_is_removed() {
        let ring = pts(&[(1.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (0.0, 0.0)]);
        assert_eq!(simplify_ring(&ring), pts(&[(2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (0.0, 0.0)]));
    }
}
