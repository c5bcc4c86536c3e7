//! The window's rings in one flat vertex array, each closed by repeating its first vertex, and its box.

use core::ops::Range;

use clip_core::{Point, Polygons, Rect, Segment};

/// A window laid out for the per-segment loops: every vertex of every ring in one contiguous
/// array, each ring followed by a copy of its first vertex so that edge `i` is always
/// `points[i] -> points[i + 1]` with no wrap-around.
#[derive(Clone, Debug)]
pub(crate) struct RingTable {
    /// The vertices, ring after ring, each ring closed by a repeat of its first vertex.
    pub points: Vec<Point>,
    /// For each ring, the indices of its edges' first vertices.
    pub rings: Vec<Range<usize>>,
    /// The window's bounding box (the paper's MEB).
    pub bounds: Rect,
}

impl RingTable {
    /// Lays out already validated rings, dropping consecutive repeated vertices.
    pub fn new(window: &Polygons) -> RingTable {
        let mut points = Vec::with_capacity(window.vertex_count() + window.rings.len());
        let mut rings = Vec::with_capacity(window.rings.len());
        for ring in &window.rings {
            let ring = ring.without_repeats();
            let start = points.len();
            points.extend_from_slice(&ring.points);
            points.push(ring.points[0]);
            rings.push(start..points.len() - 1);
        }
        RingTable { points, rings, bounds: window.bounds() }
    }

    /// True when both ends of `s` lie strictly beyond the same side of the bounding box
    /// (Cohen-Sutherland's trivial reject): then `s` cannot touch the window.
    #[inline]
    pub fn misses_bounds(&self, s: Segment) -> bool {
        outcode(s.a, &self.bounds) & outcode(s.b, &self.bounds) != 0
    }
}

/// Cohen-Sutherland's four-bit code of `p` against the closed box `r` (0 inside or on it).
#[inline]
pub(crate) fn outcode(p: Point, r: &Rect) -> u8 {
    (p.x < r.min.x) as u8 | ((p.x > r.max.x) as u8) << 1 | ((p.y < r.min.y) as u8) << 2 | ((p.y > r.max.y) as u8) << 3
}
