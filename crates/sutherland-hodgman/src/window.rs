//! The convex window, validated and prepared as one boundary per edge; it describes the window and clips nothing.

use clip_core::predicates::{Orientation, orient};
use clip_core::{ClipError, Point, Polygons, convex_window};

use crate::NAME;
use crate::boundary::Boundary;

/// A convex window, walked counter-clockwise, one [`Boundary`] per edge (collinear vertices
/// dropped, so no two boundaries share a line).
#[derive(Clone, Debug, PartialEq)]
pub struct ConvexWindow {
    boundaries: Vec<Boundary>,
}

impl ConvexWindow {
    /// Prepares `window`: one convex ring of either orientation. A window that is not convex,
    /// has several rings or encloses no area is an error.
    pub fn new(window: &Polygons) -> Result<ConvexWindow, ClipError> {
        let (ring, orientation) = convex_window(window, NAME)?;
        let ring = if orientation == Orientation::Clockwise { ring.reversed() } else { ring };
        let pts = &ring.points;
        let n = pts.len();
        let corners: Vec<Point> = (0..n)
            .filter(|&i| orient(pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n]) != Orientation::Collinear)
            .map(|i| pts[i])
            .collect();
        let m = corners.len();
        let boundaries = (0..m).map(|i| Boundary { from: corners[i], to: corners[(i + 1) % m] }).collect();
        Ok(ConvexWindow { boundaries })
    }

    /// The boundaries in counter-clockwise order.
    pub fn boundaries(&self) -> &[Boundary] {
        &self.boundaries
    }
}
