//! Signed area by the shoelace formula.

use crate::Point;

/// Shoelace signed area of a closed vertex list (last vertex not repeated): positive when
/// counter-clockwise. Coordinates are taken relative to the first vertex, which keeps the
/// rounding error proportional to the ring's size rather than its distance from the origin.
pub fn signed_area(points: &[Point]) -> f64 {
    let n = points.len();
    if n < 3 {
        return 0.0;
    }
    let o = points[0];
    let mut twice = 0.0;
    for i in 1..n - 1 {
        twice += (points[i] - o).cross(points[i + 1] - o);
    }
    twice * 0.5
}
