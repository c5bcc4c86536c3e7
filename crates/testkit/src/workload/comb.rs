//! `comb`: one ring each, a spine and long vertical teeth of random heights, so a horizontal
//! line crosses every tooth: a sweep that visits every active edge in every scanbeam does
//! Θ(teeth²) work on it. Even indices pair two combs (the clip shifted half a tooth), odd ones a
//! comb and a small box over its teeth.

use clip_core::{Point, Polygons, Rect, Ring};
use rand::Rng;
use rand_pcg::Pcg64;

/// A counter-clockwise comb of `teeth` teeth (4 `teeth` vertices, all on integers): a spine
/// [x0, x0 + 4 teeth - 2] x [-2, 0] and teeth 2 wide, 4 apart, rising from it to random heights
/// in [2 teeth, 4 teeth], so the teeth are long beside the comb's width.
pub(crate) fn comb(rng: &mut Pcg64, teeth: usize, x0: i64) -> Ring {
    let k = teeth.max(1) as i64;
    let heights: Vec<i64> = (0..k).map(|_| rng.random_range(2 * k..=4 * k)).collect();
    let at = |x: i64, y: i64| Point::new((x0 + x) as f64, y as f64);
    let mut points = Vec::with_capacity(4 * k as usize);
    points.push(at(0, -2));
    points.push(at(4 * k - 2, -2));
    // Right to left along the top: up the right side of each tooth, across, down, along the gap.
    for i in (0..k).rev() {
        let (left, right, h) = (4 * i, 4 * i + 2, heights[i as usize]);
        if i + 1 < k {
            points.push(at(right, 0));
        }
        points.push(at(right, h));
        points.push(at(left, h));
        if i > 0 {
            points.push(at(left, 0));
        }
    }
    Ring::new(points)
}

/// Two combs of `teeth` teeth each, the clip shifted right by half a tooth (1), with its own
/// heights: their spines overlap along collinear edges, their teeth half overlap.
pub(crate) fn comb_pair(rng: &mut Pcg64, teeth: usize) -> (Polygons, Polygons) {
    let subject = comb(rng, teeth, 0);
    let clip = comb(rng, teeth, 1);
    (subject.into(), clip.into())
}

/// A comb of `teeth` teeth and an axis-aligned box of about 1% of its area at a random place
/// over its teeth (below the shortest tooth's top, so teeth cross it from side to side); the
/// box's corners are not on integers, so no edge of it lies along the comb's.
pub(crate) fn comb_box(rng: &mut Pcg64, teeth: usize) -> (Polygons, Polygons) {
    let subject = comb(rng, teeth, 0);
    let k = teeth.max(1) as f64;
    let side = (0.01 * subject.signed_area()).sqrt();
    let x = rng.random_range(0.0..(4.0 * k - 2.0 - side).max(f64::MIN_POSITIVE));
    let y = rng.random_range(0.0..(2.0 * k - side).max(f64::MIN_POSITIVE));
    (subject.into(), Rect::new(x, y, x + side, y + side).into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn combs_have_four_vertices_a_tooth_and_run_counter_clockwise() {
        let mut rng = Pcg64::seed_from_u64(3);
        for teeth in [1, 2, 7, 100] {
            let c = comb(&mut rng, teeth, 0);
            assert_eq!(c.len(), 4 * teeth);
            assert!(c.signed_area() > 0.0);
            // Only vertical and horizontal edges, none of zero length.
            assert!(c.edges().all(|e| (e.a.x == e.b.x) != (e.a.y == e.b.y)), "{c:?}");
        }
    }

    #[test]
    fn the_box_is_about_a_hundredth_of_the_comb_and_over_its_teeth() {
        let mut rng = Pcg64::seed_from_u64(5);
        for teeth in [1, 10, 1000] {
            let (comb, b) = comb_box(&mut rng, teeth);
            let r = b.bounds();
            assert!((b.signed_area() / comb.signed_area() - 0.01).abs() < 1e-9);
            let k = teeth as f64;
            assert!(r.min.x >= 0.0 && r.max.x <= 4.0 * k - 2.0 && r.min.y >= 0.0 && r.max.y <= 2.0 * k);
        }
    }
}
