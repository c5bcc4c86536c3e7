//! clip-curve: circles, ellipses and their arcs clipped against rectangle and polygon windows.
//!
//! Implements the curve clipping of *Computer Graphics, Lecture 17: Polygon Clipping* (lecture
//! notes; our copy names no author, institution or date, and its wording and figure numbers
//! appear to follow D. Hearn and M. P. Baker's *Computer Graphics*): "The bounding rectangle for a
//! circle or other curved object can be used first to test for overlap with a rectangular clip
//! window ... For a circle, we can use the coordinate extents of individual quadrants and then
//! octants for preliminary testing before calculating curve-window intersections. For an
//! ellipse, we can test the coordinate extents of individual quadrants" (Fig. 6-27 clips a filled
//! circle), and for a general polygon window the bounding rectangles first, then "the
//! simultaneous line-curve equations".
//!
//! # The lecture's vocabulary in the code
//!
//! | lecture | here |
//! | --- | --- |
//! | bounding rectangle test (save / discard the object) | [`Stage::BoxAccept`], [`Stage::BoxReject`] |
//! | coordinate extents of quadrants | [`Stage::Quadrants`]: the arcs between the points of extreme x and y (`Ellipse::extreme_parameters`), which are monotone, so the box of their ends is their extent; for a rotated ellipse these are its quadrants in that sense |
//! | ... then octants (circles) | [`Stage::Octants`]: quadrants halved at multiples of π/4 |
//! | curve-line equations | `crossings`: one `acos` per rectangle side, a stable quadratic in the ellipse's unit frame per polygon edge |
//! | clipped filled circle (Fig. 6-27) | [`PreparedCurveWindow::clip_filled`], a `clip_core::CurveRegion` |
//! | filled arcs (sectors, segments) | [`PreparedCurveWindow::clip_filled_arc`] on a `clip_core::FilledArc` |
//!
//! # Conventions and limits
//!
//! - Outlines follow the closed-set rule of the line clippers (docs/DESIGN.md): the visible part
//!   is the maximal closed parameter intervals on which the curve lies in the closed window
//!   (even-odd interior, boundary included), merged, touch points dropped. For a whole ellipse a
//!   piece through parameter 0 is one interval ending past 2π.
//! - Each arc between consecutive crossings is kept or dropped by exact point location of its
//!   rounded midpoint; crossings are f64 roots, so interval ends are exact to rounding, and a
//!   curve grazing an edge within rounding may lose a piece shorter than the rounding.
//! - Filled regions are bounded by the visible arcs and the window's even-odd boundary pieces
//!   inside the ellipse (`oriented_boundary` splits crossing rings and cancels doubled edges, so
//!   any window works), linked into loops; the area is Green's theorem over the loops: sectors
//!   plus triangles about the centre, exact to rounding.
//! - Filled arcs (`clip_core::FilledArc`: the arc closed by two radii, a sector, or by its chord,
//!   a segment) add their closing sides, clipped to the window as segments, and keep only the
//!   window pieces inside the closing half-plane or wedge; their exact unclipped area is the
//!   sector formula `rx ry sweep / 2` or the segment formula `rx ry (sweep - sin sweep) / 2`. The
//!   box test uses the filled arc's own box (the centre included for a sector); the quadrant and
//!   octant tests apply to its arc. A closing side lying along a window edge is kept once when
//!   the window is on the region's side and dropped when it is beyond (exact tests on the
//!   rounded midpoint).
//! - [`flatten_region`] gives `Polygons` within a tolerance (inscribed chords); its area is
//!   within [`flattening_area_bound`] of the exact one.
//! - Bad input is a `clip_core::ClipError`: radii not positive, non-finite parameters, sweeps
//!   outside (0, 2π], empty sweeps of filled arcs (all refused when the `Ellipse` / `EllipseArc`
//!   is built, so every `FilledArc` is valid), degenerate
//!   windows, tolerances not positive or too fine. Nothing panics.
//!
//! # Example
//!
//! ```
//! use clip_core::{Ellipse, EllipseArc, Point, Polygons, Rect};
//! use clip_curve::{CurveClipper, Stage};
//!
//! let window = Polygons::from(Rect::new(0.0, 0.0, 100.0, 100.0));
//! let prepared = CurveClipper::WITH_TESTS.prepare(&window).unwrap();
//! // A circle near the window's corner, outside it: its octants settle it without equations.
//! let c = Ellipse::circle(Point::new(108.0, 108.0), 10.0).unwrap();
//! let seen = prepared.visible(&EllipseArc::full(c));
//! assert_eq!(seen.stage, Stage::Octants);
//! assert!(seen.intervals.is_empty());
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod boundary_edges;
mod clipper;
mod crossings;
mod filled_arc;
mod flatten;
mod outline;
mod preliminary;
mod region;
mod window;

pub use boundary_edges::oriented_boundary;
pub use clipper::{CurveClipper, PreparedCurveWindow};
pub use flatten::{
    MAX_FLATTEN_VERTICES, check_tolerance, flatten_arc, flatten_ellipse, flatten_filled_arc, flatten_intervals,
    flatten_region, flattening_area_bound,
};
pub use outline::{ANGLE_SNAP, Visible};
pub use preliminary::Stage;
pub use region::Clipped;
pub use window::CurveWindow;
