//! Whether the ray from a segment's start through its end can meet a box: a conservative test, exact where it rejects.

use clip_core::Point;
use clip_core::predicates::ORIENT_ERROR_BOUND;

/// The ray `a + s (b - a)`, `s >= 0`, set up for box tests: for each of the two quantities a
/// box is tested on, the corner where it is largest (or smallest) is chosen once per segment
/// from the signs of `b - a`, so a test is two or three dot products and no branch per corner.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ray {
    a: Point,
    d: Point,
    /// Corner indices into `[min x, min y, max x, max y]`: where the line function
    /// `f(c) = d × (c - a)` is largest, then smallest.
    f_max: (usize, usize),
    f_min: (usize, usize),
    /// Where the progress `g(c) = d · (c - a)` is largest.
    g_max: (usize, usize),
}

impl Ray {
    /// The ray from `a` through `b` (`a != b`).
    #[inline]
    pub fn new(a: Point, b: Point) -> Ray {
        let d = Point::new(b.x - a.x, b.y - a.y);
        let (x_lo, x_hi, y_lo, y_hi) = (0, 2, 1, 3);
        // f grows with c.y when d.x > 0 and shrinks with c.x when d.y > 0.
        let (fy_hi, fy_lo) = if d.x > 0.0 { (y_hi, y_lo) } else { (y_lo, y_hi) };
        let (fx_hi, fx_lo) = if d.y > 0.0 { (x_lo, x_hi) } else { (x_hi, x_lo) };
        let gx = if d.x > 0.0 { x_hi } else { x_lo };
        let gy = if d.y > 0.0 { y_hi } else { y_lo };
        Ray { a, d, f_max: (fx_hi, fy_hi), f_min: (fx_lo, fy_lo), g_max: (gx, gy) }
    }

    /// True only when the ray certainly misses the closed box `[min x, min y, max x, max y]`:
    /// every corner strictly on one side of the line, or strictly behind the start. Each quantity
    /// is one rounded two-product expression of exact coordinates, trusted only beyond Shewchuk's
    /// error bound for such an expression (the bound of `orient2d`'s first stage), so a box the
    /// ray touches is never rejected. A rejected box holds no point of the closed ray.
    #[inline(always)]
    pub fn misses(&self, bounds: &[f64; 4]) -> bool {
        let f = |(ix, iy): (usize, usize)| {
            let l = self.d.x * (bounds[iy] - self.a.y);
            let r = self.d.y * (bounds[ix] - self.a.x);
            (l - r, ORIENT_ERROR_BOUND * (l.abs() + r.abs()))
        };
        let (hi, hi_err) = f(self.f_max);
        let (lo, lo_err) = f(self.f_min);
        let (gx, gy) = self.g_max;
        let p = self.d.x * (bounds[gx] - self.a.x);
        let q = self.d.y * (bounds[gy] - self.a.y);
        let g = p + q;
        let g_err = ORIENT_ERROR_BOUND * (p.abs() + q.abs());
        (hi < -hi_err) | (lo > lo_err) | (g < -g_err)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: [f64; 4] = [0.0, 0.0, 1.0, 1.0];

    #[test]
    fn rejects_boxes_beside_or_behind_the_ray_only() {
        let ray = |ax: f64, ay: f64, bx: f64, by: f64| Ray::new(Point::new(ax, ay), Point::new(bx, by));
        // Passing above, below, and through the box, in all four directions.
        assert!(ray(-1.0, 2.0, 3.0, 1.5).misses(&UNIT));
        assert!(ray(3.0, -0.5, -1.0, -0.1).misses(&UNIT));
        assert!(!ray(-1.0, 0.5, 3.0, 0.5).misses(&UNIT));
        assert!(!ray(3.0, 0.5, -1.0, 0.5).misses(&UNIT));
        assert!(!ray(0.5, -1.0, 0.5, 3.0).misses(&UNIT));
        assert!(!ray(0.5, 3.0, 0.5, -1.0).misses(&UNIT));
        // Through a corner exactly, and along a side: touching counts.
        assert!(!ray(-1.0, 0.0, 0.0, 1.0).misses(&UNIT));
        assert!(!ray(-1.0, 1.0, 5.0, 1.0).misses(&UNIT));
        // Pointing away: behind the start.
        assert!(ray(2.0, 0.5, 3.0, 0.5).misses(&UNIT));
        assert!(ray(0.5, -1.0, 0.5, -2.0).misses(&UNIT));
        // Starting on the far side, pointing away from it: still touching at the start.
        assert!(!ray(1.0, 0.5, 2.0, 0.5).misses(&UNIT));
        // Starting inside: never missed.
        assert!(!ray(0.5, 0.5, 0.6, 0.7).misses(&UNIT));
    }

    #[test]
    fn rays_through_a_corner_from_awkward_starts_keep_the_box() {
        for k in 1..200 {
            let t = f64::from(k) / 7.0;
            let a = Point::new(-t, 1.0 + t / 3.0);
            // Ends exactly at the corner (0, 1), or a third of the way past it (rounded).
            assert!(!Ray::new(a, Point::new(0.0, 1.0)).misses(&UNIT), "{a:?}");
            let past = Point::new(t / 3.0, 1.0 - t / 9.0);
            let r = Ray::new(a, past);
            let exact = clip_core::predicates::orient2d(a, past, Point::new(0.0, 1.0));
            if exact == 0.0 {
                assert!(!r.misses(&UNIT));
            }
        }
    }
}
