//! Whether the ray from a segment's start through its end can meet a box: a conservative test, exact where it rejects.

use clip_core::Point;
use clip_core::predicates::ORIENT_ERROR_BOUND;

use crate::edge_tree::{Node, WAYS};

/// The ray `a + s (b - a)`, `s >= 0`, set up for box tests: the corner of a box where each tested
/// quantity is largest (or smallest) depends only on the signs of `b - a`, so it is chosen once per
/// segment, and a node's four child boxes are then tested with the same straight-line arithmetic.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ray {
    a: Point,
    d: Point,
}

impl Ray {
    /// The ray from `a` through `b` (`a != b`).
    #[inline]
    pub fn new(a: Point, b: Point) -> Ray {
        Ray { a, d: Point::new(b.x - a.x, b.y - a.y) }
    }

    /// Bit `i` set unless the ray certainly misses child box `i` of `node`: every corner strictly
    /// on one side of the line, or strictly behind the start. Each quantity is one rounded
    /// two-product expression of exact coordinates, trusted only beyond Shewchuk's error bound for
    /// such an expression (the bound of `orient2d`'s first stage), so a box the ray touches is never
    /// missed. Unused slots are not masked here.
    #[inline(always)]
    pub fn hits(&self, node: &Node) -> u32 {
        let ahead = self.ahead(node);
        self.line_hits(node) & ahead
    }

    /// As [`Ray::hits`] for the whole line: bit `i` set unless every corner of box `i` lies
    /// strictly on one side of it.
    #[inline(always)]
    pub fn line_hits(&self, node: &Node) -> u32 {
        // f(c) = l - r with l = d.x (c.y - a.y), r = d.y (c.x - a.x): its largest value over the
        // corners takes the larger l and the smaller r, its smallest the reverse. Taken with
        // min and max of the two candidates (the same products a choice of corner by the signs
        // of d would pick), so the direction costs no branch.
        let mut mask = 0;
        for i in 0..WAYS {
            let (l1, l2) = (self.d.x * (node.max_y[i] - self.a.y), self.d.x * (node.min_y[i] - self.a.y));
            let (r1, r2) = (self.d.y * (node.min_x[i] - self.a.x), self.d.y * (node.max_x[i] - self.a.x));
            let (l, r) = (l1.max(l2), r1.min(r2));
            let below = l - r < -(ORIENT_ERROR_BOUND * (l.abs() + r.abs()));
            let (l, r) = (l1.min(l2), r1.max(r2));
            let above = l - r > ORIENT_ERROR_BOUND * (l.abs() + r.abs());
            mask |= u32::from(!(below | above)) << i;
        }
        mask
    }

    /// Bit `i` set unless box `i` lies strictly behind the start: its corner farthest along the
    /// ray has `d . (c - a) < 0`, beyond the same error bound.
    #[inline(always)]
    fn ahead(&self, node: &Node) -> u32 {
        // The corner farthest along the ray: the larger of the two products per axis.
        let mut mask = 0;
        for i in 0..WAYS {
            let p = (self.d.x * (node.max_x[i] - self.a.x)).max(self.d.x * (node.min_x[i] - self.a.x));
            let q = (self.d.y * (node.max_y[i] - self.a.y)).max(self.d.y * (node.min_y[i] - self.a.y));
            let behind = p + q < -(ORIENT_ERROR_BOUND * (p.abs() + q.abs()));
            mask |= u32::from(!behind) << i;
        }
        mask
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A node whose only child is the unit box.
    fn unit() -> Node {
        Node {
            min_x: [0.0; WAYS],
            min_y: [0.0; WAYS],
            max_x: [1.0; WAYS],
            max_y: [1.0; WAYS],
            child: [0; WAYS],
            leaves: 1,
            present: 1,
        }
    }

    fn misses(ax: f64, ay: f64, bx: f64, by: f64) -> bool {
        Ray::new(Point::new(ax, ay), Point::new(bx, by)).hits(&unit()) & 1 == 0
    }

    #[test]
    fn rejects_boxes_beside_or_behind_the_ray_only() {
        // Passing above, below, and through the box, in all four directions.
        assert!(misses(-1.0, 2.0, 3.0, 1.5));
        assert!(misses(3.0, -0.5, -1.0, -0.1));
        assert!(!misses(-1.0, 0.5, 3.0, 0.5));
        assert!(!misses(3.0, 0.5, -1.0, 0.5));
        assert!(!misses(0.5, -1.0, 0.5, 3.0));
        assert!(!misses(0.5, 3.0, 0.5, -1.0));
        // Through a corner exactly, and along a side: touching counts.
        assert!(!misses(-1.0, 0.0, 0.0, 1.0));
        assert!(!misses(-1.0, 1.0, 5.0, 1.0));
        // Pointing away: behind the start.
        assert!(misses(2.0, 0.5, 3.0, 0.5));
        assert!(misses(0.5, -1.0, 0.5, -2.0));
        // Starting on the far side, pointing away from it: still touching at the start.
        assert!(!misses(1.0, 0.5, 2.0, 0.5));
        // Starting inside: never missed.
        assert!(!misses(0.5, 0.5, 0.6, 0.7));
    }

    #[test]
    fn rays_through_a_corner_from_awkward_starts_keep_the_box() {
        for k in 1..200 {
            let t = f64::from(k) / 7.0;
            // Ends exactly at the corner (0, 1).
            assert!(!misses(-t, 1.0 + t / 3.0, 0.0, 1.0), "{t}");
            // Through the corner only if the exact predicate says so; kept then.
            let (a, past) = (Point::new(-t, 1.0 + t / 3.0), Point::new(t / 3.0, 1.0 - t / 9.0));
            if clip_core::predicates::orient2d(a, past, Point::new(0.0, 1.0)) == 0.0 {
                assert!(!misses(a.x, a.y, past.x, past.y));
            }
        }
    }
}
