//! The window's rings in one flat vertex array, each closed by repeating its first vertex, and its box.

use core::ops::Range;

use clip_core::{Point, Polygons, Rect, Segment, WindowRings};

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
        let WindowRings { points, rings } = WindowRings::new(window);
        RingTable { points, rings, bounds: window.bounds() }
    }

    /// True when both ends of `s` lie strictly beyond the same side of the bounding box
    /// (Cohen-Sutherland's trivial reject): then `s` cannot touch the window.
    #[inline]
    pub fn misses_bounds(&self, s: Segment) -> bool {
        self.bounds.rejects_segment(s.a, s.b)
    }
}
