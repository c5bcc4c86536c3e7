//! The list form: the whole vertex list is clipped against one boundary, then the next.

use crate::stage::step;
use crate::vertex::StageVertex;
use crate::window::ConvexWindow;

/// Clips one closed vertex list against every boundary of `window` in turn, each stage building
/// a new list. Edges are taken in the order `v0 -> v1, ..., v(n-1) -> v0`, the order the pipeline
/// form sees them in, so both forms give the same vertices.
pub fn clip_list<V: StageVertex>(vertices: &[V], window: &ConvexWindow) -> Vec<V> {
    let mut input: Vec<V> = vertices.to_vec();
    let mut output: Vec<V> = Vec::with_capacity(input.len() + 4);
    for (k, boundary) in window.boundaries().iter().enumerate() {
        output.clear();
        let Some(&first) = input.first() else { break };
        let first_side = boundary.side(first.point());
        let (mut s, mut s_side) = (first, first_side);
        for &p in &input[1..] {
            let p_side = boundary.side(p.point());
            output.extend(step(boundary, k, s, s_side, p, p_side).into_iter());
            (s, s_side) = (p, p_side);
        }
        output.extend(step(boundary, k, s, s_side, first, first_side).into_iter());
        std::mem::swap(&mut input, &mut output);
    }
    input
}
