//! Workloads for Vatti's extensions: `spiky-box` (a spiky star against a small box inside it,
//! the envelope pre-filter's case) and `many-subjects` (small subjects over one fixed clip
//! polygon, the prepared clip's case).

use clip_core::{Point, Polygons, Rect, Ring};
use rand::Rng;
use rand_pcg::Pcg64;

use super::shapes::{lobed, scribble, star};
use super::stream_rng;

/// The clip polygon's edge count in `many-subjects` when no size is given.
pub const MANY_SUBJECTS_CLIP_EDGES: usize = 1_000;

/// A spiky star of `n` edges about (500, 500) (radii 80-400) and an axis-aligned box of about
/// 1% of its area near its centre, inside its inner radius: no star edge reaches the box.
pub(crate) fn spiky_box(rng: &mut Pcg64, n: usize) -> (Polygons, Polygons) {
    let s = star(rng, n, Point::new(500.0, 500.0), 400.0, 400.0, 0.2);
    let half = 0.5 * (0.01 * s.signed_area().abs()).sqrt();
    let c = Point::new(500.0 + rng.random_range(-10.0..10.0), 500.0 + rng.random_range(-10.0..10.0));
    (s.into(), Rect::new(c.x - half, c.y - half, c.x + half, c.y + half).into())
}

/// The fixed clip of `many-subjects`: a lobed ring of `edges` edges (seven petals, a detailed
/// boundary like a map sheet's, crossed by a line a bounded number of times) over [50, 950]²,
/// the same for every index of a seed.
pub(crate) fn many_subjects_clip(seed: u64, edges: usize) -> Ring {
    let mut rng = stream_rng("many-subjects clip", seed, edges as u64);
    lobed(&mut rng, edges, Point::new(500.0, 500.0), 450.0, 7.0, 0.4)
}

/// Subject `index` of `many-subjects`: 4-40 edges, 10-60 units across, anywhere over the clip;
/// a star on even indices, a self-crossing scribble on odd ones, one in five clockwise.
pub(crate) fn many_subjects_subject(rng: &mut Pcg64, index: usize) -> Ring {
    let n = rng.random_range(4..=40);
    let c = Point::new(rng.random_range(0.0..1000.0), rng.random_range(0.0..1000.0));
    let r = rng.random_range(5.0..30.0);
    let ring = if index.is_multiple_of(2) {
        star(rng, n, c, r, r, 0.4)
    } else {
        scribble(rng, n, Rect::new(c.x - r, c.y - r, c.x + r, c.y + r))
    };
    if rng.random_bool(0.2) { ring.reversed() } else { ring }
}
