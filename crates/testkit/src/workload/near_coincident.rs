//! `near-coincident`: pairs of polygons whose long edges nearly coincide, where rounding a
//! crossing to f64 decides the answer's topology. The inputs real overlays are full of (a
//! country against its neighbour digitised twice, a parcel against a copy moved by a
//! projection's rounding) and that random inputs never produce.
//!
//! The subject is a star of long edges with notches cut into it and spikes pulled out of it,
//! each narrower than 1e-12 of its extent. The clip, by index mod 3:
//!
//! - `turned`: the subject turned about one of its vertices by an angle from 1e-16 to 1e-6
//!   (log-uniform), so every edge nearly coincides with its original (or, when the turn moves no
//!   vertex by an ulp, coincides exactly);
//! - `shifted`: the subject with every coordinate moved by the same few ulps (1 to 8, each axis
//!   its own count and sign);
//! - `traced`: a ring walking the subject's boundary with its vertices on the subject's edges,
//!   each a few ulps off (up to 3 per coordinate), and now and then a vertex pulled away, so its
//!   edges lie along the subject's for long stretches and cross it at shallow angles.
//!
//! So the fill rules disagree: one subject in four runs clockwise, and one clip in three has a
//! second ring, its own copy turned by another tiny angle (two layers nearly everywhere). One
//! case in four sits near (1e6, 1e6), where an ulp is 1e-10.

use clip_core::{Point, Polygons, Ring};
use rand::Rng;
use rand_pcg::Pcg64;

use super::shapes::{dedup_consecutive, star};

/// The clip's construction, by case index mod 3.
const KINDS: [&str; 3] = ["turned", "shifted", "traced"];

/// The subject's radius: its extent is about twice this.
const RADIUS: f64 = 400.0;

/// A case: (subject, clip, description). `n` is the subject's edge count (notches and spikes
/// included, to within a few).
pub(crate) fn near_coincident(rng: &mut Pcg64, index: usize, n: usize) -> (Polygons, Polygons, String) {
    let far = rng.random_bool(0.25);
    let center = if far { Point::new(1.0e6 + 500.0, 1.0e6 + 500.0) } else { Point::new(500.0, 500.0) };
    let features = if n >= 12 { (n / 16).max(1) } else { 0 };
    let base = star(rng, n.saturating_sub(4 * features).max(4), center, RADIUS, RADIUS, 0.6);
    let (subject, notches, spikes) = with_features(rng, &base, features);
    let kind = KINDS[index % KINDS.len()];
    let (clip, how) = match kind {
        "turned" => {
            let angle = tiny_angle(rng);
            let pivot = subject.points[rng.random_range(0..subject.len())];
            let clip = turned(&subject, pivot, angle);
            // Far from the origin the smallest turns move no vertex by an ulp: exact coincidence.
            let exact = if clip == subject { " (an exact copy: no vertex moved)" } else { "" };
            (clip, format!("turned by {angle:.1e} rad about a vertex{exact}"))
        }
        "shifted" => {
            let (kx, ky) = (ulps(rng, 1..=8), ulps(rng, 1..=8));
            let points = subject.points.iter().map(|p| Point::new(step(p.x, kx), step(p.y, ky))).collect();
            (Ring::new(points), format!("shifted by {kx} ulps in x and {ky} in y"))
        }
        _ => (traced(rng, &subject), "tracing its edges a few ulps off".to_owned()),
    };
    let mut clip_rings = vec![clip.clone()];
    let mut layers = "";
    if rng.random_bool(1.0 / 3.0) {
        let pivot = clip.points[rng.random_range(0..clip.len())];
        clip_rings.push(turned(&clip, pivot, tiny_angle(rng)));
        layers = ", doubled by a turned copy";
    }
    let clockwise = rng.random_bool(0.25);
    let subject = if clockwise { subject.reversed() } else { subject };
    let what = format!(
        "near-coincident ({kind}) {}subject {} edges ({notches} notches, {spikes} spikes under 1e-12 of the extent){} vs its copy {how}{layers}",
        if clockwise { "clockwise " } else { "" },
        subject.len(),
        if far { " near (1e6, 1e6)" } else { "" },
    );
    (Polygons::from(subject), Polygons::new(clip_rings), what)
}

/// An angle from 1e-16 to 1e-6 radians, log-uniform, either sign.
fn tiny_angle(rng: &mut Pcg64) -> f64 {
    let angle = 10f64.powf(rng.random_range(-16.0..-6.0));
    if rng.random_bool(0.5) { angle } else { -angle }
}

/// A count of ulps in `range`, either sign.
fn ulps(rng: &mut Pcg64, range: std::ops::RangeInclusive<i32>) -> i32 {
    let k = rng.random_range(range);
    if rng.random_bool(0.5) { k } else { -k }
}

/// `v` moved by `k` representable steps (up for positive `k`).
fn step(v: f64, k: i32) -> f64 {
    (0..k.unsigned_abs()).fold(v, |v, _| if k > 0 { v.next_up() } else { v.next_down() })
}

/// `ring` turned about `pivot` by `angle` radians.
fn turned(ring: &Ring, pivot: Point, angle: f64) -> Ring {
    let (sin, cos) = angle.sin_cos();
    let points = ring
        .points
        .iter()
        .map(|p| {
            let (dx, dy) = (p.x - pivot.x, p.y - pivot.y);
            Point::new(pivot.x + dx * cos - dy * sin, pivot.y + dx * sin + dy * cos)
        })
        .collect();
    Ring::new(points)
}

/// `base` (counter-clockwise) with `count` features on distinct edges, alternately a notch cut
/// inwards and a spike pulled outwards, each a wedge or a parallel-sided slot of width 1e-15.5 to
/// 1e-12 of the extent and depth a tenth of its edge. Returns the ring and the counts.
fn with_features(rng: &mut Pcg64, base: &Ring, count: usize) -> (Ring, usize, usize) {
    let n = base.len();
    let extent = 2.0 * RADIUS;
    let mut chosen = vec![false; n];
    for _ in 0..count.min(n) {
        let mut e = rng.random_range(0..n);
        while chosen[e] {
            e = (e + 1) % n;
        }
        chosen[e] = true;
    }
    let (mut notches, mut spikes) = (0, 0);
    let mut points = Vec::with_capacity(n + 4 * count);
    for (i, &a) in base.points.iter().enumerate() {
        points.push(a);
        if !chosen[i] {
            continue;
        }
        let b = base.points[(i + 1) % n];
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let length = (dx * dx + dy * dy).sqrt();
        let (ux, uy) = (dx / length, dy / length);
        let notch = (notches + spikes) % 2 == 0;
        // Inward is left of a counter-clockwise edge.
        let (nx, ny) = if notch { (-uy, ux) } else { (uy, -ux) };
        let width = extent * 10f64.powf(rng.random_range(-15.5..-12.0));
        let depth = 0.1 * length * rng.random_range(0.2..1.0);
        let t = rng.random_range(0.2..0.8);
        let m = Point::new(a.x + t * dx, a.y + t * dy);
        let m1 = Point::new(m.x - 0.5 * width * ux, m.y - 0.5 * width * uy);
        let m2 = Point::new(m.x + 0.5 * width * ux, m.y + 0.5 * width * uy);
        if rng.random_bool(0.5) {
            points.extend([m1, Point::new(m.x + depth * nx, m.y + depth * ny), m2]);
        } else {
            let out = |p: Point| Point::new(p.x + depth * nx, p.y + depth * ny);
            points.extend([m1, out(m1), out(m2), m2]);
        }
        if notch {
            notches += 1;
        } else {
            spikes += 1;
        }
    }
    // A width under an ulp can round two feature points together.
    dedup_consecutive(&mut points);
    (Ring::new(points), notches, spikes)
}

/// A ring walking `subject`'s boundary: per edge, up to two points on it, each coordinate a few
/// ulps off (up to 3), and one edge in six contributing a point pulled a little way off instead.
fn traced(rng: &mut Pcg64, subject: &Ring) -> Ring {
    let n = subject.len();
    let mut points = Vec::with_capacity(2 * n);
    for i in 0..n {
        let (a, b) = (subject.points[i], subject.points[(i + 1) % n]);
        if rng.random_bool(1.0 / 6.0) {
            let m = a.lerp(b, 0.5);
            let pull = rng.random_range(-0.05..0.05);
            points.push(Point::new(m.x + pull * (b.y - a.y), m.y - pull * (b.x - a.x)));
            continue;
        }
        let mut ts = [rng.random_range(0.0..1.0), rng.random_range(0.0..1.0)];
        ts.sort_by(f64::total_cmp);
        for t in ts.iter().take(rng.random_range(1..=2)) {
            let p = a.lerp(b, *t);
            points.push(Point::new(step(p.x, ulps(rng, 0..=3)), step(p.y, ulps(rng, 0..=3))));
        }
    }
    dedup_consecutive(&mut points);
    Ring::new(points)
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn features_are_narrower_than_1e12_of_the_extent() {
        let mut rng = Pcg64::seed_from_u64(3);
        let base = star(&mut rng, 40, Point::new(500.0, 500.0), RADIUS, RADIUS, 0.6);
        let (ring, notches, spikes) = with_features(&mut rng, &base, 4);
        assert_eq!((notches, spikes), (2, 2));
        assert!(ring.len() >= 40 + 4 * 3);
        // Every feature's mouth: two consecutive new points closer than 1e-12 of the extent.
        let p = &ring.points;
        let mouths = (0..p.len())
            .flat_map(|i| (2..=3).map(move |k| (i, k)))
            .filter(|&(i, k)| p[i].distance(p[(i + k) % p.len()]) < 1e-12 * 2.0 * RADIUS)
            .count();
        assert_eq!(mouths, 4, "{p:?}");
    }

    #[test]
    fn traced_vertices_lie_a_few_ulps_off_the_subject() {
        let mut rng = Pcg64::seed_from_u64(5);
        let subject = star(&mut rng, 30, Point::new(500.0, 500.0), RADIUS, RADIUS, 0.6);
        let clip = traced(&mut rng, &subject);
        let near =
            |q: Point| subject.edges().any(|e| clip_core::predicates::orient2d(e.a, e.b, q).abs() / e.length() < 1e-11);
        let on_edges = clip.points.iter().filter(|&&q| near(q)).count();
        assert!(on_edges * 4 >= clip.len() * 3, "{on_edges} of {}", clip.len());
        assert!(clip.points.iter().any(|q| !subject.points.contains(q)));
    }
}
