//! `SutherlandHodgman` behind clip-core's `PolygonClipper` trait.

use clip_core::{
    BoolOp, ClipError, FillRule, Operand, PolygonCapabilities, PolygonClipper, Polygons, WindowKind, validate_polygons,
    window_covers,
};

use crate::window::ConvexWindow;
use crate::{Form, NAME};

/// Sutherland-Hodgman reentrant clipping of any subject against a convex window
/// (intersection only), registered as `sutherland-hodgman`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SutherlandHodgman {
    /// Which of the two equivalent forms runs.
    pub form: Form,
}

impl SutherlandHodgman {
    /// The clipper running the given form.
    pub fn new(form: Form) -> SutherlandHodgman {
        SutherlandHodgman { form }
    }

    /// Clips and also returns how many zero-width bridges the output holds
    /// (see [`crate::bridge_count`]).
    pub fn clip_counting_bridges(&self, subject: &Polygons, clip: &Polygons) -> Result<(Polygons, usize), ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        let window = ConvexWindow::new(clip)?;
        Ok((window.clip(subject, self.form), crate::bridge_count(subject, &window)))
    }
}

impl PolygonClipper for SutherlandHodgman {
    fn name(&self) -> &'static str {
        NAME
    }

    fn capabilities(&self) -> PolygonCapabilities {
        PolygonCapabilities::window_clipper(WindowKind::Convex)
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        self.capabilities().check(NAME, op, fill)?;
        validate_polygons(subject, Operand::Subject)?;
        let window = ConvexWindow::new(clip)?;
        // Any fill rule: clipping to half-planes keeps every winding number inside the window, so
        // the output read under `fill` is the subject read under `fill`, within the window.
        if !window_covers(clip, fill) {
            return Ok(Polygons::empty());
        }
        Ok(window.clip(subject, self.form))
    }
}
