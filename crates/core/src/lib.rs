//! clip-core: the shared vocabulary of clipbench.
//!
//! Points, segments, rings and polygon sets; circles, ellipses and their arcs ([`Ellipse`],
//! [`EllipseArc`]), filled arcs closed as sectors or chords ([`FilledArc`]) and the regions a
//! clipped filled ellipse or arc leaves ([`CurveRegion`]); the boolean
//! operations and fill rules; one module of exact predicates (Shewchuk's adaptive arithmetic
//! through the `robust` crate) through which every orientation and in/out decision goes; typed
//! errors for bad input; and the
//! [`PolygonClipper`], [`LineClipper`] and [`PreparedWindow`] traits the harness registers
//! clippers behind. Conventions (output orientation, the closed-set rule for lines) are set out
//! in the repository's `docs/DESIGN.md` and are restated where each applies.
//!
//! Coordinates are f64 with `y` up; counter-clockwise is positive. Magnitudes from
//! [`MIN_COORDINATE`] up to [`MAX_COORDINATE`], and zero, are accepted.
//!
//! # Limits
//!
//! The predicates are exact, but points this crate computes (segment crossings, points along a
//! segment) are rounded to f64. Coordinates beyond [`MAX_COORDINATE`], non-zero ones below
//! [`MIN_COORDINATE`] (where products of differences would underflow), NaN and infinities are
//! refused by the `validate_*` functions with a [`ClipError`]. No clipping algorithm lives here:
//! the clippers are in their own crates.
//!
//! ```
//! use clip_core::{FillRule, Location, Point, Polygons, Rect, locate, orient, Orientation};
//!
//! let square = Polygons::from(Rect::new(0.0, 0.0, 2.0, 2.0));
//! assert_eq!(square.signed_area(), 4.0);
//! assert_eq!(locate(Point::new(1.0, 1.0), &square, FillRule::NonZero), Location::Inside);
//! assert_eq!(locate(Point::new(2.0, 1.0), &square, FillRule::NonZero), Location::Boundary);
//!
//! // Exact where naive f64 arithmetic is not: these three points are not collinear.
//! let (a, b) = (Point::new(0.5, 0.5), Point::new(12.0, 12.0));
//! let c = Point::new(24.0, 24.0 + 2f64.powi(-48));
//! assert_eq!(orient(a, b, c), Orientation::CounterClockwise);
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod area;
mod batch_filter;
mod cell_index;
mod clipper;
mod curve_region;
mod double_double;
mod ellipse;
mod error;
mod filled_arc;
#[cfg(feature = "geo")]
mod geo;
mod line_crossings;
mod line_frame;
mod near_edges;
mod nesting;
mod ops;
mod point;
mod polygons;
pub mod predicates;
mod rect;
mod ring;
mod segment;
mod snap_rounding;
mod trapezoid;
mod vertex_snapping;
mod winding;
mod window_rings;

pub use area::{runs_counter_clockwise, signed_area};
pub use batch_filter::retain_indices;
pub use cell_index::{CellIndex, power_of_two_at_least};
pub use clipper::{
    LineCapabilities, LineClipper, OutputForm, PolygonCapabilities, PolygonClipper, PreparedWindow, VisiblePiece,
    WindowKind,
};
pub use curve_region::{BoundaryPiece, CurveRegion};
pub use ellipse::{Ellipse, EllipseArc, MIN_AXIS_RATIO, MIN_RADIUS_TO_CENTRE};
pub use error::{
    ClipError, FailureKind, MAX_COORDINATE, MIN_COORDINATE, Operand, convex_window, rect_window, validate_polygons,
    validate_ring, validate_segments, validate_window, window_covers,
};
pub use filled_arc::{ArcFill, FilledArc};
pub use line_crossings::{LineCrossings, PARAMETER_SNAP};
pub use line_frame::{Along, LineFrame};
pub use near_edges::NearEdges;
pub use nesting::{NestedPolygon, nest};
pub use ops::{BoolOp, FillRule, UnknownName};
pub use point::Point;
pub use polygons::Polygons;
pub use predicates::{LineSide, Orientation, SegmentIntersection, orient, segment_intersection};
pub use rect::Rect;
pub use ring::Ring;
pub use segment::{FAR_REACH, Segment};
pub use snap_rounding::{snap_round, snap_round_near};
pub use trapezoid::Trapezoid;
pub use vertex_snapping::snap_edges_to_vertices;
pub use winding::{Location, edge_winding, locate, ring_winding, winding_number};
pub use window_rings::WindowRings;
