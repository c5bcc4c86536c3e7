//! Whether the ray from a segment's start through its end can meet a box: a conservative test, exact where it rejects.

use clip_core::predicates::ORIENT_ERROR_BOUND;
use clip_core::{Point, Rect};

use crate::edge_tree::{MAX_X, MIN_X, MIN_Y, Node, WAYS};

/// The ray `a + s (b - a)`, `s >= 0`, set up for box tests: the corner of a box where each tested
/// quantity is largest (or smallest) depends only on the signs of `b - a`, so which of a box's
/// bounds to read is chosen once per segment, and a node's four child boxes are then tested with
/// the same straight-line arithmetic, one corner per quantity.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ray {
    a: Point,
    /// The segment's other end (exact), for [`Ray::within_span`].
    b: Point,
    d: Point,
    /// Error bounds of the line function and of the projection on `d` at any point of the window's
    /// bounding box (every box tested lies in it).
    line_error: f64,
    ahead_error: f64,
    /// The error bound of the projection on `d` measured from `b`.
    before_end_error: f64,
    /// Rows of a node's sides at the corners where the line function is highest (`y_high`,
    /// `x_low`) and lowest, and where the projection on `d` is largest (`x_far`, `y_far`): from the
    /// signs of `d`, which are the exact ones.
    y_high: usize,
    x_low: usize,
    x_far: usize,
    y_far: usize,
}

impl Ray {
    /// The ray from `a` through `b` (`a != b`), for boxes inside `bounds`.
    #[inline]
    pub fn new(a: Point, b: Point, bounds: &Rect) -> Ray {
        let d = Point::new(b.x - a.x, b.y - a.y);
        // The largest rounded |x - a.x| and |y - a.y| over the box: rounding is monotone, so no
        // rounded product at a point of the box exceeds the one formed from these.
        let far_x = (bounds.max.x - a.x).abs().max((bounds.min.x - a.x).abs());
        let far_y = (bounds.max.y - a.y).abs().max((bounds.min.y - a.y).abs());
        let far_x_b = (bounds.max.x - b.x).abs().max((bounds.min.x - b.x).abs());
        let far_y_b = (bounds.max.y - b.y).abs().max((bounds.min.y - b.y).abs());
        // Chosen by arithmetic: a branch here mispredicts on half of a batch of random segments.
        let (x_up, y_up) = (usize::from(d.x >= 0.0), usize::from(d.y >= 0.0));
        Ray {
            a,
            b,
            d,
            line_error: ORIENT_ERROR_BOUND * (d.x.abs() * far_y + d.y.abs() * far_x),
            ahead_error: ORIENT_ERROR_BOUND * (d.x.abs() * far_x + d.y.abs() * far_y),
            before_end_error: ORIENT_ERROR_BOUND * (d.x.abs() * far_x_b + d.y.abs() * far_y_b),
            y_high: MIN_Y + 2 * x_up,
            x_low: MAX_X - 2 * y_up,
            x_far: MIN_X + 2 * x_up,
            y_far: MIN_Y + 2 * y_up,
        }
    }

    /// Bit `i` set unless the ray certainly misses child box `i` of `node`: every corner strictly
    /// on one side of the line, or strictly behind the start. Each quantity is one rounded
    /// two-product expression of exact coordinates at the corner where it is extreme, trusted only
    /// beyond Shewchuk's error bound for such an expression (the bound of `orient2d`'s first
    /// stage, taken once for the whole bounding box), so a box the ray touches is never missed.
    /// Unused slots are not masked here.
    #[inline(always)]
    pub fn hits(&self, node: &Node) -> u32 {
        // f(c) = d.x (c.y - a.y) - d.y (c.x - a.x) is largest at the corner with the larger y when
        // d.x >= 0 and the smaller x when d.y >= 0, smallest at the opposite corner (the signs of
        // the rounded d are the exact ones); d . (c - a) is largest at the far corner.
        // The opposite row of a side is two rows on (mod 4); `& 3` lets the compiler drop the
        // bounds checks.
        let (y_high, y_low) = (&node.sides[self.y_high & 3], &node.sides[(self.y_high + 2) & 3]);
        let (x_low, x_high) = (&node.sides[self.x_low & 3], &node.sides[(self.x_low + 2) & 3]);
        let (x_far, y_far) = (&node.sides[self.x_far & 3], &node.sides[self.y_far & 3]);
        // Child by child in lanes (the children side by side vectorise), the bits packed after.
        let mut keep = [0u32; WAYS];
        for (i, keep) in keep.iter_mut().enumerate() {
            let highest = self.d.x * (y_high[i] - self.a.y) - self.d.y * (x_low[i] - self.a.x);
            let lowest = self.d.x * (y_low[i] - self.a.y) - self.d.y * (x_high[i] - self.a.x);
            let farthest = self.d.x * (x_far[i] - self.a.x) + self.d.y * (y_far[i] - self.a.y);
            // As differences that must not be positive (see `segment_hits`): the line meets the
            // box, and its far corner is not behind the start.
            let line = larger(-self.line_error - highest, lowest - self.line_error);
            *keep = u32::from(larger(line, -self.ahead_error - farthest) <= 0.0);
        }
        keep[0] | (keep[1] << 1) | (keep[2] << 2) | (keep[3] << 3)
    }

    /// Bit `i` set unless the closed segment certainly misses child box `i` of `node`: every
    /// corner strictly on one side of its line (as in [`Ray::hits`]), or the box apart from
    /// `segment`, the segment's own box. Both tests child by child in lanes, one mask.
    #[inline(always)]
    pub fn segment_hits(&self, node: &Node, segment: &Rect) -> u32 {
        let (y_high, y_low) = (&node.sides[self.y_high & 3], &node.sides[(self.y_high + 2) & 3]);
        let (x_low, x_high) = (&node.sides[self.x_low & 3], &node.sides[(self.x_low + 2) & 3]);
        let [min_x, min_y, max_x, max_y] = &node.sides;
        let mut keep = [0u32; WAYS];
        for (i, keep) in keep.iter_mut().enumerate() {
            let highest = self.d.x * (y_high[i] - self.a.y) - self.d.y * (x_low[i] - self.a.x);
            let lowest = self.d.x * (y_low[i] - self.a.y) - self.d.y * (x_high[i] - self.a.x);
            // The six tests as differences that must not be positive, decided by their largest:
            // the rounded difference of two finite values has the sign of the exact one, and
            // `max` chains vectorise where six comparisons and their `&` did not.
            let line = larger(-self.line_error - highest, lowest - self.line_error);
            let across = larger(min_x[i] - segment.max.x, segment.min.x - max_x[i]);
            let along = larger(min_y[i] - segment.max.y, segment.min.y - max_y[i]);
            *keep = u32::from(larger(line, larger(across, along)) <= 0.0);
        }
        keep[0] | (keep[1] << 1) | (keep[2] << 2) | (keep[3] << 3)
    }

    /// True when child box `i` of `node` lies strictly between the perpendiculars to the segment
    /// at its ends: every point `c` of it has `d . (c - a) > 0` and `d . (c - b) < 0`, each decided
    /// at the box's extreme corner beyond the error bound, so exactly. Every crossing of the line
    /// with an edge in that box is then inside the segment.
    #[inline(always)]
    pub fn within_span(&self, node: &Node, i: usize) -> bool {
        let (x_far, y_far) = (node.sides[self.x_far & 3][i], node.sides[self.y_far & 3][i]);
        let (x_near, y_near) = (node.sides[(self.x_far + 2) & 3][i], node.sides[(self.y_far + 2) & 3][i]);
        let nearest = self.d.x * (x_near - self.a.x) + self.d.y * (y_near - self.a.y);
        let farthest = self.d.x * (x_far - self.b.x) + self.d.y * (y_far - self.b.y);
        (nearest > self.ahead_error) & (farthest < -self.before_end_error)
    }
}

/// The larger of two values, as one `max` instruction (`f64::max` also orders NaN, which costs
/// more; a NaN here only comes from an unused slot's infinite box, which the caller masks off).
#[inline(always)]
fn larger(a: f64, b: f64) -> f64 {
    if a > b { a } else { b }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A node whose every slot holds the unit box.
    fn unit() -> Node {
        Node { sides: [[0.0; WAYS], [0.0; WAYS], [1.0; WAYS], [1.0; WAYS]] }
    }

    fn misses(ax: f64, ay: f64, bx: f64, by: f64) -> bool {
        let bounds = Rect::new(0.0, 0.0, 1.0, 1.0);
        Ray::new(Point::new(ax, ay), Point::new(bx, by), &bounds).hits(&unit()) & 1 == 0
    }

    #[test]
    fn boxes_within_the_span_only_when_strictly_between_the_ends() {
        let bounds = Rect::new(0.0, 0.0, 1.0, 1.0);
        let within = |ax: f64, ay: f64, bx: f64, by: f64| {
            Ray::new(Point::new(ax, ay), Point::new(bx, by), &bounds).within_span(&unit(), 3)
        };
        // Across the box, either way and slanted: strictly between the ends.
        assert!(within(-1.0, 0.5, 2.0, 0.5));
        assert!(within(2.0, 0.5, -1.0, 0.5));
        assert!(within(-1.0, -2.0, 2.0, 3.0));
        // An end on the box's side, at its corner, or inside it: not strictly between.
        assert!(!within(0.0, 0.5, 2.0, 0.5));
        assert!(!within(-1.0, 0.5, 1.0, 0.5));
        assert!(!within(-1.0, -1.0, 1.0, 1.0));
        assert!(!within(0.5, 0.5, 2.0, 0.5));
        // The perpendicular at the start through the corner (0, 0) exactly, and just past it.
        assert!(!within(-1.0, 1.0, 1.0, 3.0));
        assert!(within(-1.0, 0.9, 1.0, 2.9));
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
