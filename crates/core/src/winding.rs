//! Exact winding numbers and point location under a fill rule.

use crate::predicates::{Orientation, on_segment, orient};
use crate::{FillRule, Point, Polygons, Ring, Segment};

/// Where a point lies relative to a region.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Location {
    /// In the interior.
    Inside,
    /// On an edge of some ring (whether or not that edge bounds the filled region).
    Boundary,
    /// In the exterior.
    Outside,
}

/// The winding number of `ring` around `p`, or `None` when `p` lies on one of its edges.
/// Counter-clockwise loops count +1. Exact (Sunday's crossing rule with exact orientation).
pub fn ring_winding(p: Point, ring: &Ring) -> Option<i32> {
    let pts = &ring.points;
    let Some(&last) = pts.last() else { return Some(0) };
    let mut w = 0;
    let mut prev = last;
    for &b in pts {
        let a = std::mem::replace(&mut prev, b);
        // Wholly above or below p: neither through p nor crossing its ray (the common case,
        // decided before the box and orientation tests).
        if (a.y > p.y && b.y > p.y) || (a.y < p.y && b.y < p.y) {
            continue;
        }
        w += edge_winding(p, a, b)?;
    }
    Some(w)
}

/// What the edge from `a` to `b` adds to a ring's winding number around `p` (+1 where it
/// crosses the rightward ray from `p` upwards, −1 downwards, else 0), or `None` when `p` lies on
/// it: one step of [`ring_winding`], for callers that visit edges in another order (a pass of
/// many points sorted by y). Exact.
#[inline]
pub fn edge_winding(p: Point, a: Point, b: Point) -> Option<i32> {
    if on_segment(p, Segment::new(a, b)) {
        return None;
    }
    Some(if a.y <= p.y {
        i32::from(b.y > p.y && orient(a, b, p) == Orientation::CounterClockwise)
    } else {
        -i32::from(b.y <= p.y && orient(a, b, p) == Orientation::Clockwise)
    })
}

/// The total winding number of all rings around `p`, or `None` when `p` is on an edge.
pub fn winding_number(p: Point, polygons: &Polygons) -> Option<i32> {
    polygons.rings.iter().try_fold(0, |w, r| ring_winding(p, r).map(|rw| w + rw))
}

/// Where `p` lies relative to the region `polygons` covers under `fill`.
///
/// A point on any ring's edge is [`Location::Boundary`], even where that edge does not bound the
/// filled region (two coincident opposite edges, say): the oracles leave such points alone.
pub fn locate(p: Point, polygons: &Polygons, fill: FillRule) -> Location {
    match winding_number(p, polygons) {
        None => Location::Boundary,
        Some(w) if fill.is_inside(w) => Location::Inside,
        Some(_) => Location::Outside,
    }
}
