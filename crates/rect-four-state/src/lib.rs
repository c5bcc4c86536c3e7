//! clip-rect-four-state: the four-state point-splitting polygon clipper for rectangle windows.
//!
//! The algorithm of *Polygon Clipping Algorithm* (a short undated text that names no author or
//! institution), as written: one walk over a cyclic point list; each point is checked against four
//! states (MinY, MaxY, MinX, MaxX), one clip condition each. A point outside the current condition
//! is divided into two points at the same place; each is removed when its next point (the previous
//! list point for the first, the following one for the second) is outside too, and otherwise moved
//! along the line towards that next point onto the boundary. After a move the walk goes on with the
//! other pair of states (horizontal after vertical and vice versa); after two removals it restarts
//! at state one with the point that is now current; a point inside all four states is done and the
//! walk takes the next one.
//!
//! # Vocabulary
//!
//! | paper | code |
//! |---|---|
//! | states one to four, clip conditions | [`State`], [`State::inside`] |
//! | current clip region | the [`State`] being tried |
//! | divide a point into (2a) and (2b) | [`Event::Divide`] |
//! | remove / move the current point | [`Event::Remove`], [`Event::Move`] |
//! | trace equations 1.4 and 2.4 | [`State::move_towards`] |
//! | cyclic list of connected points | [`clip_points`] |
//!
//! # Where the walk starts (the one change to the paper)
//!
//! As written, the walk takes the list's first point first. When that point is outside, its
//! previous point (the list's last) is not processed yet; near a corner, with both neighbours
//! outside, the point's halves then slide back and forth between the two sides towards the
//! corner, for ever ([`walk_as_written`] shows it, with a step limit). So the walk starts at a
//! vertex inside the rectangle (rotating a cyclic list changes nothing); if there is none, at a
//! point where an edge meets the rectangle (decided exactly), inserted into that edge; if no edge
//! meets the rectangle, the winding number is the same all over it and the answer is the
//! rectangle traced that many times, or nothing. From an inside start every point's previous
//! point is finished when the point is taken, and the walk always ends. A consequence: the first
//! half of a divided point is never removed then, so the "both removed, restart at state one"
//! rule only fires in [`walk_as_written`].
//!
//! # Limits and where the output differs from a true intersection
//!
//! - Intersection only; the window must be an axis-aligned rectangle
//!   ([`ClipError::WindowNotRectangle`](clip_core::ClipError::WindowNotRectangle) otherwise).
//! - Each subject ring gives at most one output ring, in its input orientation. When the part of a
//!   concave ring inside the rectangle falls apart, the pieces stay connected by zero-width
//!   **bridges** along the rectangle's sides, exactly like Sutherland-Hodgman's: the output covers
//!   the right region (read under the input's fill rule, any of the four, since winding numbers
//!   inside the rectangle are unchanged) but is not the conventional output of `docs/DESIGN.md`, so
//!   it is compared by region. An edge that cuts across a corner outside the rectangle becomes a
//!   path through that corner, as it should. The rectangle is read under the same rule: under
//!   positive a clockwise rectangle covers nothing (under negative a counter-clockwise one).
//! - Decisions compare coordinates with the boundary values (exact). Moved points come from the
//!   paper's trace equations in f64, clamped between the two points; a move onto a next point
//!   that already lies on the boundary yields that point exactly. Repeated vertices are removed
//!   and rings left without area are dropped.
//!
//! # Example
//!
//! ```
//! use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons, Rect, Ring};
//! use clip_rect_four_state::FourState;
//!
//! // A triangle whose apex sticks out above the window.
//! let subject = Polygons::from(Ring::from(&[(1.0, 1.0), (5.0, 1.0), (3.0, 5.0)][..]));
//! let window = Polygons::from(Rect::new(0.0, 0.0, 6.0, 3.0));
//! let out = FourState.clip(&subject, &window, BoolOp::Intersection, FillRule::NonZero).unwrap();
//! // The apex (3, 5) was divided and both halves moved down their edges onto y = 3.
//! assert_eq!(out.rings[0].points, vec![
//!     clip_core::Point::new(1.0, 1.0),
//!     clip_core::Point::new(5.0, 1.0),
//!     clip_core::Point::new(4.0, 3.0),
//!     clip_core::Point::new(2.0, 3.0),
//! ]);
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod clipper;
mod point_list;
mod start;
mod state;

pub use clipper::FourState;
pub use point_list::{Event, clip_points, clip_points_observed, walk_as_written};
pub use state::State;

/// The registry name.
pub const NAME: &str = "rect-four-state";
