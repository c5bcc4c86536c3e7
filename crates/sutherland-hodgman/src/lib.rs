//! clip-sutherland-hodgman: Sutherland-Hodgman reentrant polygon clipping against a convex window.
//!
//! I. E. Sutherland and G. W. Hodgman, *Reentrant polygon clipping*, Communications of the ACM
//! 17(1):32-42, 1974, as described in the lecture notes *Computer Graphics, Lecture 17: Polygon
//! Clipping* (section "Sutherland-Hodgeman Polygon Clipping"; the notes name no author,
//! institution or date): the subject's vertex list is clipped against each window boundary in
//! turn, by the four vertex cases. Both forms the notes describe are here and give identical
//! vertices:
//!
//! - the **list form** ([`Form::List`], [`clip_list`]): a whole new vertex list per boundary;
//! - the **pipeline form** ([`Form::Pipeline`], [`Pipeline`]): each vertex goes through the
//!   boundary stages one at a time, no intermediate lists; a point reaches the output only once
//!   every stage has found it "inside or on" its boundary.
//!
//! # Vocabulary
//!
//! | notes | code |
//! |---|---|
//! | window boundary, boundary clipper | [`Boundary`], one stage of [`clip_list`] / [`Pipeline`] |
//! | inside / outside the boundary | [`Boundary::side`] (exact sign, [`Side`]) |
//! | edge intersection with the boundary | [`Boundary::crossing`] |
//! | the four cases (out→in, in→in, in→out, out→out) | `stage::step` |
//! | output vertex list | the returned `Vec<Point>`, one per subject ring |
//! | extraneous lines of a concave subject | bridges, counted by [`bridge_count`] |
//! | "check the final vertex list ... and correctly join pairs of vertices" | [`Joins::Split`] |
//!
//! # Limits and behaviour
//!
//! - Intersection only; the window must be one convex ring, either orientation, any number of
//!   edges ([`ClipError::WindowNotConvex`](clip_core::ClipError::WindowNotConvex) otherwise, a
//!   degenerate window is [`ClipError::DegenerateWindow`](clip_core::ClipError::DegenerateWindow)).
//! - Every subject ring is clipped separately and keeps its orientation. Clipping a closed curve
//!   to a half-plane replaces each excursion outside by a segment of the boundary line, which
//!   does not change the winding number of any point inside the window. So the output, read under
//!   the *input's* fill rule, is the intersection under that rule, for all four rules (even-odd,
//!   non-zero, positive, negative). It is not the conventional output of `docs/DESIGN.md`: rings
//!   may overlap.
//!   The window is read under the same rule: under positive a clockwise window covers nothing
//!   (and under negative a counter-clockwise one), so the result is then empty.
//! - The known defect is kept, not hidden: when a concave subject's part inside the window falls
//!   apart, the single output list joins the pieces by zero-width **bridges** along the window.
//!   They enclose no area, so the harness compares the output by region;
//!   [`bridge_count`] (or [`SutherlandHodgman::clip_counting_bridges`]) says how many there are.
//! - The notes' fix is the split mode ([`SutherlandHodgman::SPLIT`], [`Joins::Split`], registered
//!   as `sutherland-hodgman-split`): every list is cut where it runs along the window and the
//!   pieces of all lists are rejoined in pairs along the window boundary, so a hole the window
//!   cuts becomes a notch in its outer. Winding numbers inside the window are kept exactly, so the
//!   output is the same region under every fill rule; when the subject is in conventional form
//!   (simple rings that do not cross, outers counter-clockwise, holes clockwise) the output is
//!   conventional too. A subject that crosses itself gives rings that may cross: the split mode
//!   removes bridges, it does not resolve crossings. It runs the list form; it costs a sort of the
//!   pieces' ends along the window on top of the clip.
//! - Decisions are exact (`orient2d`, Shewchuk's predicates). A point exactly on a boundary is
//!   inside and is its own crossing (no repeated vertex). A crossing is computed from the edge's
//!   endpoints in a canonical order, so an edge gives the same point whichever way it is walked;
//!   it is rounded, so it may lie a few ulps off a slanted boundary. Rings that end up with no
//!   area are dropped.
//!
//! # Example
//!
//! ```
//! use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons, Rect, Ring};
//! use clip_sutherland_hodgman::{ConvexWindow, Form, SutherlandHodgman, bridge_count};
//!
//! // A U opening upwards; the window keeps the tops of both arms, which SH joins by a bridge.
//! let u = Ring::from(&[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)][..]);
//! let subject = Polygons::from(u);
//! let window = Polygons::from(Rect::new(-1.0, 2.0, 4.0, 4.0));
//!
//! let out = SutherlandHodgman::default().clip(&subject, &window, BoolOp::Intersection, FillRule::NonZero).unwrap();
//! assert_eq!(out.rings.len(), 1);
//! assert_eq!(out.signed_area(), 2.0); // two 1x1 arm tops; the bridge adds no area
//! assert_eq!(bridge_count(&subject, &ConvexWindow::new(&window).unwrap()), 1);
//!
//! let piped = SutherlandHodgman::new(Form::Pipeline).clip(&subject, &window, BoolOp::Intersection, FillRule::NonZero);
//! assert_eq!(piped.unwrap(), out);
//!
//! // The split mode returns the two arm tops as two rings, with no bridge.
//! let split = SutherlandHodgman::SPLIT.clip(&subject, &window, BoolOp::Intersection, FillRule::NonZero).unwrap();
//! assert_eq!(split.rings.len(), 2);
//! assert_eq!(split.signed_area(), 2.0);
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod boundary;
mod bridges;
mod clipper;
mod list_form;
mod pipeline;
mod split;
mod stage;
mod vertex;
mod window;

pub use boundary::{Boundary, Side};
pub use bridges::bridge_count;
pub use clipper::SutherlandHodgman;
pub use list_form::clip_list;
pub use pipeline::Pipeline;
pub use vertex::{StageVertex, TaggedVertex};
pub use window::ConvexWindow;

/// The registry name.
pub const NAME: &str = "sutherland-hodgman";

/// The registry name of the split mode ([`SutherlandHodgman::SPLIT`]).
pub const SPLIT_NAME: &str = "sutherland-hodgman-split";

/// What becomes of an output list whose part inside the window falls apart.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Joins {
    /// Kept as one list, its pieces joined by zero-width bridges along the window (the
    /// algorithm as published; output read under the input's fill rule).
    #[default]
    Bridged,
    /// The notes' fix: every list is cut where it runs along the window, and the pieces of all
    /// lists are rejoined in pairs along the window boundary into separate rings. No bridges;
    /// winding numbers are kept, so the output is read under the input's fill rule, and it is
    /// conventional output when the subject is in conventional form.
    Split,
}

/// Which of the notes' two forms of the algorithm runs. Both give the same vertices.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Form {
    /// Clip the whole vertex list against one boundary, then the next.
    #[default]
    List,
    /// Pass each vertex through the boundary stages, keeping no intermediate lists.
    Pipeline,
}
