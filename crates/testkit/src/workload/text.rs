//! The `text` workload: seeded strings, sizes, positions and windows for text clipping.

use clip_core::{Point, Polygons, Rect};
use rand::Rng;

use super::shapes::{convex, star};
use super::stream_rng;

/// The characters `text` strings are drawn from: printable basic Latin, which both the outline
/// and the bitmap font have, with spaces.
pub const TEXT_CHARSET: &str =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789 .,;:!?'\"()[]{}<>-+*/=_@#$%&~^|\\";

/// One text case: a string laid out at `size` pixels from `origin` (baseline, y up), and a
/// window. The text stays in `x, y > 0` (its descenders too): the oracle draws there.
#[derive(Clone, Debug, PartialEq)]
pub struct TextCase {
    /// The run's seed.
    pub seed: u64,
    /// The case's index.
    pub index: usize,
    /// The string (1 to 24 characters of [`TEXT_CHARSET`]).
    pub string: String,
    /// Pixels per em (outline font); the bitmap font uses `floor(size / 8)` pixels per font pixel.
    pub size: f64,
    /// Where the baseline starts.
    pub origin: Point,
    /// The window: a rectangle, a convex polygon or a concave star (by index mod 3), over the
    /// text's estimated box, from a little part of it to all of it.
    pub window: Polygons,
    /// What the case is, in words.
    pub description: String,
}

/// Case `index` of the `text` workload.
pub fn text_case(seed: u64, index: usize) -> TextCase {
    let mut rng = stream_rng("text", seed, index as u64);
    let length = rng.random_range(1..=24);
    let chars: Vec<char> = TEXT_CHARSET.chars().collect();
    let string: String = (0..length).map(|_| chars[rng.random_range(0..chars.len())]).collect();
    // Sizes from 8 to 64 pixels; on odd indices whole pixels, so edges and pixel centres meet.
    let mut size = rng.random_range(8.0..64.0);
    let mut origin = Point::new(0.3 * size + rng.random_range(1.0..100.0), size + rng.random_range(1.0..100.0));
    if index % 2 == 1 {
        size = size.round();
        origin = Point::new(origin.x.round(), origin.y.round());
    }
    // About what the string covers: an em high (from a quarter below the baseline), 0.65 em a character.
    let estimate = Rect::new(origin.x, origin.y - 0.25 * size, origin.x + 0.65 * size * length as f64, origin.y + size);
    let (w, h) = (estimate.width(), estimate.height());
    let centre =
        Point::new(estimate.min.x + w * rng.random_range(0.1..0.9), estimate.min.y + h * rng.random_range(0.1..0.9));
    let (hw, hh) = (w * rng.random_range(0.1..0.8), h * rng.random_range(0.2..1.0));
    let (window, shape) = match index % 3 {
        0 => {
            let mut r = Rect::new(centre.x - hw, centre.y - hh, centre.x + hw, centre.y + hh);
            if index % 2 == 1 {
                r = Rect::new(r.min.x.floor(), r.min.y.floor(), r.max.x.ceil(), r.max.y.ceil());
            }
            (Polygons::from(r), "rectangle")
        }
        1 => {
            let n = rng.random_range(4..=12);
            (Polygons::from(convex(&mut rng, n, centre, hw, hh)), "convex")
        }
        _ => {
            let n = rng.random_range(6..=20);
            (Polygons::from(star(&mut rng, n, centre, hw, hh, 0.5)), "concave")
        }
    };
    let description = format!("text {string:?} at {size} px from ({}, {}), {shape} window", origin.x, origin.y);
    TextCase { seed, index, string, size, origin, window, description }
}
