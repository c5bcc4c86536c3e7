//! Exact oracles for polygon boolean operations and line clipping.
//!
//! Give it the inputs of a clip and the answer a clipper returned, and it says whether the answer
//! is right, independent of any clipping library:
//!
//! - [`polygon`]: [`check_polygon_result`] checks one output of `subject op clip` under a fill
//!   rule: its form ([`check_form`], strict and exact: no crossing, no overlapping edges, no
//!   ring visiting a point twice, no zero-area ring, outers counter-clockwise and holes clockwise
//!   by nesting, each fault a typed [`FormFailure`] with where it is), exact membership at
//!   sample points away from every edge (exact winding numbers from `robust`'s orientation
//!   predicate), and the area of the symmetric difference between the output and the exact answer,
//!   from [`region_area`], a slab decomposition that reads only the input rings. Plus
//!   [`polygon::check_area_identities`] across the four operations, [`polygon::same_region`] for
//!   two answers, and [`polygon::bridge_count`] for Sutherland-Hodgman-style bridged output.
//! - [`line`]: [`visible_intervals`], the closed-set visible part of a segment in a window (even-odd
//!   interior, boundary included) from exact incidences, and [`check_line_batch`] for a line
//!   clipper's pieces.
//! - [`curve`]: [`curve::check_visible`] for the visible parameter intervals of a circle, ellipse
//!   or arc (samples of the curve against exact even-odd point location, interval ends on the
//!   window's boundary), [`curve::check_region`] for a clipped filled ellipse (samples of the plane
//!   against a careful point-in-ellipse test and exact location in the window, winding number of
//!   the region's arcs and segments), [`curve::check_filled_region`] the same for a clipped sector or
//!   chord region (`clip_core::FilledArc`), and [`curve::check_identities`] (spans and areas in a window
//!   and in its complement add up to the whole).
//!
//! The conventions it checks (output form, the closed-set rule, tolerances) are set out in the
//! repository's `docs/DESIGN.md`.
//!
//! # Example: testing a clipper of your own
//!
//! A deliberately wrong "clipper" that answers an intersection with the subject's bounding box:
//!
//! ```
//! use clip_core::{BoolOp, FillRule, Point, Polygons, Rect, Ring};
//! use clip_oracle::{OutputRules, PolygonFailure, REGION_TOLERANCE, check_polygon_result};
//!
//! fn my_intersection(subject: &Polygons, _clip: &Polygons) -> Polygons {
//!     Polygons::from(subject.bounds())
//! }
//!
//! let triangle = Polygons::from(Ring::new(vec![
//!     Point::new(0.0, 0.0),
//!     Point::new(10.0, 0.0),
//!     Point::new(0.0, 10.0),
//! ]));
//! let window = Polygons::from(Rect::new(-5.0, -5.0, 20.0, 20.0));
//! let rules = OutputRules::conventional(REGION_TOLERANCE);
//!
//! let out = my_intersection(&triangle, &window);
//! let verdict = check_polygon_result(&triangle, &window, BoolOp::Intersection, FillRule::NonZero, &out, &rules);
//! // The box covers points the exact intersection (the triangle) does not.
//! assert!(matches!(verdict, Err(PolygonFailure::WrongPoint { .. } | PolygonFailure::WrongRegion { .. })));
//!
//! // The right answer passes; `Ok` carries the area by which it differs from the exact region.
//! let verdict = check_polygon_result(&triangle, &window, BoolOp::Intersection, FillRule::NonZero, &triangle, &rules);
//! assert!(verdict.unwrap() <= 1e-9);
//! ```
//!
//! # Limits
//!
//! - Areas are f64 sums of trapezoids with crossing heights rounded, so the region check has a
//!   tolerance: [`REGION_TOLERANCE`] of the inputs' bounding-box area for f64 clippers,
//!   [`GEO_TOLERANCE`] for libraries that snap to a grid. Membership at sample points and the line
//!   oracle's in/out decisions are exact. Sample points within a margin of any edge are skipped, so
//!   a wrong answer thinner than the margin is caught by area only.
//! - The form check allows rings to touch at isolated points only; it is exact, so a crossing
//!   an f64 clipper made by rounding a vertex across an edge is reported like any other. It is
//!   one sweep, O((n + k) log n) for n edges and k vertices lying inside other edges.
//! - [`region_area`] costs O(s m + k log k): s distinct vertex heights, m edges crossing a typical
//!   horizontal line, k edge crossings (found as order inversions per slab). A 20-edge pair takes
//!   tens of microseconds, a 200-edge pair about half a millisecond, two 10^5-vertex blobs tens of
//!   milliseconds.

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

pub mod curve;
pub mod line;
pub mod polygon;

pub use line::{LINE_T_TOLERANCE, LineFailure, check_line_batch, visible_intervals};
pub use polygon::{
    FormFailure, GEO_TOLERANCE, OutputRules, PolygonFailure, REGION_TOLERANCE, check_form, check_polygon_result,
    region_area,
};
