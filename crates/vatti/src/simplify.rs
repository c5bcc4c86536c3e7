//! Removes repeated and collinear vertices from a ring, zero-area spikes included.

use clip_core::Point;
use clip_core::predicates::{Orientation, orient};

/// The ring without repeated consecutive vertices and without vertices whose neighbours are
/// collinear with them (straight-through vertices and the tips of zero-area spikes). Neither
/// changes the winding number of any point off the ring, so the region is the same. Returns an
/// empty list when fewer than three vertices remain (the ring encloses nothing).
pub(crate) fn simplify_ring(points: &[Point]) -> Vec<Point> {
    let mut out: Vec<Point> = Vec::with_capacity(points.len());
    simplify_ring_into(points, &mut out);
    out
}

/// [`simplify_ring`] into `out` (cleared first), so a caller can reuse one buffer.
pub(crate) fn simplify_ring_into(points: &[Point], out: &mut Vec<Point>) {
    out.clear();
    for &p in points {
        push_vertex(out, p);
    }
    // The closing edge: drop vertices at the seam while they repeat or are collinear there.
    // Every pass removes a vertex or stops, so this ends.
    loop {
        let n = out.len();
        if n < 3 {
            out.clear();
            return;
        }
        if out[n - 1] == out[0] || orient(out[n - 2], out[n - 1], out[0]) == Orientation::Collinear {
            out.pop();
        } else if orient(out[n - 1], out[0], out[1]) == Orientation::Collinear {
            out.remove(0);
        } else {
            return;
        }
    }
}

/// Appends `p`, first popping every vertex that `p` makes collinear or repeated.
fn push_vertex(out: &mut Vec<Point>, p: Point) {
    loop {
        let n = out.len();
        if n >= 1 && out[n - 1] == p {
            return;
        }
        if n >= 2 && orient(out[n - 2], out[n - 1], p) == Orientation::Collinear {
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
    fn collinear_ring_vanishes() {
        assert!(simplify_ring(&pts(&[(0.0, 0.0), (1.0, 1.0), (3.0, 3.0)])).is_empty());
    }

    #[test]
    fn seam_vertex_is_removed() {
        let ring = pts(&[(1.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (0.0, 0.0)]);
        assert_eq!(simplify_ring(&ring), pts(&[(2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (0.0, 0.0)]));
    }
}
