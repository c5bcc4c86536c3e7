//! `SutherlandHodgman` behind clip-core's `PolygonClipper` trait: runs the chosen form on each ring.

use clip_core::predicates::{Orientation, orient};
use clip_core::{
    BoolOp, ClipError, FillRule, Operand, OutputForm, Point, PolygonCapabilities, PolygonClipper, Polygons, Ring,
    WindowKind, validate_polygons, window_covers,
};

use crate::bridges::bridge_count;
use crate::list_form::clip_list;
use crate::pipeline::Pipeline;
use crate::split::clip_split;
use crate::window::ConvexWindow;
use crate::{Form, Joins, NAME, SPLIT_NAME};

/// Sutherland-Hodgman reentrant clipping of any subject against a convex window
/// (intersection only), registered as `sutherland-hodgman`, or with its pieces rejoined along the
/// window as `sutherland-hodgman-split` ([`SutherlandHodgman::SPLIT`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SutherlandHodgman {
    /// Which of the two equivalent forms runs (the split mode always runs the list form).
    pub form: Form,
    /// Whether the output lists keep their bridges or are split into separate rings.
    pub joins: Joins,
}

impl SutherlandHodgman {
    /// The split mode: output lists cut at the window and rejoined into separate rings.
    pub const SPLIT: SutherlandHodgman = SutherlandHodgman { form: Form::List, joins: Joins::Split };

    /// The clipper running the given form, keeping the bridges.
    pub fn new(form: Form) -> SutherlandHodgman {
        SutherlandHodgman { form, joins: Joins::Bridged }
    }

    /// Clips and also returns how many zero-width bridges Sutherland-Hodgman's lists hold
    /// (see [`crate::bridge_count`]): those in the output, or in the split mode those it removed.
    pub fn clip_counting_bridges(&self, subject: &Polygons, clip: &Polygons) -> Result<(Polygons, usize), ClipError> {
        validate_polygons(subject, Operand::Subject)?;
        let window = ConvexWindow::new(clip)?;
        Ok((self.clip_rings(subject, &window), bridge_count(subject, &window)))
    }

    /// Clips every ring of `subject` separately and keeps the rings that still enclose area,
    /// each in its input orientation (so winding numbers inside the window are unchanged); in
    /// the split mode, rejoins the pieces along the window (winding numbers still unchanged).
    fn clip_rings(&self, subject: &Polygons, window: &ConvexWindow) -> Polygons {
        if self.joins == Joins::Split {
            return clip_split(subject, window, encloses_area);
        }
        let rings =
            subject.rings.iter().filter_map(|r| encloses_area(Ring::new(clip_ring(r, window, self.form)))).collect();
        Polygons::new(rings)
    }
}

impl PolygonClipper for SutherlandHodgman {
    fn name(&self) -> &'static str {
        match self.joins {
            Joins::Bridged => NAME,
            Joins::Split => SPLIT_NAME,
        }
    }

    fn capabilities(&self) -> PolygonCapabilities {
        let window_clipper = PolygonCapabilities::window_clipper(WindowKind::Convex);
        match self.joins {
            Joins::Bridged => window_clipper,
            Joins::Split => PolygonCapabilities {
                bridges: false,
                output: OutputForm::ConventionalForConventionalSubject,
                ..window_clipper
            },
        }
    }

    fn clip(&self, subject: &Polygons, clip: &Polygons, op: BoolOp, fill: FillRule) -> Result<Polygons, ClipError> {
        self.capabilities().check(self.name(), op, fill)?;
        validate_polygons(subject, Operand::Subject)?;
        let window = ConvexWindow::new(clip)?;
        // Any fill rule: clipping to half-planes keeps every winding number inside the window, so
        // the output read under `fill` is the subject read under `fill`, within the window.
        if !window_covers(clip, fill) {
            return Ok(Polygons::empty());
        }
        Ok(self.clip_rings(subject, &window))
    }
}

/// Clips one ring's vertices with `form`; the result may be empty and may hold bridges.
fn clip_ring(ring: &Ring, window: &ConvexWindow, form: Form) -> Vec<Point> {
    match form {
        Form::List => clip_list(&ring.points, window),
        Form::Pipeline => {
            let mut pipeline = Pipeline::new(window);
            ring.points.iter().for_each(|&p| pipeline.push(p));
            pipeline.finish()
        }
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
