//! The files of `clipbench reproduce lecture`'s text part: timings per strategy as the window shrinks, the sidecar, the figures.

use serde::{Deserialize, Serialize};

/// The raw timings, one [`TextTiming`] per row.
pub const CSV: &str = "lecture-text.csv";
/// The sidecar of [`CSV`].
pub const META: &str = "lecture-text.meta.json";
/// The notes' text figures redrawn from real runs, with their captions: all-or-none string
/// (6-28), all-or-none character (6-29), per-component on the outline and the bitmap font (6-30).
pub const FIGURES: [(&str, &str); 4] = [
    ("lecture-fig6-28-string.svg", "Fig. 6-28: all-or-none string clipping"),
    ("lecture-fig6-29-char.svg", "Fig. 6-29: all-or-none character clipping"),
    ("lecture-fig6-30-outline.svg", "Fig. 6-30: per-component clipping, DejaVu Sans outlines clipped by Vatti"),
    ("lecture-fig6-30-bitmap.svg", "Fig. 6-30: per-component clipping, 8x8 bitmap font pixel by pixel"),
];

/// One row of [`CSV`]: one strategy at one window size, median of interleaved rounds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TextTiming {
    /// `string`, `char`, `outline-vatti`, `outline-sh-split` or `bitmap`.
    pub strategy: String,
    /// The window's sides as a fraction of the paragraph box's (centred; above 1 holds it all).
    pub window_side: f64,
    /// Characters in the paragraph.
    pub chars: usize,
    /// Glyphs the window cuts (neither wholly inside nor wholly outside its box test).
    pub cut_glyphs: usize,
    /// Median time per character, ns.
    pub ns_per_char: f64,
    /// Rounds the median is over.
    pub rounds: usize,
}
