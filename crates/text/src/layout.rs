//! Laying out a string on a baseline: each character's glyph as flattened polygons (outline font) or lit pixels (bitmap font), with its box.

use clip_core::{Point, Polygons, Rect};

use crate::error::{MAX_COORDINATE_TEXT, MAX_SIZE, TextError};
use crate::flatten::Flattener;
use crate::font::{OutlineFont, bitmap_glyph};

/// The default flattening tolerance, in pixels: every flattened curve lies within this distance
/// of the exact quadratic or cubic.
pub const DEFAULT_TOLERANCE: f64 = 0.05;

/// One laid-out character.
#[derive(Clone, Debug, PartialEq)]
pub struct Glyph {
    /// The character.
    pub ch: char,
    /// Its shape.
    pub shape: Shape,
    /// The box of what it draws (the flattened outline, or the lit pixels' squares); empty for a
    /// glyph that draws nothing (a space).
    pub bounds: Rect,
}

/// What a glyph draws.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// Flattened contours, read under non-zero (TrueType's rule), turned so the glyph's signed
    /// area is positive (outer contours counter-clockwise).
    Outline(Polygons),
    /// Lit pixels `(i, j)`, each the square `[i, i + 1) x [j, j + 1)`.
    Pixels(Vec<(i64, i64)>),
}

/// A laid-out string: glyphs left to right along a baseline, no kerning.
#[derive(Clone, Debug, PartialEq)]
pub struct Text {
    /// The glyphs, one per character.
    pub glyphs: Vec<Glyph>,
    /// The box of everything drawn.
    pub bounds: Rect,
}

fn check_common(string: &str, size: f64, origin: Point) -> Result<(), TextError> {
    if string.is_empty() {
        return Err(TextError::EmptyString);
    }
    if !(size > 0.0 && size <= MAX_SIZE) {
        return Err(TextError::BadSize { size });
    }
    if !(origin.x.abs() <= MAX_COORDINATE_TEXT && origin.y.abs() <= MAX_COORDINATE_TEXT) {
        return Err(TextError::BadOrigin { x: origin.x, y: origin.y });
    }
    Ok(())
}

impl Text {
    /// Lays out `string` in an outline font at `size` pixels per em, its baseline starting at
    /// `origin` (y up), curves flattened within `tolerance` pixels. Every character must have a
    /// glyph in the font ([`TextError::MissingGlyph`] otherwise; a space has one that draws
    /// nothing).
    pub fn outline(
        font: &OutlineFont,
        string: &str,
        size: f64,
        origin: Point,
        tolerance: f64,
    ) -> Result<Text, TextError> {
        check_common(string, size, origin)?;
        if !(tolerance > 0.0 && tolerance.is_finite()) {
            return Err(TextError::BadTolerance { tolerance });
        }
        let face = font.face()?;
        let scale = size / f64::from(font.units_per_em());
        let mut pen = origin;
        let mut glyphs = Vec::with_capacity(string.chars().count());
        for ch in string.chars() {
            let id =
                face.glyph_index(ch).ok_or_else(|| TextError::MissingGlyph { font: font.name().to_owned(), ch })?;
            let mut flattener = Flattener::new(scale, pen, tolerance);
            // A glyph with no outline (a space) draws nothing.
            let _ = face.outline_glyph(id, &mut flattener);
            // TrueType runs outer contours clockwise, CFF counter-clockwise: turn each glyph so its
            // outers run counter-clockwise, as a polygon clipper's output does, so a kept glyph and
            // a clipped piece that overlap add up under non-zero instead of cancelling.
            let mut shape = Polygons::new(flattener.rings);
            if shape.signed_area() < 0.0 {
                shape = Polygons::new(shape.rings.iter().map(|r| r.reversed()).collect());
            }
            let bounds = shape.bounds();
            glyphs.push(Glyph { ch, shape: Shape::Outline(shape), bounds });
            pen.x += scale * f64::from(face.glyph_hor_advance(id).unwrap_or(0));
        }
        Ok(Text::from_glyphs(glyphs))
    }

    /// Lays out `string` in the 8x8 bitmap font, each font pixel drawn as a square of
    /// `max(1, floor(size / 8))` pixels, the first cell's lower-left corner at `origin` rounded
    /// down to whole pixels. Only basic Latin characters have glyphs.
    pub fn bitmap(string: &str, size: f64, origin: Point) -> Result<Text, TextError> {
        check_common(string, size, origin)?;
        let scale = ((size / 8.0).floor() as i64).max(1);
        let (mut left, bottom) = (origin.x.floor() as i64, origin.y.floor() as i64);
        let mut glyphs = Vec::with_capacity(string.len());
        for ch in string.chars() {
            let rows = bitmap_glyph(ch)?;
            let mut pixels = Vec::new();
            for (r, bits) in rows.iter().enumerate() {
                // Row 0 is the top row of the cell.
                let j0 = bottom + (7 - r as i64) * scale;
                for c in (0..8).filter(|c| bits & (1 << c) != 0) {
                    let i0 = left + c * scale;
                    for dj in 0..scale {
                        pixels.extend((0..scale).map(|di| (i0 + di, j0 + dj)));
                    }
                }
            }
            let bounds = pixels.iter().fold(Rect::EMPTY, |b, &(i, j)| {
                b.including(Point::new(i as f64, j as f64)).including(Point::new((i + 1) as f64, (j + 1) as f64))
            });
            glyphs.push(Glyph { ch, shape: Shape::Pixels(pixels), bounds });
            left += 8 * scale;
        }
        Ok(Text::from_glyphs(glyphs))
    }

    fn from_glyphs(glyphs: Vec<Glyph>) -> Text {
        let bounds = glyphs.iter().fold(Rect::EMPTY, |b, g| if g.bounds.is_empty() { b } else { b.union(g.bounds) });
        Text { glyphs, bounds }
    }

    /// Every glyph's outline together (empty for bitmap text).
    pub fn outlines(&self) -> Polygons {
        Polygons::new(
            self.glyphs
                .iter()
                .flat_map(|g| match &g.shape {
                    Shape::Outline(p) => p.rings.clone(),
                    Shape::Pixels(_) => Vec::new(),
                })
                .collect(),
        )
    }

    /// The characters laid out.
    pub fn len(&self) -> usize {
        self.glyphs.len()
    }

    /// True when there are no glyphs (never, for a successful layout).
    pub fn is_empty(&self) -> bool {
        self.glyphs.is_empty()
    }
}
