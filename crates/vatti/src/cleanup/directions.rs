//! Exact orders of the directions leaving one point, by which the clean-up's walks choose where
//! to turn: clockwise from a way back (the rebuild) and counter-clockwise from east (the planned
//! turns). Only orientation tests and comparisons of input coordinates: nothing is rounded.

use std::cmp::Ordering;

use clip_core::Point;
use clip_core::predicates::{Orientation, orient};

/// Sector of direction `v -> w` measured clockwise from `v -> r`: 0 for (0, pi), 1 at pi,
/// 2 for (pi, 2pi), 3 when it points back along `v -> r` (a full turn).
#[inline]
pub(crate) fn sector(v: Point, r: Point, w: Point) -> u8 {
    match orient(v, r, w) {
        Orientation::Clockwise => 0,
        Orientation::CounterClockwise => 2,
        Orientation::Collinear => {
            // Collinear through v: same direction when on the same side of v (exact compares).
            let same = if r.x != v.x { (w.x > v.x) == (r.x > v.x) } else { (w.y > v.y) == (r.y > v.y) };
            if same { 3 } else { 1 }
        }
    }
}

/// True when `v -> w1` comes strictly before `v -> w2` turning clockwise from `v -> r`.
#[inline]
pub(crate) fn clockwise_before(v: Point, r: Point, w1: Point, w2: Point) -> bool {
    let (s1, s2) = (sector(v, r, w1), sector(v, r, w2));
    if s1 != s2 {
        return s1 < s2;
    }
    if s1 == 0 || s1 == 2 { orient(v, w1, w2) == Orientation::Clockwise } else { false }
}

/// Orders directions from `v` to `a` and `b` counter-clockwise from east (the direction of +x
/// first); `Equal` for one direction.
#[inline]
pub(crate) fn counter_clockwise_from_east(v: Point, a: Point, b: Point) -> Ordering {
    let lower = |p: Point| p.y < v.y || (p.y == v.y && p.x < v.x);
    match (lower(a), lower(b)) {
        (false, true) => Ordering::Less,
        (true, false) => Ordering::Greater,
        _ => match orient(v, a, b) {
            Orientation::CounterClockwise => Ordering::Less,
            Orientation::Clockwise => Ordering::Greater,
            Orientation::Collinear => Ordering::Equal,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_orders_agree_on_the_directions_around_a_point() {
        let v = Point::new(0.0, 0.0);
        // Counter-clockwise from east, every quadrant and axis.
        let around: Vec<Point> =
            [(1.0, 0.0), (2.0, 1.0), (0.0, 1.0), (-1.0, 1.0), (-1.0, 0.0), (-1.0, -3.0), (0.0, -1.0), (1.0, -1.0)]
                .into_iter()
                .map(|(x, y)| Point::new(x, y))
                .collect();
        for (i, &a) in around.iter().enumerate() {
            for (j, &b) in around.iter().enumerate() {
                assert_eq!(counter_clockwise_from_east(v, a, b), i.cmp(&j), "{a:?} {b:?}");
                // Clockwise from east is counter-clockwise from east reversed, east itself last.
                let east = around[0];
                if i != 0 && j != 0 {
                    assert_eq!(clockwise_before(v, east, a, b), j < i, "{a:?} {b:?}");
                }
            }
        }
        // Twice as far is the same way; the opposite direction is half a turn.
        let (e, e2, w) = (Point::new(1.0, 0.0), Point::new(2.0, 0.0), Point::new(-1.0, 0.0));
        assert_eq!(counter_clockwise_from_east(v, e, e2), Ordering::Equal);
        assert_eq!(sector(v, e, w), 1);
        assert_eq!(sector(v, e, e2), 3);
    }
}
