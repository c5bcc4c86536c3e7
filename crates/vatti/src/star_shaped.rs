//! A linear-time certificate that a ring is simple: a point it is star-shaped from (every edge
//! turns counter-clockwise around it and the ring goes round it once), found by linear
//! programming over the edges' half-planes (Seidel's randomized incremental algorithm on a
//! sample, grown by the edges its optimum violates, as in Clarkson's scheme, so a big ring is
//! only read in sequence) and then checked exactly.

use clip_core::predicates::{Orientation, orient};
use clip_core::{Point, Rect};

use crate::envelope::sunday;

/// True when the counter-clockwise ring `pts` (no repeated or collinear vertices) is star-shaped
/// from a point found here, so it is simple. `false` says only that no such point was found.
pub(crate) fn certified_simple(pts: &[Point]) -> bool {
    let n = pts.len();
    if n < 3 {
        return false;
    }
    let bounds = Rect::bounding(pts);
    // The mean of the kernel's extreme points in two opposite directions is inside it when it
    // has an interior, unless both lie on one edge's line: then four directions are averaged.
    let dirs = [Point::new(1.0, 0.3), Point::new(-1.0, -0.3), Point::new(-0.3, 1.0), Point::new(0.3, -1.0)];
    let mut sum = Point::ZERO;
    for (k, &dir) in dirs.iter().enumerate() {
        let Some(p) = kernel_extreme(pts, bounds, dir) else { return false };
        sum = Point::new(sum.x + p.x, sum.y + p.y);
        if k == 1 && star_from(pts, Point::new(0.5 * sum.x, 0.5 * sum.y)) {
            return true;
        }
    }
    star_from(pts, Point::new(0.25 * sum.x, 0.25 * sum.y))
}

/// True when every edge of the ring turns counter-clockwise around `k` and the ring goes round
/// it once: then each ray from `k` meets the ring once, so no two edges cross or touch.
fn star_from(pts: &[Point], k: Point) -> bool {
    let n = pts.len();
    let turns = (0..n).all(|i| orient(pts[i], pts[(i + 1) % n], k) == Orientation::CounterClockwise);
    turns && (0..n).map(|i| sunday(pts[i], pts[(i + 1) % n], k)).sum::<i32>() == 1
}

/// Edges in the first sample of the kernel search; each round adds at most four times as many.
const SAMPLE: usize = 1024;

/// An edge's half-plane `a·x <= b` and a point on its line.
struct Plane {
    a: Point,
    b: f64,
    on: Point,
}

impl Plane {
    /// The half-plane left of edge `i` of ring `pts`: `a = (dy, -dx)`, `b = a·p_i`.
    #[inline]
    fn of_edge(pts: &[Point], i: usize) -> Plane {
        let (p, q) = (pts[i], pts[(i + 1) % pts.len()]);
        let a = Point::new(q.y - p.y, p.x - q.x);
        Plane { a, b: a.x * p.x + a.y * p.y, on: p }
    }

    /// True when `x` is outside the half-plane by more than rounding.
    #[inline]
    fn violated_by(&self, x: Point) -> bool {
        let scale = self.a.x.abs().max(self.a.y.abs());
        self.a.x * x.x + self.a.y * x.y > self.b + 1e-12 * scale * (x.x.abs() + x.y.abs() + 1.0)
    }
}

/// The point of the ring's kernel (left of every edge) furthest in direction `dir`, within
/// `bounds`, in floating point (the caller checks the certificate exactly); `None` when the
/// kernel looks empty or the search does not settle. Clarkson's scheme: solve on a sample of
/// the edges, then one pass over all of them adds those the optimum violates, until none does.
fn kernel_extreme(pts: &[Point], bounds: Rect, dir: Point) -> Option<Point> {
    let n = pts.len();
    let mut set: Vec<Plane> = (0..n).step_by(n.div_ceil(SAMPLE)).map(|i| Plane::of_edge(pts, i)).collect();
    let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
    for _ in 0..16 {
        shuffle(&mut set, &mut seed);
        let x = seidel(&set, bounds, dir)?;
        let before = set.len();
        for i in 0..n {
            let plane = Plane::of_edge(pts, i);
            if plane.violated_by(x) {
                set.push(plane);
                if set.len() > before + 4 * SAMPLE {
                    break;
                }
            }
        }
        if set.len() == before {
            return Some(x);
        }
    }
    None
}

/// Seidel's algorithm: the point inside every half-plane of `planes` (taken in their order,
/// which should be random) and `bounds` furthest in direction `dir`; `None` when there is none.
fn seidel(planes: &[Plane], bounds: Rect, dir: Point) -> Option<Point> {
    let mut x = Point::new(
        if dir.x > 0.0 { bounds.max.x } else { bounds.min.x },
        if dir.y > 0.0 { bounds.max.y } else { bounds.min.y },
    );
    for (done, plane) in planes.iter().enumerate() {
        if !plane.violated_by(x) {
            continue;
        }
        let (a, p0) = (plane.a, plane.on);
        // The optimum moves onto this edge's line: a one-dimensional problem along it.
        let u = Point::new(-a.y, a.x);
        let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
        let mut bound = |au: f64, rhs: f64| {
            if au > 0.0 {
                hi = hi.min(rhs / au);
            } else if au < 0.0 {
                lo = lo.max(rhs / au);
            } else if rhs < 0.0 {
                lo = f64::INFINITY;
            }
        };
        bound(u.x, bounds.max.x - p0.x);
        bound(-u.x, p0.x - bounds.min.x);
        bound(u.y, bounds.max.y - p0.y);
        bound(-u.y, p0.y - bounds.min.y);
        for &Plane { a: aj, b: bj, .. } in &planes[..done] {
            bound(aj.x * u.x + aj.y * u.y, bj - (aj.x * p0.x + aj.y * p0.y));
        }
        if lo > hi {
            return None;
        }
        let t = if dir.x * u.x + dir.y * u.y > 0.0 { hi } else { lo };
        x = Point::new(p0.x + t * u.x, p0.y + t * u.y);
    }
    Some(x)
}

/// Shuffles `items` (Fisher-Yates with a xorshift generator: a fixed seed keeps results
/// reproducible, and the expected linear time needs an order the input cannot line up with).
fn shuffle<T>(items: &mut [T], seed: &mut u64) {
    for i in (1..items.len()).rev() {
        *seed ^= *seed << 13;
        *seed ^= *seed >> 7;
        *seed ^= *seed << 17;
        items.swap(i, (*seed % (i as u64 + 1)) as usize);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn stars_are_certified_and_crossing_rings_are_not() {
        let star: Vec<Point> = (0..2000)
            .map(|i| {
                let a = f64::from(i) * std::f64::consts::TAU / 2000.0;
                let r = if i % 2 == 0 { 400.0 } else { 80.0 + f64::from(i % 13) };
                p(500.0 + r * a.cos(), 500.0 + r * a.sin())
            })
            .collect();
        assert!(certified_simple(&star));
        // A bow tie crosses itself; a ring going round twice is not simple either.
        assert!(!certified_simple(&[p(0.0, 0.0), p(2.0, 2.0), p(2.0, 0.0), p(0.0, 2.0)]));
        let twice: Vec<Point> = (0..10)
            .map(|i| {
                let a = f64::from(i) * 2.0 * std::f64::consts::TAU / 10.0;
                p(a.cos(), a.sin())
            })
            .collect();
        assert!(!certified_simple(&twice));
        // Simple but not star-shaped (a spiral): no certificate, the caller sweeps.
        let spiral = [
            p(0.0, 0.0),
            p(10.0, 0.0),
            p(10.0, 10.0),
            p(1.0, 10.0),
            p(1.0, 2.0),
            p(8.0, 2.0),
            p(8.0, 8.0),
            p(0.0, 8.0),
        ];
        assert!(!certified_simple(&spiral));
    }
}
