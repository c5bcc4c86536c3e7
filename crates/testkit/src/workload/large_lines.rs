//! Line workloads against large windows: `lines-large` (10^3-10^4 edges, concave with holes) and
//! the windows and short segments of the beyond-the-paper scaling table.

use super::shapes::{convex, lobed};
use super::stream_rng;
use super::wang::{WangSize, wang_box};
use clip_core::{Point, Polygons, Rect, Ring, Segment};
use rand::Rng;
use rand_pcg::Pcg64;
use std::f64::consts::TAU;

/// The sizes `lines-large` cycles through (window edges, holes included).
pub const LINES_LARGE_EDGES: [usize; 4] = [1_000, 2_000, 5_000, 10_000];

/// The window sizes of the beyond-the-paper table: Table 4's, then up to 10^4 edges.
pub const BEYOND_EDGES: [usize; 7] = [6, 10, 20, 50, 100, 1_000, 10_000];

/// Petals of the lobed windows: a line crosses such a window at most about twice this often.
const LOBES: f64 = 7.0;

/// A `lines-large` window of about `edges` edges in the 800x600 screen: a lobed outer ring
/// (counter-clockwise, half the edges) and 1-4 lobed holes (clockwise) sharing the other half.
pub fn lines_large_window(rng: &mut Pcg64, edges: usize) -> Polygons {
    let edges = edges.max(24);
    let center = Point::new(400.0, 300.0);
    let outer_edges = edges / 2;
    let holes = rng.random_range(1..=4usize);
    let mut rings = vec![lobed(rng, outer_edges, center, 280.0, LOBES, 0.35)];
    let phase = rng.random::<f64>() * TAU;
    let per_hole = (edges - outer_edges) / holes;
    for i in 0..holes {
        let m = if i + 1 == holes { edges - outer_edges - (holes - 1) * per_hole } else { per_hole };
        let (d, r) = if holes == 1 { (0.0, 80.0) } else { (110.0, 45.0) };
        let a = phase + TAU * i as f64 / holes as f64;
        let c = Point::new(center.x + d * a.cos(), center.y + d * a.sin());
        rings.push(lobed(rng, m, c, r, 5.0, 0.3).reversed());
    }
    Polygons::new(rings)
}

/// `count` segments about a `lines-large` window: 40% long (ends uniform in its bounding box grown
/// by a tenth), 30% short (at most 2% of the box's width), and 30% with exact incidences: from a
/// vertex, vertex to vertex, horizontal or vertical through a vertex, along an edge, or of zero
/// length.
pub fn lines_large_segments(rng: &mut Pcg64, window: &Polygons, count: usize) -> Vec<Segment> {
    let b = window.bounds();
    let grown = b.inflate(0.1 * b.width().max(b.height()));
    let vertex = |rng: &mut Pcg64| {
        let ring = &window.rings[rng.random_range(0..window.rings.len())].points;
        let i = rng.random_range(0..ring.len());
        (ring[i], ring[(i + 1) % ring.len()])
    };
    (0..count)
        .map(|_| match rng.random_range(0..10) {
            0..=3 => Segment::new(uniform(rng, &grown), uniform(rng, &grown)),
            4..=6 => short_segment(rng, &b, 0.02 * b.width()),
            7 => {
                let (v, _) = vertex(rng);
                let (w, _) = vertex(rng);
                if rng.random_bool(0.5) { Segment::new(v, uniform(rng, &grown)) } else { Segment::new(v, w) }
            }
            8 => {
                let (v, _) = vertex(rng);
                let (lo, hi) = (rng.random_range(-300.0..0.0), rng.random_range(0.0..300.0));
                if rng.random_bool(0.5) {
                    Segment::new(Point::new(v.x + lo, v.y), Point::new(v.x + hi, v.y))
                } else {
                    Segment::new(Point::new(v.x, v.y + lo), Point::new(v.x, v.y + hi))
                }
            }
            _ => {
                let (v, next) = vertex(rng);
                match rng.random_range(0..3) {
                    0 => Segment::new(v, next),
                    1 => Segment::new(next, v),
                    _ => Segment::new(v, v),
                }
            }
        })
        .collect()
}

/// A beyond-the-paper window of `edges` edges: lobed (concave) or convex, its bounding box sized
/// like Table 4's second size row (W1 = 4, W2 = 80) and centred on the screen, so that only the
/// edge count changes from one size to the next. The shape depends on `seed` and `edges` only.
pub fn beyond_window(edges: usize, seed: u64, convex_window: bool) -> Polygons {
    let mut rng = stream_rng("beyond-window", seed, edges as u64 * 2 + u64::from(convex_window));
    let ring = if convex_window {
        convex(&mut rng, edges, Point::ZERO, 1.0, 1.0)
    } else {
        lobed(&mut rng, edges, Point::ZERO, 1.0, LOBES, 0.35)
    };
    let (w1, w2) = WangSize::W2.paper_w1_w2(edges);
    let (w, h) = wang_box(w1, w2);
    let rb = ring.bounds();
    let (sx, sy) = (w / rb.width(), h / rb.height());
    let fitted = ring
        .points
        .iter()
        .map(|p| Point::new(400.0 + (p.x - rb.min.x) * sx - w / 2.0, 300.0 + (p.y - rb.min.y) * sy - h / 2.0))
        .collect();
    Polygons::from(Ring::new(fitted))
}

/// `count` short segments over `bounds`, as in road data: midpoints uniform in it, directions
/// uniform, lengths uniform in `(0, max_length]`.
pub fn short_segments(count: usize, seed: u64, bounds: &Rect, max_length: f64) -> Vec<Segment> {
    let mut rng = stream_rng("short-segments", seed, count as u64);
    (0..count).map(|_| short_segment(&mut rng, bounds, max_length)).collect()
}

fn short_segment(rng: &mut Pcg64, bounds: &Rect, max_length: f64) -> Segment {
    let m = uniform(rng, bounds);
    let half = 0.5 * max_length * (1.0 - rng.random::<f64>());
    let (s, c) = (rng.random::<f64>() * TAU).sin_cos();
    Segment::new(Point::new(m.x - half * c, m.y - half * s), Point::new(m.x + half * c, m.y + half * s))
}

fn uniform(rng: &mut Pcg64, r: &Rect) -> Point {
    Point::new(r.min.x + rng.random::<f64>() * r.width(), r.min.y + rng.random::<f64>() * r.height())
}
