//! The text timing workload: a paragraph of the lecture notes' own text and centred windows that
//! shrink over it, from holding all of it to a small part.

use clip_core::{Point, Polygons, Rect};

/// The paragraph's lines, top to bottom.
pub const PARAGRAPH_LINES: [&str; 6] = [
    "There are several techniques that can be used",
    "to provide text clipping in a graphics package.",
    "The simplest method is all-or-none string",
    "clipping; an alternative is all-or-none",
    "character clipping; a final method clips the",
    "components of individual characters (6-30).",
];

/// Pixels per em of the paragraph's text.
pub const PARAGRAPH_SIZE: f64 = 24.0;

/// Distance between baselines, pixels.
pub const PARAGRAPH_LEADING: f64 = 30.0;

/// The window sides as fractions of the paragraph box's, largest first: 1.05 holds it all.
pub const PARAGRAPH_WINDOW_SIDES: [f64; 7] = [1.05, 0.9, 0.75, 0.6, 0.45, 0.3, 0.15];

/// Where line `k`'s baseline starts (y up, the first line on top, all of it in `x, y > 0`).
pub fn paragraph_origin(k: usize) -> Point {
    Point::new(20.0, 20.0 + PARAGRAPH_LEADING * (PARAGRAPH_LINES.len() - k) as f64)
}

/// Characters in the paragraph.
pub fn paragraph_chars() -> usize {
    PARAGRAPH_LINES.iter().map(|l| l.chars().count()).sum()
}

/// The window centred on the paragraph's box `bounds` with sides `side` times the box's.
pub fn paragraph_window(bounds: &Rect, side: f64) -> Polygons {
    let c = Point::new(0.5 * (bounds.min.x + bounds.max.x), 0.5 * (bounds.min.y + bounds.max.y));
    let (hw, hh) = (0.5 * side * bounds.width(), 0.5 * side * bounds.height());
    Polygons::from(Rect::new(c.x - hw, c.y - hh, c.x + hw, c.y + hh))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn windows_shrink_about_the_centre() {
        let b = Rect::new(0.0, 0.0, 100.0, 50.0);
        let big = paragraph_window(&b, PARAGRAPH_WINDOW_SIDES[0]).bounds();
        assert!(big.contains_rect(&b));
        let small = paragraph_window(&b, 0.5).bounds();
        assert_eq!(small, Rect::new(25.0, 12.5, 75.0, 37.5));
        assert!(paragraph_origin(PARAGRAPH_LINES.len() - 1).y < paragraph_origin(0).y);
        assert_eq!(paragraph_chars(), PARAGRAPH_LINES.iter().map(|l| l.len()).sum::<usize>());
    }
}
