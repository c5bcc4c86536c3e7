//! The curve-line equations: where an ellipse meets an axis-parallel line or a segment.

use core::f64::consts::TAU;

use clip_core::{Ellipse, Point, Rect, Segment};

/// Crossing parameters this far outside a segment's `[0, 1]` still count, so a crossing at a
/// shared window vertex, rounded past the end of both edges, is not lost. An extra breakpoint
/// is harmless (each arc between breakpoints is classified on its own); a missing one is not.
pub const ENDPOINT_SLACK: f64 = 1e-9;

/// An ellipse's coordinates as `x(θ) = cx + hx cos(θ - ax)`, `y(θ) = cy + hy cos(θ - ay)`:
/// solving `x(θ) = k` is then one `acos`.
#[derive(Clone, Copy, Debug)]
pub struct AxisForm {
    center: Point,
    hx: f64,
    ax: f64,
    hy: f64,
    ay: f64,
}

impl AxisForm {
    /// The form of `e`.
    pub fn new(e: &Ellipse) -> AxisForm {
        let (rx, ry) = e.radii();
        let (s, c) = e.rotation().sin_cos();
        // x(θ) = cx + rx c cos θ - ry s sin θ;  y(θ) = cy + rx s cos θ + ry c sin θ.
        let (xa, xb) = (rx * c, -ry * s);
        let (ya, yb) = (rx * s, ry * c);
        AxisForm { center: e.center(), hx: xa.hypot(xb), ax: xb.atan2(xa), hy: ya.hypot(yb), ay: yb.atan2(ya) }
    }

    /// The parameters (in `[0, 2π)`, 0 or 2 of them; a tangent gives two equal ones) where the
    /// ellipse meets the vertical line `x = k`.
    #[inline]
    pub fn vertical(&self, k: f64, out: &mut Vec<f64>) {
        solve(k - self.center.x, self.hx, self.ax, out);
    }

    /// The same for the horizontal line `y = k`.
    #[inline]
    pub fn horizontal(&self, k: f64, out: &mut Vec<f64>) {
        solve(k - self.center.y, self.hy, self.ay, out);
    }
}

#[inline]
fn solve(offset: f64, h: f64, phase: f64, out: &mut Vec<f64>) {
    let c = offset / h;
    if c.abs() <= 1.0 {
        let d = c.acos();
        out.push((phase + d).rem_euclid(TAU));
        out.push((phase - d).rem_euclid(TAU));
    }
}

/// Where the line through segment `s` meets the ellipse: the two roots as parameters `t` of `s`
/// (ascending; equal for a tangent) with the ellipse parameter of each crossing, or `None` when
/// the line misses the ellipse or `s` misses `reach`, a box around the ellipse.
///
/// The segment is first cut to `reach` (Liang-Barsky), so the quadratic is solved on a piece of
/// about the ellipse's size, in the ellipse's unit frame, with the stable root formula: a long
/// edge far from a small ellipse neither overflows nor cancels.
pub fn line_roots(e: &Ellipse, reach: &Rect, s: Segment) -> Option<[(f64, f64); 2]> {
    let (t0, t1) = clip_to_box(s, reach)?;
    let (a, b) = (s.at(t0), s.at(t1));
    let qa = e.to_unit(a);
    let d = e.to_unit(b) - qa;
    let aa = d.dot(d);
    if aa == 0.0 {
        return None;
    }
    let bb = qa.dot(d);
    let cc = qa.dot(qa) - 1.0;
    let disc = bb * bb - aa * cc;
    if disc < 0.0 || disc.is_nan() {
        return None;
    }
    let q = -(bb + disc.sqrt().copysign(bb));
    let (r1, r2) = if q == 0.0 { (0.0, 0.0) } else { (q / aa, cc / q) };
    let (r1, r2) = if r1 <= r2 { (r1, r2) } else { (r2, r1) };
    let root = |r: f64| {
        let p = qa + d * r;
        (t0 + r * (t1 - t0), p.y.atan2(p.x).rem_euclid(TAU))
    };
    Some([root(r1), root(r2)])
}

/// The parameter range of `s` inside the closed box `r`, or `None` when it misses it.
fn clip_to_box(s: Segment, r: &Rect) -> Option<(f64, f64)> {
    let d = s.b - s.a;
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for (p, q) in [(-d.x, s.a.x - r.min.x), (d.x, r.max.x - s.a.x), (-d.y, s.a.y - r.min.y), (d.y, r.max.y - s.a.y)] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                lo = lo.max(t);
            } else {
                hi = hi.min(t);
            }
        }
    }
    (lo <= hi).then_some((lo, hi))
}

/// The box the segment solver cuts edges to: the ellipse's bounding box grown by a hundredth of
/// its long radius, so every crossing lies well inside it.
pub fn reach(e: &Ellipse) -> Rect {
    e.bounds().inflate(0.01 * e.max_radius())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_lines_meet_a_rotated_ellipse_where_its_points_are() {
        let e = Ellipse::new(Point::new(2.0, 1.0), 4.0, 1.5, 0.6).unwrap();
        let f = AxisForm::new(&e);
        let mut out = Vec::new();
        f.vertical(3.0, &mut out);
        f.horizontal(0.0, &mut out);
        assert_eq!(out.len(), 4);
        for (i, &t) in out.iter().enumerate() {
            let p = e.point_at(t);
            let (got, want) = if i < 2 { (p.x, 3.0) } else { (p.y, 0.0) };
            assert!((got - want).abs() < 1e-12, "{got} vs {want}");
        }
        out.clear();
        f.vertical(100.0, &mut out);
        assert!(out.is_empty());
    }

    #[test]
    fn segment_roots_are_on_the_ellipse_and_on_the_segment() {
        let e = Ellipse::new(Point::new(0.0, 0.0), 3.0, 2.0, 0.4).unwrap();
        // A long edge far beyond the ellipse on both sides.
        let s = Segment::new(Point::new(-1e9, 0.5), Point::new(1e9, 0.7));
        let [(t1, a1), (t2, a2)] = line_roots(&e, &reach(&e), s).unwrap();
        assert!(t1 < t2 && t1 > 0.0 && t2 < 1.0);
        for (t, a) in [(t1, a1), (t2, a2)] {
            let p = s.at(t);
            assert!(e.implicit(p).abs() < 1e-6, "{}", e.implicit(p));
            assert!(e.point_at(a).distance(p) < 1e-6);
        }
        assert!(line_roots(&e, &reach(&e), Segment::new(Point::new(10.0, 10.0), Point::new(20.0, 10.0))).is_none());
        assert!(line_roots(&e, &reach(&e), Segment::new(Point::new(-9.0, 5.0), Point::new(9.0, 5.0))).is_none());
    }
}
