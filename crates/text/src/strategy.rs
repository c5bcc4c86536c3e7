//! The notes' text-clipping strategies: all-or-none string, all-or-none character, and per-component (outline glyphs as polygons, bitmap glyphs pixel by pixel).

use core::fmt;
use core::str::FromStr;

use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons};

use crate::error::TextError;
use crate::layout::{Shape, Text};
use crate::window::TextWindow;

/// How a string is clipped.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Strategy {
    /// All-or-none string (Fig. 6-28): the string's box against the window; the whole string is
    /// kept when its box is inside, else nothing.
    String,
    /// All-or-none character (Fig. 6-29): each glyph's box against the window; a glyph is kept
    /// whole when its box is inside, else dropped.
    Character,
    /// Per-component (Fig. 6-30): the parts of each glyph outside the window are clipped off. An
    /// outline glyph is clipped as polygons by a polygon clipper; a bitmap glyph pixel by pixel,
    /// a pixel kept when its centre is in the closed window.
    Components,
}

impl Strategy {
    /// Every strategy, in the notes' order.
    pub const ALL: [Strategy; 3] = [Strategy::String, Strategy::Character, Strategy::Components];

    /// Its name: `string`, `char` or `components`.
    pub fn name(self) -> &'static str {
        match self {
            Strategy::String => "string",
            Strategy::Character => "char",
            Strategy::Components => "components",
        }
    }
}

impl fmt::Display for Strategy {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Strategy {
    type Err = String;
    fn from_str(s: &str) -> Result<Strategy, String> {
        Strategy::ALL
            .into_iter()
            .find(|k| k.name() == s)
            .ok_or_else(|| format!("unknown strategy '{s}' (string, char, components)"))
    }
}

/// What survives clipping.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Clipped {
    /// Glyphs kept whole (by index into the text's glyphs).
    pub kept: Vec<usize>,
    /// The outline that is drawn: kept glyphs' outlines and clipped pieces, read under non-zero.
    pub polygons: Polygons,
    /// The bitmap pixels that are drawn.
    pub pixels: Vec<(i64, i64)>,
}

/// Clips `text` to `window` with `strategy`. `clipper` clips outline glyphs the window cuts
/// (intersection, non-zero); it is only called by [`Strategy::Components`] on outline text, and
/// its own limits apply (a Sutherland-Hodgman clipper refuses a window that is not convex with
/// [`clip_core::ClipError::WindowNotConvex`]).
pub fn clip_text(
    text: &Text,
    window: &TextWindow,
    strategy: Strategy,
    clipper: &dyn PolygonClipper,
) -> Result<Clipped, TextError> {
    let mut out = Clipped::default();
    match strategy {
        Strategy::String => {
            if window.contains_box(text.bounds) {
                (0..text.glyphs.len()).for_each(|i| keep_whole(text, i, &mut out));
            }
        }
        Strategy::Character => {
            for (i, g) in text.glyphs.iter().enumerate() {
                if window.contains_box(g.bounds) {
                    keep_whole(text, i, &mut out);
                }
            }
        }
        Strategy::Components => {
            for (i, g) in text.glyphs.iter().enumerate() {
                // The notes' trivial tests first: a glyph whose box is inside is kept whole, one
                // whose box misses the window's box is dropped; only the rest are clipped.
                if g.bounds.is_empty() || !g.bounds.intersects(&window.bounds()) {
                    continue;
                }
                if window.contains_box(g.bounds) {
                    keep_whole(text, i, &mut out);
                    continue;
                }
                match &g.shape {
                    Shape::Outline(p) => {
                        let piece = clipper.clip(p, window.polygons(), BoolOp::Intersection, FillRule::NonZero)?;
                        out.polygons.rings.extend(piece.rings);
                    }
                    Shape::Pixels(pixels) => {
                        out.pixels.extend(pixels.iter().copied().filter(|&(i, j)| window.covers(pixel_centre(i, j))))
                    }
                }
            }
        }
    }
    Ok(out)
}

fn keep_whole(text: &Text, i: usize, out: &mut Clipped) {
    out.kept.push(i);
    match &text.glyphs[i].shape {
        Shape::Outline(p) => out.polygons.rings.extend(p.rings.iter().cloned()),
        Shape::Pixels(p) => out.pixels.extend_from_slice(p),
    }
}

/// The centre of pixel `(i, j)`, which decides whether it is drawn (clip-raster's rule).
pub fn pixel_centre(i: i64, j: i64) -> clip_core::Point {
    clip_core::Point::new(i as f64 + 0.5, j as f64 + 0.5)
}
