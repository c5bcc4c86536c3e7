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
