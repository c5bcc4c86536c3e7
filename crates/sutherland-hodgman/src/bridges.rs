//! Counting the zero-width bridges Sutherland-Hodgman lays along the window.

use clip_core::Polygons;

use crate::list_form::clip_list;
use crate::vertex::TaggedVertex;
use crate::window::ConvexWindow;

/// How many zero-width bridges clipping `subject` against `window` leaves in the output.
///
/// The clip is rerun with vertices that remember which boundaries they lie on, so an output edge
/// lies along boundary `k` exactly when both its ends do (no geometric tolerance). Within each
/// output ring, the edges along one boundary are intervals on its line; a bridge is a maximal
/// stretch of positive length covered both forwards and backwards. A result that does not fall
/// apart has none; a concave subject cut into `m` pieces by one boundary typically has `m - 1`.
pub fn bridge_count(subject: &Polygons, window: &ConvexWindow) -> usize {
    subject
        .rings
        .iter()
        .map(|ring| {
            let tagged: Vec<TaggedVertex> = ring.points.iter().map(|&p| TaggedVertex::new(p)).collect();
            ring_bridges(&clip_list(&tagged, window), window)
        })
        .sum()
}

/// Bridges within one clipped ring.
fn ring_bridges(ring: &[TaggedVertex], window: &ConvexWindow) -> usize {
    let n = ring.len();
    let mut count = 0;
    for (k, boundary) in window.boundaries().iter().enumerate() {
        let direction = boundary.to - boundary.from;
        let along = |v: &TaggedVertex| (v.point - boundary.from).dot(direction);
        // Each edge along the boundary becomes (start, end, +1 forwards / -1 backwards).
        let mut events: Vec<(f64, i32, i32)> = Vec::new();
        for i in 0..n {
            let (u, v) = (&ring[i], &ring[(i + 1) % n]);
            if !(u.is_on(k) && v.is_on(k)) || u.point == v.point {
                continue;
            }
            let (a, b) = (along(u), along(v));
            let (lo, hi, forward) = if a < b { (a, b, true) } else { (b, a, false) };
            let (df, db) = if forward { (1, 0) } else { (0, 1) };
            events.push((lo, df, db));
            events.push((hi, -df, -db));
        }
        events.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (mut fwd, mut bwd, mut in_bridge) = (0, 0, false);
        let mut i = 0;
        while i < events.len() {
            let at = events[i].0;
            while i < events.len() && events[i].0 == at {
                fwd += events[i].1;
                bwd += events[i].2;
                i += 1;
            }
            let both = fwd > 0 && bwd > 0;
            if both && !in_bridge {
                count += 1;
            }
            in_bridge = both;
        }
    }
    count
}
