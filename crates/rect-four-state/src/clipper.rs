//! `FourState` behind clip-core's `PolygonClipper` trait.

use clip_core::predicates::{Orientation, orient};
use clip_core::{
    BoolOp, ClipError, FillRule, Operand, PolygonCapabilities, PolygonClipper, Polygons, Rect, Ring, WindowKind,
    rect_window, validate_polygons, window_covers,
};

use crate::NAME;
use crate::point_list::clip_points;

/// The four-state point-splitting clipper, registered as `rect-four-state`: intersection of any
/// subject with an axis-aligned rectangle.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FourState;

impl FourState {
    /// Clips every ring of `subject` to `rect` and keeps the rings that still enclose area, each
    /// in its input orientation.
    pub fn clip_to_rect(&self, subject: &Polygons, rect: &Rect) -> Polygons {
        let rings = subject.rings.iter().filter_map(|r| encloses_area(Ring::new(clip_points(&r.points, rect))));
        Polygons::new(rings.collect())
    }
}

impl PolygonClipper for FourState {
    fn name(&self) -> &'static str {
        NAME
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities::window_clipper(WindowKind::Rectangle)
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        self.capabilities().check(NAME, op, fill)?;
        validate_polygons(subject, Operand::Subject)?;
        let rect = rect_window(clip, NAME)?;
        // Any fill rule: like Sutherland-Hodgman, the walk replaces what lies outside a boundary
        // by pieces of that boundary, which keeps every winding number inside the rectangle.
        if !window_covers(clip, fill) {
            return Ok(Polygons::empty());
        }
        Ok(self.clip_to_rect(subject, &rect))
    }
}

/// The ring without repeated vertices, or `None` when what is left is a point or a line.
fn encloses_area(ring: Ring) -> Option<Ring> {
    let ring = ring.without_repeats();
    let pts = &ring.points;
    let &first = pts.first()?;
    let second = pts.iter().copied().find(|&p| p != first)?;
    pts.iter().any(|&p| orient(first, second, p) != Orientation::Collinear).then_some(ring)
}
