//! The 45° rotated virtual box of Lu et al. 2002: the window's bounding box in `u = x + y`, `v = x - y`.

use clip_core::Point;

/// The window's bounding box in the rotated coordinates `u = x + y`, `v = x - y` (the paper's
/// Fig. 3), coded like Cohen-Sutherland's. It rejects segments that cross a corner region of the
/// MEB without touching the window's rotated box.
///
/// Exact although `u` and `v` are rounded: rounding to nearest is monotone, so
/// `fl(u_p) > max_w fl(u_w)` implies `u_p > u_w` for every window vertex `w`; the strict
/// comparisons below only ever reject segments that truly lie beyond the box.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RotatedBox {
    u_min: f64,
    u_max: f64,
    v_min: f64,
    v_max: f64,
}

impl RotatedBox {
    /// The rotated box of some vertices.
    pub fn new<'a>(points: impl IntoIterator<Item = &'a Point>) -> RotatedBox {
        let empty = RotatedBox {
            u_min: f64::INFINITY,
            u_max: f64::NEG_INFINITY,
            v_min: f64::INFINITY,
            v_max: f64::NEG_INFINITY,
        };
        points.into_iter().fold(empty, |r, p| {
            let (u, v) = (p.x + p.y, p.x - p.y);
            RotatedBox { u_min: r.u_min.min(u), u_max: r.u_max.max(u), v_min: r.v_min.min(v), v_max: r.v_max.max(v) }
        })
    }

    /// True when both ends lie strictly beyond the same side of the rotated box: Cohen-Sutherland's
    /// common outcode bit, read as the nearer end beyond that side (no branch).
    #[inline]
    pub fn rejects(&self, a: Point, b: Point) -> bool {
        let (ua, ub, va, vb) = (a.x + a.y, b.x + b.y, a.x - a.y, b.x - b.y);
        (ua.max(ub) < self.u_min) | (ua.min(ub) > self.u_max) | (va.max(vb) < self.v_min) | (va.min(vb) > self.v_max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_only_beyond_one_rotated_side() {
        // The diamond |x| + |y| <= 1 is its own rotated box.
        let diamond = [Point::new(1.0, 0.0), Point::new(0.0, 1.0), Point::new(-1.0, 0.0), Point::new(0.0, -1.0)];
        let r = RotatedBox::new(&diamond);
        // Across the MEB's corner region near (1,1), beyond u = 1.
        assert!(r.rejects(Point::new(1.0, 0.5), Point::new(0.5, 1.0)));
        // Touching the diamond's edge at (0.5, 0.5): not rejected.
        assert!(!r.rejects(Point::new(1.0, 0.0), Point::new(0.5, 0.5)));
        // Beyond different sides: not rejected (the segment may cross).
        assert!(!r.rejects(Point::new(1.0, 1.0), Point::new(-1.0, -1.0)));
    }
}
