//! Where the walk starts: at a point inside the rectangle, so that it always ends.
//!
//! The paper takes the list's first point first. If that point is outside, its previous point
//! (the list's last) is not processed yet, and near a corner the walk can then slide the point
//! towards the corner for ever. Starting inside removes the problem and changes no geometry:
//!
//! 1. the list is rotated to start at a vertex inside the rectangle, if there is one;
//! 2. otherwise at a point where an edge meets the rectangle (exactly decided), inserted there;
//! 3. otherwise no edge meets the rectangle, so inside it the winding number is constant: the
//!    result is the rectangle traced that many times (in the ring's sense), or nothing.

use clip_core::predicates::{SegmentIntersection, segment_intersection};
use clip_core::{Point, Rect, Ring, Segment, ring_winding};

use crate::state::State;

/// How the walk over a ring begins.
pub(crate) enum WalkStart {
    /// Walk this list, whose first point is inside the rectangle.
    From(Vec<Point>),
    /// No edge meets the rectangle; the ring winds this many times around it.
    Enclosed {
        /// The ring's winding number around the rectangle.
        winding: i32,
    },
}

/// True when `p` is inside all four states.
fn inside_rect(p: Point, rect: &Rect) -> bool {
    State::ORDER.iter().all(|s| s.inside(p, rect))
}

/// Chooses the start of the walk over `points`.
pub(crate) fn walk_start(points: &[Point], rect: &Rect) -> WalkStart {
    let n = points.len();
    if let Some(i) = points.iter().position(|&p| inside_rect(p, rect)) {
        let mut list = points.to_vec();
        list.rotate_left(i);
        return WalkStart::From(list);
    }
    let sides = rect.to_ring().edges().collect::<Vec<Segment>>();
    for i in 0..n {
        let edge = Segment::new(points[i], points[(i + 1) % n]);
        if !edge.bounds().intersects(rect) {
            continue;
        }
        for side in &sides {
            let meet = match segment_intersection(edge, *side) {
                SegmentIntersection::None => continue,
                SegmentIntersection::Crossing(p) | SegmentIntersection::Touching(p) => p,
                SegmentIntersection::Overlap(s) => s.a,
            };
            // A rounded crossing is clamped onto the rectangle, so the walk starts inside.
            let start = Point::new(meet.x.clamp(rect.min.x, rect.max.x), meet.y.clamp(rect.min.y, rect.max.y));
            let mut list = Vec::with_capacity(n + 1);
            list.push(start);
            list.extend((1..=n).map(|k| points[(i + k) % n]));
            return WalkStart::From(list);
        }
    }
    // No edge meets the rectangle, so its centre is on no edge and the winding is exact.
    let centre = Point::new(0.5 * (rect.min.x + rect.max.x), 0.5 * (rect.min.y + rect.max.y));
    WalkStart::Enclosed { winding: ring_winding(centre, &Ring::new(points.to_vec())).unwrap_or(0) }
}

/// The rectangle traced `|winding|` times, counter-clockwise for a positive winding.
pub(crate) fn enclosed_rectangle(rect: &Rect, winding: i32) -> Vec<Point> {
    let ring = if winding < 0 { rect.to_ring().reversed() } else { rect.to_ring() };
    ring.points.iter().copied().cycle().take(4 * winding.unsigned_abs() as usize).collect()
}
