//! A window's rings in one flat vertex array, each closed by repeating its first vertex.

use core::ops::Range;

use crate::{Point, Polygons};

/// A window laid out for per-segment loops: every vertex of every ring in one contiguous array,
/// each ring followed by a copy of its first vertex, so edge `i` of a ring is always
/// `points[i] -> points[i + 1]` with no wrap-around. Consecutive repeated vertices are dropped.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct WindowRings {
    /// The vertices, ring after ring, each ring closed by a repeat of its first vertex.
    pub points: Vec<Point>,
    /// For each ring, the indices of its edges' first vertices.
    pub rings: Vec<Range<usize>>,
}

impl WindowRings {
    /// Lays out already validated rings (each with at least one vertex).
    pub fn new(window: &Polygons) -> WindowRings {
        let mut points = Vec::with_capacity(window.vertex_count() + window.rings.len());
        let mut rings = Vec::with_capacity(window.rings.len());
        for ring in &window.rings {
            let ring = ring.without_repeats();
            let start = points.len();
            points.extend_from_slice(&ring.points);
            points.push(ring.points[0]);
            rings.push(start..points.len() - 1);
        }
        WindowRings { points, rings }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Rect, Ring};

    #[test]
    fn closes_each_ring_and_drops_repeats() {
        let square = Rect::new(0.0, 0.0, 1.0, 1.0).to_ring();
        let tri =
            Ring::new(vec![Point::new(5.0, 5.0), Point::new(6.0, 5.0), Point::new(6.0, 5.0), Point::new(5.0, 6.0)]);
        let w = WindowRings::new(&Polygons::new(vec![square.clone(), tri]));
        assert_eq!(w.rings, vec![0..4, 5..8]);
        assert_eq!(w.points.len(), 9);
        assert_eq!(w.points[4], square.points[0]);
        assert_eq!(w.points[8], Point::new(5.0, 5.0));
    }
}
