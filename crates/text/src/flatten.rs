//! Flattening glyph outlines: quadratic and cubic Bézier segments to polylines within a stated tolerance.

use clip_core::{Point, Ring};

/// How many equal parameter steps keep a quadratic `p0, p1, p2` within `tolerance` of its chords.
///
/// Its second derivative is the constant `2 (p0 - 2 p1 + p2)`; a chord over a parameter step
/// `h` deviates from the curve by at most `|B''| h² / 8`, so `n` steps give
/// `|p0 - 2 p1 + p2| / (4 n²)`.
pub fn quadratic_steps(p0: Point, p1: Point, p2: Point, tolerance: f64) -> usize {
    let d = (p0 - p1 * 2.0 + p2).distance(Point::ZERO);
    steps_for(d / 4.0, tolerance)
}

/// How many equal parameter steps keep a cubic `p0..p3` within `tolerance` of its chords: its
/// second derivative is at most `6 max(|p0 - 2 p1 + p2|, |p1 - 2 p2 + p3|)` in length, so `n`
/// steps deviate by at most `3/4 max(..) / n²`.
pub fn cubic_steps(p0: Point, p1: Point, p2: Point, p3: Point, tolerance: f64) -> usize {
    let d = (p0 - p1 * 2.0 + p2).distance(Point::ZERO).max((p1 - p2 * 2.0 + p3).distance(Point::ZERO));
    steps_for(0.75 * d, tolerance)
}

/// The smallest `n >= 1` with `bound / n² <= tolerance`, capped so a huge curve at a tiny
/// tolerance cannot ask for unbounded memory.
fn steps_for(bound: f64, tolerance: f64) -> usize {
    const MAX_STEPS: f64 = 4096.0;
    // A straight segment (or a NaN bound) needs one step.
    if bound.is_nan() || bound <= 0.0 {
        return 1;
    }
    (bound / tolerance).sqrt().ceil().clamp(1.0, MAX_STEPS) as usize
}

/// The point at `t` of the quadratic.
pub fn quadratic_at(p0: Point, p1: Point, p2: Point, t: f64) -> Point {
    let u = 1.0 - t;
    p0 * (u * u) + p1 * (2.0 * u * t) + p2 * (t * t)
}

/// The point at `t` of the cubic.
pub fn cubic_at(p0: Point, p1: Point, p2: Point, p3: Point, t: f64) -> Point {
    let u = 1.0 - t;
    p0 * (u * u * u) + p1 * (3.0 * u * u * t) + p2 * (3.0 * u * t * t) + p3 * (t * t * t)
}

/// Collects a glyph's contours as rings, flattening curves, through ttf-parser's outline
/// callbacks. Coordinates are mapped by `scale` and `offset` (font units to pixels, y up) before
/// flattening, so the tolerance is in pixels.
pub struct Flattener {
    scale: f64,
    offset: Point,
    tolerance: f64,
    current: Vec<Point>,
    /// The closed contours so far (at least three points each, no repeated closing point).
    pub rings: Vec<Ring>,
}

impl Flattener {
    /// A flattener for one glyph: font unit `(u, v)` maps to `offset + scale (u, v)`.
    pub fn new(scale: f64, offset: Point, tolerance: f64) -> Flattener {
        Flattener { scale, offset, tolerance, current: Vec::new(), rings: Vec::new() }
    }

    fn map(&self, x: f32, y: f32) -> Point {
        Point::new(self.offset.x + self.scale * f64::from(x), self.offset.y + self.scale * f64::from(y))
    }

    fn last(&self) -> Point {
        self.current.last().copied().unwrap_or(self.offset)
    }

    /// Ends the contour; one of fewer than three distinct points encloses nothing and is dropped.
    fn finish(&mut self) {
        let ring = Ring::new(std::mem::take(&mut self.current)).without_repeats();
        if ring.distinct_points_up_to(3) >= 3 {
            self.rings.push(ring);
        }
    }
}

impl ttf_parser::OutlineBuilder for Flattener {
    fn move_to(&mut self, x: f32, y: f32) {
        if !self.current.is_empty() {
            self.finish();
        }
        let p = self.map(x, y);
        self.current.push(p);
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let p = self.map(x, y);
        self.current.push(p);
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (p0, p1, p2) = (self.last(), self.map(x1, y1), self.map(x, y));
        let n = quadratic_steps(p0, p1, p2, self.tolerance);
        self.current.extend((1..n).map(|i| quadratic_at(p0, p1, p2, i as f64 / n as f64)));
        self.current.push(p2);
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (p0, p1, p2, p3) = (self.last(), self.map(x1, y1), self.map(x2, y2), self.map(x, y));
        let n = cubic_steps(p0, p1, p2, p3, self.tolerance);
        self.current.extend((1..n).map(|i| cubic_at(p0, p1, p2, p3, i as f64 / n as f64)));
        self.current.push(p3);
    }

    fn close(&mut self) {
        self.finish();
    }
}

#[cfg(test)]
mod tests {
    use ttf_parser::OutlineBuilder;

    use super::*;

    /// Distance from `p` to the polyline through `points`.
    fn distance_to_polyline(p: Point, points: &[Point]) -> f64 {
        points
            .windows(2)
            .map(|w| {
                let (a, b) = (w[0], w[1]);
                let d = b - a;
                let t = if d.dot(d) > 0.0 { ((p - a).dot(d) / d.dot(d)).clamp(0.0, 1.0) } else { 0.0 };
                p.distance(a + d * t)
            })
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn a_quadratic_stays_within_the_tolerance_of_its_polyline() {
        for tolerance in [1.0, 0.1, 0.01] {
            let mut f = Flattener::new(1.0, Point::ZERO, tolerance);
            f.move_to(0.0, 0.0);
            f.quad_to(50.0, 120.0, 100.0, 0.0);
            f.close();
            let ring = &f.rings[0].points;
            let mut polyline = ring.clone();
            polyline.truncate(ring.len()); // the curve part ends at (100, 0), the last point
            for k in 0..=1000 {
                let c = quadratic_at(
                    Point::new(0.0, 0.0),
                    Point::new(50.0, 120.0),
                    Point::new(100.0, 0.0),
                    k as f64 / 1000.0,
                );
                assert!(distance_to_polyline(c, &polyline) <= tolerance * 1.0001, "tolerance {tolerance}");
            }
            // And it does not use far more points than needed: the bound is within a factor of 2 of tight.
            let n = quadratic_steps(Point::new(0.0, 0.0), Point::new(50.0, 120.0), Point::new(100.0, 0.0), tolerance);
            assert_eq!(ring.len(), n + 1);
        }
    }

    #[test]
    fn a_cubic_stays_within_the_tolerance_of_its_polyline() {
        let (p0, p1, p2, p3) =
            (Point::new(0.0, 0.0), Point::new(0.0, 80.0), Point::new(100.0, -60.0), Point::new(100.0, 40.0));
        for tolerance in [0.5, 0.05] {
            let mut f = Flattener::new(1.0, Point::ZERO, tolerance);
            f.move_to(0.0, 0.0);
            f.curve_to(0.0, 80.0, 100.0, -60.0, 100.0, 40.0);
            f.close();
            let polyline = &f.rings[0].points;
            for k in 0..=1000 {
                let c = cubic_at(p0, p1, p2, p3, k as f64 / 1000.0);
                assert!(distance_to_polyline(c, polyline) <= tolerance * 1.0001, "tolerance {tolerance}");
            }
        }
    }

    #[test]
    fn contours_of_fewer_than_three_points_are_dropped_and_scale_applies() {
        let mut f = Flattener::new(0.5, Point::new(10.0, 20.0), 0.1);
        f.move_to(0.0, 0.0);
        f.line_to(4.0, 0.0);
        f.close();
        f.move_to(0.0, 0.0);
        f.line_to(4.0, 0.0);
        f.line_to(4.0, 4.0);
        f.close();
        assert_eq!(f.rings.len(), 1);
        assert_eq!(f.rings[0].points, vec![Point::new(10.0, 20.0), Point::new(12.0, 20.0), Point::new(12.0, 22.0)]);
    }
}
