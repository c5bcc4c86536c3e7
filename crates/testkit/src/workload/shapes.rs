//! The ring shapes workloads are built from: stars, scribbles, smooth blobs, convex polygons,
//! checkerboards and integer-grid rings.

use clip_core::predicates::{Orientation, orient};
use clip_core::{Point, Rect, Ring};
use rand::Rng;
use rand_pcg::Pcg64;
use std::f64::consts::TAU;

/// `n` strictly increasing angles over one turn from a random phase; every gap is at least a
/// fifth of the mean gap, so stars built on them stay simple.
pub(crate) fn sorted_angles(rng: &mut Pcg64, n: usize) -> Vec<f64> {
    let phase = rng.random::<f64>() * TAU;
    let step = TAU / n as f64;
    (0..n).map(|i| phase + (i as f64 + 0.8 * rng.random::<f64>()) * step).collect()
}

/// A star-shaped ring around `center` (counter-clockwise): vertex `i` at a sorted angle and a
/// radius drawn from `[inner, 1]`, stretched by `rx` and `ry`. Concave for most draws, never
/// self-intersecting.
pub(crate) fn star(rng: &mut Pcg64, n: usize, center: Point, rx: f64, ry: f64, inner: f64) -> Ring {
    let n = n.max(3);
    let angles = sorted_angles(rng, n);
    let points = angles
        .iter()
        .map(|&a| {
            let r = inner + (1.0 - inner) * rng.random::<f64>();
            Point::new(center.x + rx * r * a.cos(), center.y + ry * r * a.sin())
        })
        .collect();
    Ring::new(points)
}

/// `n` vertices uniform in `bounds`: a ring that crosses itself many times.
pub(crate) fn scribble(rng: &mut Pcg64, n: usize, bounds: Rect) -> Ring {
    let points = (0..n.max(3))
        .map(|_| {
            Point::new(
                bounds.min.x + rng.random::<f64>() * bounds.width(),
                bounds.min.y + rng.random::<f64>() * bounds.height(),
            )
        })
        .collect();
    Ring::new(points)
}

/// A smooth star-shaped blob of `n` equally spaced vertices: a circle of `radius` perturbed by
/// a few low harmonics (total amplitude below 0.35, so the radius stays positive).
pub(crate) fn smooth(rng: &mut Pcg64, n: usize, center: Point, radius: f64) -> Ring {
    let harmonics: Vec<(f64, f64, f64)> =
        (2..6).map(|k| (k as f64, 0.08 * rng.random::<f64>(), rng.random::<f64>() * TAU)).collect();
    let n = n.max(3);
    let points = (0..n)
        .map(|i| {
            let a = TAU * i as f64 / n as f64;
            let r = radius * (1.0 + harmonics.iter().map(|&(k, amp, ph)| amp * (k * a + ph).cos()).sum::<f64>());
            Point::new(center.x + r * a.cos(), center.y + r * a.sin())
        })
        .collect();
    Ring::new(points)
}

/// A lobed star of `n` vertices around `center` (counter-clockwise): a flower of `lobes` petals,
/// the radius dipping to `1 - depth` of `radius` between petals, sampled at `n` sorted angles and
/// jittered by at most 1% of the radius and a fifth of the mean gap between vertices (so the
/// boundary does not zig-zag at large `n`). Concave for `lobes >= 3` and never self-intersecting;
/// unlike [`star`], a line crosses it about `2 lobes` times at most whatever `n` is, so it models
/// a large window with a detailed boundary (a coastline, a district) rather than a spiky one.
pub(crate) fn lobed(rng: &mut Pcg64, n: usize, center: Point, radius: f64, lobes: f64, depth: f64) -> Ring {
    let phase = rng.random::<f64>() * TAU;
    let jitter = 0.01f64.min(0.2 * TAU / n.max(3) as f64);
    let points = sorted_angles(rng, n.max(3))
        .iter()
        .map(|&a| {
            let petal = 0.5 + 0.5 * (lobes * a + phase).cos();
            let r = radius * (1.0 - depth * (1.0 - petal)) * (1.0 + jitter * (rng.random::<f64>() - 0.5));
            Point::new(center.x + r * a.cos(), center.y + r * a.sin())
        })
        .collect();
    Ring::new(points)
}

/// A strictly convex ring of `n` vertices on an ellipse of half-axes `rx`, `ry` turned by a
/// random angle, counter-clockwise. Falls back to fewer vertices if rounding ever makes three
/// of them collinear (checked exactly).
pub(crate) fn convex(rng: &mut Pcg64, n: usize, center: Point, rx: f64, ry: f64) -> Ring {
    let turn = rng.random::<f64>() * TAU;
    let (sin, cos) = turn.sin_cos();
    let mut n = n.max(3);
    loop {
        let points: Vec<Point> = sorted_angles(rng, n)
            .iter()
            .map(|&a| {
                let (x, y) = (rx * a.cos(), ry * a.sin());
                Point::new(center.x + x * cos - y * sin, center.y + x * sin + y * cos)
            })
            .collect();
        let ring = Ring::new(points);
        if ring.convex_orientation() == Some(Orientation::CounterClockwise) || n == 3 {
            return ring;
        }
        n = (n - 1).max(3);
    }
}

/// The cells `(i + j)` even of a `k` x `k` board of square cells of side `cell` from `origin`,
/// each a counter-clockwise square; neighbouring squares touch at their corners.
pub(crate) fn checkerboard(k: usize, cell: f64, origin: Point) -> Vec<Ring> {
    let mut rings = Vec::with_capacity(k * k / 2 + 1);
    for i in 0..k {
        for j in 0..k {
            if (i + j).is_multiple_of(2) {
                // Each corner from its own grid index, so neighbours share corners exactly.
                let at = |k: usize, o: f64| o + k as f64 * cell;
                rings.push(
                    Rect::new(at(i, origin.x), at(j, origin.y), at(i + 1, origin.x), at(j + 1, origin.y)).to_ring(),
                );
            }
        }
    }
    rings
}

/// A ring of about `n` vertices on the integer grid `[0, g]²`, of a random kind: random grid
/// points (self-intersecting, collinear and shared vertices), a rectilinear histogram
/// (horizontal edges, collinear vertices), or a star rounded to the grid; sometimes with a
/// zero-width spike, sometimes reversed.
pub(crate) fn grid_ring(rng: &mut Pcg64, n: usize, g: i32) -> Ring {
    let n = n.max(3);
    let mut points = match rng.random_range(0..3) {
        0 => grid_scribble(rng, n, g),
        1 => histogram(rng, n, g),
        _ => {
            let c = Point::new(f64::from(g) / 2.0, f64::from(g) / 2.0);
            let r = f64::from(g) / 2.0;
            let s = star(rng, n, c, r, r, 0.3);
            s.points.iter().map(|p| Point::new(p.x.round(), p.y.round())).collect()
        }
    };
    dedup_consecutive(&mut points);
    if points.len() >= 3 && rng.random_bool(0.3) {
        // A spike: out to a grid point and straight back.
        let at = rng.random_range(0..points.len());
        let tip = grid_point(rng, g);
        if tip != points[at] && tip != points[(at + 1) % points.len()] {
            points.splice(at + 1..at + 1, [tip, points[at]]);
        }
    }
    if rng.random_bool(0.5) {
        points.reverse();
    }
    if Ring::new(points.clone()).distinct_points() < 3 {
        // Rare: everything rounded onto one or two points. Use a grid triangle instead.
        points = vec![Point::new(0.0, 0.0), Point::new(f64::from(g), 0.0), Point::new(0.0, f64::from(g))];
    }
    Ring::new(points)
}

fn grid_point(rng: &mut Pcg64, g: i32) -> Point {
    Point::new(f64::from(rng.random_range(0..=g)), f64::from(rng.random_range(0..=g)))
}

fn grid_scribble(rng: &mut Pcg64, n: usize, g: i32) -> Vec<Point> {
    let mut points: Vec<Point> = Vec::with_capacity(n);
    while points.len() < n {
        let p = grid_point(rng, g);
        if points.last() != Some(&p) {
            points.push(p);
        }
    }
    points
}

/// A rectilinear "histogram": a flat bottom and columns of random heights, `2 + 2m` vertices.
fn histogram(rng: &mut Pcg64, n: usize, g: i32) -> Vec<Point> {
    let columns = ((n.saturating_sub(2)) / 2).clamp(1, g.max(1) as usize);
    let x0 = rng.random_range(0..=(g - columns as i32).max(0));
    let base = rng.random_range(0..g.max(1));
    let heights: Vec<i32> = (0..columns).map(|_| rng.random_range(base + 1..=g.max(base + 1))).collect();
    let mut points =
        vec![Point::new(f64::from(x0), f64::from(base)), Point::new(f64::from(x0 + columns as i32), f64::from(base))];
    for j in (1..=columns).rev() {
        let h = f64::from(heights[j - 1]);
        points.push(Point::new(f64::from(x0 + j as i32), h));
        points.push(Point::new(f64::from(x0 + j as i32 - 1), h));
    }
    points
}

/// Removes consecutive repeated vertices, the closing pair included.
pub(crate) fn dedup_consecutive(points: &mut Vec<Point>) {
    points.dedup();
    while points.len() > 1 && points.first() == points.last() {
        points.pop();
    }
}

/// The convex hull of some points, counter-clockwise, collinear points dropped (Andrew's
/// monotone chain with exact orientation). Fewer than 3 points when they are all collinear.
pub fn convex_hull(points: &[Point]) -> Vec<Point> {
    let mut pts = points.to_vec();
    pts.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    pts.dedup();
    if pts.len() < 3 {
        return pts;
    }
    let mut hull: Vec<Point> = Vec::with_capacity(pts.len() * 2);
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &Point>> =
            if pass == 0 { Box::new(pts.iter()) } else { Box::new(pts.iter().rev()) };
        for &p in iter {
            while hull.len() >= start + 2
                && orient(hull[hull.len() - 2], hull[hull.len() - 1], p) != Orientation::CounterClockwise
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// Edge counts from 6 to 200, log-uniform so small cases (quick to check and to read) are common.
pub(crate) fn edge_count(rng: &mut Pcg64) -> usize {
    let (lo, hi) = (6f64.ln(), 200f64.ln());
    ((lo + (hi - lo) * rng.random::<f64>()).exp().round() as usize).clamp(6, 200)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn hull_of_square_with_inner_and_collinear_points() {
        let pts: Vec<Point> =
            [(0.0, 0.0), (2.0, 0.0), (1.0, 0.0), (2.0, 2.0), (0.0, 2.0), (1.0, 1.0)].map(Point::from).to_vec();
        let hull = convex_hull(&pts);
        assert_eq!(hull.len(), 4);
        assert_eq!(Ring::new(hull).convex_orientation(), Some(Orientation::CounterClockwise));
    }

    #[test]
    fn stars_are_counter_clockwise_and_convex_rings_convex() {
        let mut rng = Pcg64::seed_from_u64(7);
        for n in [3, 4, 10, 50] {
            assert!(star(&mut rng, n, Point::ZERO, 10.0, 5.0, 0.2).signed_area() > 0.0);
            let c = convex(&mut rng, n, Point::ZERO, 10.0, 5.0);
            assert_eq!(c.convex_orientation(), Some(Orientation::CounterClockwise));
        }
    }
}
