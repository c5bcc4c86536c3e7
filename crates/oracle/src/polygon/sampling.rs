//! Exact point classification at sample points, skipping points near any edge.

use clip_core::predicates::{Orientation, orient};
use clip_core::{Point, Polygons, Rect};

/// Sample points per side of the regular grid.
const GRID_SIDE: usize = 12;
/// Random sample points on top of the grid.
const RANDOM_POINTS: usize = 112;

/// The sample points for a box: a regular grid (cell centres) and seeded random points, the
/// same for the same box.
pub(crate) fn sample_points(b: &Rect) -> Vec<Point> {
    let mut points = Vec::with_capacity(GRID_SIDE * GRID_SIDE + RANDOM_POINTS);
    let (w, h) = (b.width(), b.height());
    for i in 0..GRID_SIDE {
        for j in 0..GRID_SIDE {
            let (fx, fy) = ((i as f64 + 0.5) / GRID_SIDE as f64, (j as f64 + 0.5) / GRID_SIDE as f64);
            points.push(Point::new(b.min.x + fx * w, b.min.y + fy * h));
        }
    }
    let mut rng = SplitMix64(0x005e_ed0f_0c1e);
    for _ in 0..RANDOM_POINTS {
        points.push(Point::new(b.min.x + rng.unit() * w, b.min.y + rng.unit() * h));
    }
    points
}

/// Vigna's SplitMix64: enough randomness to scatter sample points, and no dependency for a crate
/// that should need only clip-core.
struct SplitMix64(u64);

impl SplitMix64 {
    /// A uniform f64 in [0, 1) from the top 53 bits of the next output.
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// One polygon set's edges, bucketed by y so a point meets only the edges near its height.
pub(crate) struct PointClassifier {
    edges: Vec<(Point, Point)>,
    buckets: Vec<Vec<u32>>,
    y0: f64,
    bucket_height: f64,
    margin: f64,
}

impl PointClassifier {
    /// Indexes `polygons`; points within `margin` of an edge will be left unclassified.
    pub(crate) fn new(polygons: &Polygons, margin: f64) -> PointClassifier {
        let edges: Vec<(Point, Point)> = polygons.edges().map(|s| (s.a, s.b)).collect();
        let b = polygons.bounds();
        let count = ((edges.len() as f64).sqrt() as usize).clamp(1, 512);
        let bucket_height = if b.is_empty() || b.height() == 0.0 { 1.0 } else { b.height() / count as f64 };
        let y0 = if b.is_empty() { 0.0 } else { b.min.y };
        let mut buckets = vec![Vec::new(); count];
        for (i, &(a, c)) in edges.iter().enumerate() {
            let lo = ((a.y.min(c.y) - margin - y0) / bucket_height).floor().max(0.0) as usize;
            let hi = (((a.y.max(c.y) + margin - y0) / bucket_height).floor().max(0.0) as usize).min(count - 1);
            for bucket in &mut buckets[lo.min(count - 1)..=hi] {
                bucket.push(i as u32);
            }
        }
        PointClassifier { edges, buckets, y0, bucket_height, margin }
    }

    /// The winding number around `p`, or `None` when `p` is within the margin of an edge.
    /// The winding number is exact (Sunday's rule with exact orientation).
    pub(crate) fn winding(&self, p: Point) -> Option<i32> {
        // Points beyond the box fall in the nearest bucket, whose edges the y test then skips.
        let k = ((p.y - self.y0) / self.bucket_height).floor();
        let bucket = if k > 0.0 { (k as usize).min(self.buckets.len() - 1) } else { 0 };
        let m = self.margin;
        let mut w = 0;
        for &i in &self.buckets[bucket] {
            let (a, b) = self.edges[i as usize];
            let (y_lo, y_hi) = if a.y <= b.y { (a.y, b.y) } else { (b.y, a.y) };
            let (x_lo, x_hi) = if a.x <= b.x { (a.x, b.x) } else { (b.x, a.x) };
            if p.y < y_lo - m || p.y > y_hi + m || p.x > x_hi + m {
                // Too far above, below or left of p to touch it or to be crossed by its rightward ray.
                continue;
            }
            let far_right = p.x < x_lo - m;
            if !far_right && distance_to_segment(p, a, b) <= m {
                return None;
            }
            // Sunday's rule; an edge entirely to the right is crossed whenever it spans p.y.
            if a.y <= p.y {
                if b.y > p.y && (far_right || orient(a, b, p) == Orientation::CounterClockwise) {
                    w += 1;
                }
            } else if b.y <= p.y && (far_right || orient(a, b, p) == Orientation::Clockwise) {
                w -= 1;
            }
        }
        Some(w)
    }
}

fn distance_to_segment(p: Point, a: Point, b: Point) -> f64 {
    let d = b - a;
    let len2 = d.dot(d);
    let t = if len2 > 0.0 { ((p - a).dot(d) / len2).clamp(0.0, 1.0) } else { 0.0 };
    p.distance(a + d * t)
}
