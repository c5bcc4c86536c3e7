//! clip-text: text clipping by the lecture notes' strategies, on an outline font and a bitmap font.
//!
//! *Computer Graphics, Lecture 17: Polygon Clipping* (lecture notes; our copy names no author,
//! institution or date), section "Text Clipping", Figs. 6-28 to 6-30:
//!
//! | notes | code |
//! |---|---|
//! | all-or-none string clipping: "a bounding rectangle around the text pattern" | [`Strategy::String`] |
//! | all-or-none character clipping: "the boundary limits of individual characters" | [`Strategy::Character`] |
//! | clipping the components of individual characters | [`Strategy::Components`] |
//! | outline character fonts | [`Text::outline`] (ttf-parser, flattened by [`flatten`]) |
//! | characters defined with bit maps, compared pixel by pixel | [`Text::bitmap`] (font8x8) |
//!
//! The notes clip outline characters "using a line-clipping algorithm"; here an outline glyph is a
//! filled shape, so it is clipped as polygons by any [`clip_core::PolygonClipper`] the caller
//! passes (Vatti for any window, Sutherland-Hodgman for convex ones), which keeps what is drawn a
//! filled region the oracle can compare.
//!
//! # Conventions and limits
//!
//! - Coordinates are pixels, y up. Glyphs sit on a baseline from the origin, advanced by the
//!   font's horizontal advances; no kerning or shaping.
//! - Outline curves (TrueType quadratics, CFF cubics) are flattened with equal parameter steps,
//!   enough for every chord to lie within the tolerance of its curve ([`DEFAULT_TOLERANCE`] =
//!   0.05 pixel unless another is given; bounds in [`flatten`]).
//! - Bitmap glyphs are `font8x8`'s basic Latin, each font pixel a square of
//!   `max(1, floor(size / 8))` pixels.
//! - The window is any valid polygon set, read under non-zero and closed ([`TextWindow`]). The
//!   box test is exact for windows whose rings do not overlap.
//! - The oracle ([`oracle::check_clipped_text`]) draws with clip-raster's scanline fill: pixel
//!   `(i, j)` lit when its centre `(i + 0.5, j + 0.5)` is inside, ties half-open.
//! - Bad input is a typed [`TextError`]: missing or unreadable font, a character the font lacks,
//!   an empty string, a size that is not finite and positive, a degenerate window.

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod error;
pub mod flatten;
mod font;
mod layout;
pub mod oracle;
mod raster;
mod strategy;
mod window;

pub use error::{MAX_COORDINATE_TEXT, MAX_SIZE, TextError};
pub use font::{BITMAP_FONT_NAME, DEJAVU_SANS, OutlineFont, bitmap_glyph};
pub use layout::{DEFAULT_TOLERANCE, Glyph, Shape, Text};
pub use raster::{rasterize, rasterize_clipped, rasterize_glyphs};
pub use strategy::{Clipped, Strategy, clip_text, pixel_centre};
pub use window::TextWindow;
