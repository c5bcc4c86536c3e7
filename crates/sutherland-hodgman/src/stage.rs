//! The four vertex cases of one boundary stage, shared by the list form and the pipeline form.

use crate::boundary::{Boundary, Side};
use crate::vertex::StageVertex;

/// What one step of a stage passes on: none, one or two vertices.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Emitted<V> {
    slots: [Option<V>; 2],
}

impl<V: Copy> Emitted<V> {
    fn none() -> Self {
        Emitted { slots: [None, None] }
    }
    fn one(v: V) -> Self {
        Emitted { slots: [Some(v), None] }
    }
    fn two(a: V, b: V) -> Self {
        Emitted { slots: [Some(a), Some(b)] }
    }
    /// The vertices, in output order.
    pub(crate) fn into_iter(self) -> impl Iterator<Item = V> {
        self.slots.into_iter().flatten()
    }
}

/// The edge `s -> p` against boundary `k`: the notes' four cases.
///
/// 1. out -> in: the crossing, then `p`;
/// 2. in -> in: `p`;
/// 3. in -> out: the crossing;
/// 4. out -> out: nothing.
///
/// "In" is the closed half-plane. A vertex exactly on the line is its own crossing, so a crossing
/// is made only when one end is strictly inside and the other strictly outside; that keeps the
/// classic output minus the repeated vertices it would otherwise emit.
#[inline]
pub(crate) fn step<V: StageVertex>(
    boundary: &Boundary,
    k: usize,
    s: V,
    s_side: Side,
    p: V,
    p_side: Side,
) -> Emitted<V> {
    if p_side.outside() {
        if s_side.strictly_inside() {
            let at = boundary.crossing(s.point(), s_side, p.point(), p_side);
            Emitted::one(V::crossing(s, p, k, at))
        } else {
            Emitted::none()
        }
    } else if p_side.on_line() {
        Emitted::one(p.on_boundary(k))
    } else if s_side.outside() {
        let at = boundary.crossing(s.point(), s_side, p.point(), p_side);
        Emitted::two(V::crossing(s, p, k, at), p)
    } else {
        Emitted::one(p)
    }
}

#[cfg(test)]
mod tests {
    //! The notes' four vertex cases (Fig. 6-20) against the left boundary `x >= 0` of a
    //! counter-clockwise window, whose left edge runs downwards.

    use clip_core::Point;

    use super::*;

    const LEFT: Boundary = Boundary { from: Point::new(0.0, 10.0), to: Point::new(0.0, 0.0) };

    fn run(s: Point, p: Point) -> Vec<Point> {
        step(&LEFT, 0, s, LEFT.side(s), p, LEFT.side(p)).into_iter().collect()
    }

    #[test]
    fn out_to_in_emits_the_crossing_then_the_second_vertex() {
        let (s, p) = (Point::new(-2.0, 2.0), Point::new(2.0, 6.0));
        assert_eq!(run(s, p), vec![Point::new(0.0, 4.0), p]);
    }

    #[test]
    fn in_to_in_emits_the_second_vertex() {
        let (s, p) = (Point::new(1.0, 2.0), Point::new(3.0, 5.0));
        assert_eq!(run(s, p), vec![p]);
    }

    #[test]
    fn in_to_out_emits_the_crossing_only() {
        let (s, p) = (Point::new(2.0, 6.0), Point::new(-2.0, 2.0));
        assert_eq!(run(s, p), vec![Point::new(0.0, 4.0)]);
    }

    #[test]
    fn out_to_out_emits_nothing() {
        assert_eq!(run(Point::new(-1.0, 1.0), Point::new(-3.0, 7.0)), vec![]);
    }

    #[test]
    fn a_vertex_on_the_boundary_is_inside_and_its_own_crossing() {
        let on = Point::new(0.0, 3.0);
        assert_eq!(run(Point::new(-1.0, 1.0), on), vec![on]);
        assert_eq!(run(on, Point::new(-1.0, 1.0)), vec![]);
        assert_eq!(run(on, Point::new(1.0, 1.0)), vec![Point::new(1.0, 1.0)]);
    }

    #[test]
    fn a_crossing_does_not_depend_on_the_walking_direction() {
        let slanted = Boundary { from: Point::new(0.1, 0.3), to: Point::new(7.7, 3.1) };
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut next = || {
            seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 20.0 - 10.0
        };
        let mut checked = 0;
        while checked < 500 {
            let (p, q) = (Point::new(next(), next()), Point::new(next(), next()));
            let (sp, sq) = (slanted.side(p), slanted.side(q));
            if sp.strictly_inside() == sq.outside() && !sp.on_line() && !sq.on_line() {
                let c = slanted.crossing(p, sp, q, sq);
                assert_eq!(c, slanted.crossing(q, sq, p, sp));
                assert!(c.x >= p.x.min(q.x) && c.x <= p.x.max(q.x));
                checked += 1;
            }
        }
    }
}
