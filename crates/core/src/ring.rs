//! A closed ring of vertices; the closing edge from the last vertex back to the first is implied.

use crate::predicates::{Orientation, orient};
use crate::{Point, Rect, Segment};

/// A closed polygon boundary. The last vertex is not repeated: the edge from the last vertex to
/// the first is implied. A ring may be concave or self-intersecting; its orientation matters under
/// the non-zero, positive and negative fill rules.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ring {
    /// The vertices in order.
    pub points: Vec<Point>,
}

impl Ring {
    /// Makes a ring; a last vertex equal to the first (an explicitly closed ring) is dropped.
    pub fn new(mut points: Vec<Point>) -> Ring {
        if points.len() > 1 && points.first() == points.last() {
            points.pop();
        }
        Ring { points }
    }

    /// Number of vertices (and of edges).
    #[inline]
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// True when the ring has no vertex.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The edges in order, the closing edge last.
    pub fn edges(&self) -> impl Iterator<Item = Segment> + '_ {
        let n = self.points.len();
        (0..n).map(move |i| Segment::new(self.points[i], self.points[(i + 1) % n]))
    }

    /// The shoelace signed area: positive when counter-clockwise (y up).
    pub fn signed_area(&self) -> f64 {
        crate::area::signed_area(&self.points)
    }

    /// Whether the ring (not crossing itself) runs counter-clockwise, decided exactly where its
    /// shoelace sum is within rounding: see [`crate::runs_counter_clockwise`].
    pub fn runs_counter_clockwise(&self) -> bool {
        crate::area::runs_counter_clockwise(&self.points)
    }

    /// The bounding box.
    pub fn bounds(&self) -> Rect {
        Rect::bounding(&self.points)
    }

    /// The same ring walked the other way.
    pub fn reversed(&self) -> Ring {
        let mut points = self.points.clone();
        points.reverse();
        Ring { points }
    }

    /// Number of distinct vertices, counted only up to `limit`: a scan that stops once `limit`
    /// are found, where [`Ring::distinct_points`] sorts (validation asks for at least three).
    pub fn distinct_points_up_to(&self, limit: usize) -> usize {
        // Validation calls this for every ring of every clip: small limits count on the stack.
        const ON_STACK: usize = 8;
        if limit <= ON_STACK {
            let mut seen = [Point::new(0.0, 0.0); ON_STACK];
            let mut n = 0;
            for &p in &self.points {
                if n >= limit {
                    break;
                }
                if !seen[..n].contains(&p) {
                    seen[n] = p;
                    n += 1;
                }
            }
            return n;
        }
        let mut seen: Vec<Point> = Vec::with_capacity(limit);
        for &p in &self.points {
            if seen.len() >= limit {
                break;
            }
            if !seen.contains(&p) {
                seen.push(p);
            }
        }
        seen.len()
    }

    /// Number of distinct vertices.
    pub fn distinct_points(&self) -> usize {
        let mut pts: Vec<(u64, u64)> =
            self.points.iter().map(|p| ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())).collect();
        pts.sort_unstable();
        pts.dedup();
        pts.len()
    }

    /// The ring with consecutive repeated vertices (and a repeated closing vertex) removed.
    pub fn without_repeats(&self) -> Ring {
        let mut points: Vec<Point> = Vec::with_capacity(self.points.len());
        for &p in &self.points {
            if points.last() != Some(&p) {
                points.push(p);
            }
        }
        while points.len() > 1 && points.first() == points.last() {
            points.pop();
        }
        Ring { points }
    }

    /// The orientation of a strictly convex ring, or `None` when it is not strictly convex.
    ///
    /// Repeated vertices and collinear vertices (180° turns that keep going forward) are
    /// tolerated; a ring must turn the same way at every other vertex, turn once in total
    /// (no star pentagon), and enclose positive area. Decided with exact predicates.
    pub fn convex_orientation(&self) -> Option<Orientation> {
        let ring = self.without_repeats();
        let pts = &ring.points;
        let n = pts.len();
        if n < 3 {
            return None;
        }
        let mut turn = Orientation::Collinear;
        for i in 0..n {
            let (a, b, c) = (pts[i], pts[(i + 1) % n], pts[(i + 2) % n]);
            match orient(a, b, c) {
                // A collinear vertex must continue forward (lie between its neighbours), not fold back.
                Orientation::Collinear if !between(a.x, b.x, c.x) || !between(a.y, b.y, c.y) => return None,
                Orientation::Collinear => {}
                o if turn == Orientation::Collinear => turn = o,
                o if o != turn => return None,
                _ => {}
            }
        }
        if turn == Orientation::Collinear {
            return None;
        }
        // Same turn everywhere but winding twice around (a pentagram) is not convex:
        // the edge directions must sweep 2π exactly once. Each turn is taken the way the exact
        // test above found: a turn of nearly 180° has a rounded cross product of 0 or the wrong
        // sign, which counted it as -π and let a ring winding twice pass (found by the
        // `line_clippers` fuzz target: a window turning back at 3e140 by 1e74).
        let sign = if turn == Orientation::CounterClockwise { 1.0 } else { -1.0 };
        let mut angle = 0.0f64;
        for i in 0..n {
            let d0 = pts[(i + 1) % n] - pts[i];
            let d1 = pts[(i + 2) % n] - pts[(i + 1) % n];
            angle += sign * d0.cross(d1).abs().atan2(d0.dot(d1));
        }
        if angle.abs() > 3.0 * std::f64::consts::PI {
            return None;
        }
        Some(turn)
    }

    /// The rectangle this ring traces, when it is an axis-aligned rectangle of positive area
    /// (four corners, either orientation, any start; collinear extra vertices are not accepted).
    pub fn as_rect(&self) -> Option<Rect> {
        let ring = self.without_repeats();
        if ring.len() != 4 {
            return None;
        }
        let r = ring.bounds();
        if r.width() <= 0.0 || r.height() <= 0.0 {
            return None;
        }
        let p = &ring.points;
        let corner = |q: Point| (q.x == r.min.x || q.x == r.max.x) && (q.y == r.min.y || q.y == r.max.y);
        let axis_edge = |i: usize| {
            let (a, b) = (p[i], p[(i + 1) % 4]);
            (a.x == b.x) != (a.y == b.y)
        };
        // Four corners each visited once: a zero-area spike can visit three corners with axis
        // edges only.
        let distinct = (0..4).all(|i| (i + 1..4).all(|j| p[i] != p[j]));
        if distinct && p.iter().all(|&q| corner(q)) && (0..4).all(axis_edge) { Some(r) } else { None }
    }
}

/// True when `m` lies between `a` and `c` inclusive (exact).
fn between(a: f64, m: f64, c: f64) -> bool {
    (a <= m && m <= c) || (a >= m && m >= c)
}

impl From<Vec<Point>> for Ring {
    fn from(points: Vec<Point>) -> Ring {
        Ring::new(points)
    }
}

impl From<&[(f64, f64)]> for Ring {
    fn from(points: &[(f64, f64)]) -> Ring {
        Ring::new(points.iter().map(|&p| p.into()).collect())
    }
}
