//! The minimal enclosing box (MEB) and Cohen-Sutherland's endpoint codes against it (the paper's Fig. 2).

use clip_core::{Point, Rect};

/// Cohen-Sutherland's four-bit code of `p` against the closed box `r`: 0 inside or on it, one bit
/// per side it lies strictly beyond.
#[inline]
pub(crate) fn outcode(p: Point, r: &Rect) -> u8 {
    (p.x < r.min.x) as u8 | ((p.x > r.max.x) as u8) << 1 | ((p.y < r.min.y) as u8) << 2 | ((p.y > r.max.y) as u8) << 3
}

/// True when both ends of the segment `a b` lie strictly beyond the same side of the MEB: the
/// segment cannot touch the window. Exact (comparisons of input coordinates).
#[inline]
pub(crate) fn meb_rejects(a: Point, b: Point, meb: &Rect) -> bool {
    outcode(a, meb) & outcode(b, meb) != 0
}
