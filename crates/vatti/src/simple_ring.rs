//! A lone small ring that neither crosses nor touches itself is its own conventional form: found
//! by testing every pair of its edges exactly, so such an operand skips the sweep.

use clip_core::predicates::{SegmentIntersection, segment_intersection};
use clip_core::{FillRule, Polygons, Ring, Segment};

use crate::simplify::simplify_ring;

/// The most vertices a ring may have for the pairwise test (it costs their square).
const MAX_VERTICES: usize = 24;

/// The conventional form of `operand`'s region under `fill` when it is one simple ring of at most
/// [`MAX_VERTICES`] vertices (without repeated and collinear ones): the ring counter-clockwise, or
/// nothing when the fill rule leaves it empty. `None` when that does not apply.
pub(crate) fn alone(operand: &Polygons, fill: FillRule) -> Option<Polygons> {
    let [ring] = operand.rings.as_slice() else { return None };
    if ring.points.len() > MAX_VERTICES {
        return None;
    }
    let ring = Ring { points: simplify_ring(&ring.points) };
    let n = ring.points.len();
    if n < 3 {
        return Some(Polygons::default());
    }
    let edge = |i: usize| Segment::new(ring.points[i], ring.points[(i + 1) % n]);
    // Consecutive edges share a vertex and, with no collinear vertex left, nothing else.
    let crossed = (0..n).any(|i| {
        (i + 2..n)
            .filter(|&j| (j + 1) % n != i)
            .any(|j| segment_intersection(edge(i), edge(j)) != SegmentIntersection::None)
    });
    if crossed {
        return None;
    }
    // A sliver whose rounded area is near zero has its orientation and form left to the sweep.
    let area = ring.signed_area();
    let b = ring.bounds();
    let scale = b.width().max(b.height());
    if area.abs() <= 1e-6 * scale * scale {
        return None;
    }
    let inside = fill.is_inside(if area > 0.0 { 1 } else { -1 });
    Some(match (inside, area > 0.0) {
        (false, _) => Polygons::default(),
        (true, true) => Polygons::new(vec![ring]),
        (true, false) => Polygons::new(vec![ring.reversed()]),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Point;

    fn ring(pts: &[(f64, f64)]) -> Polygons {
        Polygons::from(Ring::new(pts.iter().map(|&(x, y)| Point::new(x, y)).collect()))
    }

    #[test]
    fn simple_rings_are_their_own_form_and_others_are_left_to_the_sweep() {
        let cw_square = ring(&[(0.0, 0.0), (0.0, 1.0), (1.0, 1.0), (1.0, 0.0)]);
        let out = alone(&cw_square, FillRule::NonZero).unwrap();
        assert_eq!(out.signed_area(), 1.0);
        assert!(alone(&cw_square, FillRule::Positive).unwrap().rings.is_empty());
        // A bow tie crosses itself; two squares touching at a corner touch.
        assert!(alone(&ring(&[(0.0, 0.0), (2.0, 2.0), (2.0, 0.0), (0.0, 2.0)]), FillRule::NonZero).is_none());
        let pinched =
            ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (2.0, 1.0), (2.0, 2.0), (1.0, 2.0), (1.0, 1.0), (0.0, 1.0)]);
        assert!(alone(&pinched, FillRule::NonZero).is_none());
        // A collinear vertex goes, as the sweep drops it.
        let out = alone(&ring(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 2.0)]), FillRule::EvenOdd).unwrap();
        assert_eq!(out.rings[0].points.len(), 3);
    }
}
