//! Signed area by the shoelace formula, and the way a ring runs where that area is rounding.

use crate::Point;
use crate::predicates::{Orientation, orient};

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

/// Whether a ring that does not cross itself (last vertex not repeated) runs counter-clockwise:
/// by the sign of its shoelace sum (from its first vertex) where that is clearly beyond the
/// sum's rounding; else by the exact turn at its lowest (then leftmost) vertex, where a simple
/// ring turns its own way. The sum comes first because a ring simple only up to rounding, with a
/// loop an ulp wide at its lowest vertex, may turn the wrong way there. (Found by the `vatti`
/// fuzz target: a triangle near 1e140 whose exact area is far below the rounding of its terms,
/// and a clockwise sliver near (1, 1.6) whose rounded sum came out positive.)
pub fn runs_counter_clockwise(points: &[Point]) -> bool {
    let n = points.len();
    if n < 3 {
        return false;
    }
    let o = points[0];
    let (mut sum, mut size) = (0.0, 0.0);
    // The two edges at the first vertex add nothing: their terms are 0.
    for w in points[1..].windows(2) {
        let (a, b) = (w[0] - o, w[1] - o);
        let (l, r) = (a.x * b.y, b.x * a.y);
        sum += l - r;
        size += l.abs() + r.abs();
    }
    // Each term and each addition rounds by at most an ulp of the running size.
    if sum.abs() > 4.0 * (n as f64 + 2.0) * f64::EPSILON * size {
        return sum > 0.0;
    }
    let lowest = (0..n).min_by(|&i, &j| points[i].y.total_cmp(&points[j].y).then(points[i].x.total_cmp(&points[j].x)));
    let Some(i) = lowest else { return false };
    match orient(points[(i + n - 1) % n], points[i], points[(i + 1) % n]) {
        Orientation::CounterClockwise => true,
        Orientation::Clockwise => false,
        Orientation::Collinear => sum > 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sliver_whose_rounded_area_has_the_wrong_sign_runs_by_its_exact_turn() {
        // Three points near y = x + 0.6: exactly clockwise, with a rounded shoelace area of +4e-16.
        let sliver = [Point::new(1.1, 1.7), Point::new(0.1, 0.7), Point::new(8.1, 8.7)];
        assert!(signed_area(&sliver) > 0.0);
        assert!(!runs_counter_clockwise(&sliver));
        let reversed = [sliver[2], sliver[1], sliver[0]];
        assert!(runs_counter_clockwise(&reversed));
        // Clearly beyond rounding, the sum decides.
        let square = [Point::new(0.0, 0.0), Point::new(1.0, 0.0), Point::new(1.0, 1.0), Point::new(0.0, 1.0)];
        assert!(runs_counter_clockwise(&square));
    }
}
