//! The convex window prepared as a list of boundaries, and the clipping of whole polygon sets.

use clip_core::predicates::{Orientation, orient};
use clip_core::{ClipError, Point, Polygons, Ring, convex_window};

use crate::boundary::Boundary;
use crate::list_form::clip_list;
use crate::pipeline::Pipeline;
use crate::{Form, NAME};

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

    /// Clips one ring's vertices; the result may be empty and may hold bridges.
    pub fn clip_ring(&self, ring: &Ring, form: Form) -> Vec<Point> {
        match form {
            Form::List => clip_list(&ring.points, self),
            Form::Pipeline => {
                let mut pipeline = Pipeline::new(self);
                ring.points.iter().for_each(|&p| pipeline.push(p));
                pipeline.finish()
            }
        }
    }

    /// Clips every ring of `subject` separately and keeps the rings that still enclose area,
    /// each in its input orientation (so winding numbers inside the window are unchanged).
    pub fn clip(&self, subject: &Polygons, form: Form) -> Polygons {
        let rings = subject.rings.iter().filter_map(|r| encloses_area(Ring::new(self.clip_ring(r, form)))).collect();
        Polygons::new(rings)
    }
}

/// The ring without repeated vertices, or `None` when what is left is a point or a line.
pub(crate) fn encloses_area(ring: Ring) -> Option<Ring> {
    let ring = ring.without_repeats();
    let pts = &ring.points;
    let &first = pts.first()?;
    let second = pts.iter().copied().find(|&p| p != first)?;
    pts.iter().any(|&p| orient(first, second, p) != Orientation::Collinear).then_some(ring)
}
