//! clip-clipper2-rect: Clipper2's dedicated rectangle clipper (`RectClip`) as a peer.
//!
//! Sutherland-Hodgman (I. E. Sutherland and G. W. Hodgman, *Reentrant polygon clipping*,
//! Communications of the ACM 17(1):32-42, 1974) and the four-state clipper (*Polygon Clipping
//! Algorithm*, a text that names no author) clip polygons to a rectangle; the modern
//! library routine for the same job is Angus Johnson's `RectClip` in Clipper2
//! (`clipper.rectclip.cpp`), much faster than Clipper2's general boolean engine. The `clipper2`
//! 0.6 crate does not bind it; its C layer `clipper2c-sys` compiles and links it. This crate
//! wraps that C function in [`Clipper2RectClipper`], a [`clip_core::PolygonClipper`], so the
//! harness's `verify` and the window clippers' benches can put the two papers' algorithms
//! next to it, and its line counterpart `RectClipLines` in [`Clipper2RectLines`], a
//! [`clip_core::LineClipper`] for rectangle windows. The general engine's open-path clipping
//! (`Clipper64` with `AddOpenSubject`), which the `clipper2` crate does not return, is the line
//! peer [`Clipper2OpenLines`] for any window.
//!
//! # Why a crate of its own
//!
//! Calling C needs `unsafe`, which the workspace forbids (`forbid` cannot be lowered by
//! `allow`). This crate does not take the workspace lints; it has the same ones with unsafe code
//! *denied*, and allows it only in the private `ffi` module, where every unsafe block says why it
//! is sound and every C++ object allocated is deleted by an owner's `Drop`.
//!
//! # Vocabulary
//!
//! | Clipper2 | code |
//! |---|---|
//! | `Rect64 {left, top, right, bottom}` (`top` is the smaller y) | [`clip_core::Rect`] `min`, `max` |
//! | `Path64`, `Paths64` on `int64` points | [`clip_core::Ring`], [`clip_core::Polygons`] on an [`IntegerGrid`] |
//! | `RectClip(rect, paths)` | [`Clipper2RectClipper::clip_to_rect`] |
//! | `RectClipLines(rect, paths)` | the window [`Clipper2RectLines`] prepares |
//!
//! # Limits and where the output differs from a true intersection
//!
//! - Intersection only; the window must be one axis-aligned rectangle
//!   ([`ClipError::WindowNotRectangle`](clip_core::ClipError::WindowNotRectangle) otherwise),
//!   and bad subjects get clip-core's typed errors (non-finite, out of range, too few points).
//! - `RectClip` clips each ring on its own and keeps its orientation, so overlapping rings stay
//!   overlapping: the output is read under the input's fill rule, like Sutherland-Hodgman's
//!   (capabilities say `bridges`). Unlike Sutherland-Hodgman it splits a result that falls apart
//!   into separate rings, with no bridges. The rectangle is read under the same rule: under
//!   positive a clockwise rectangle covers nothing (under negative a counter-clockwise one).
//! - It computes on integers: the inputs are rounded to a grid of about extent x 2^-30
//!   ([`IntegerGrid`]), so the output is compared with a loose tolerance (the testkit's
//!   `GEO_TOLERANCE`). Cut points on the rectangle's sides get the sides' exact coordinates back.
//!   Line pieces are rebuilt on the input segment from their parameters; each segment gets a
//!   grid of its own (see [`Clipper2RectLines`]).
//! - [`Clipper2OpenLines`] runs one `Execute` per segment on a grid shared by the batch and the
//!   window; its boundary rules are Clipper2's: a segment along a window edge can lose its part
//!   on the edge, so `verify` reports oracle failures for it on `lines-degenerate` and `lines-large`.
//! - `RectClipLines` breaks the closed-set rule of `docs/DESIGN.md` for a segment along a side that
//!   goes on beyond the rectangle: it drops the part on the side (a segment wholly on a side is
//!   kept), so `verify` reports oracle failures for this peer on the `lines-degenerate` workload.
//!
//! # Example
//!
//! ```
//! use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons, Rect, Ring};
//! use clip_clipper2_rect::Clipper2RectClipper;
//!
//! let subject = Polygons::from(Rect::new(-1.0, -1.0, 1.0, 1.0).to_ring());
//! let window = Polygons::from(Rect::new(0.0, 0.0, 4.0, 4.0).to_ring());
//! let out = Clipper2RectClipper.clip(&subject, &window, BoolOp::Intersection, FillRule::NonZero).unwrap();
//! assert_eq!(out.rings.len(), 1);
//! assert_eq!(out.signed_area(), 1.0);
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod clipper;
#[allow(unsafe_code)]
mod ffi;
mod grid;
mod lines;
mod open_lines;

pub use clipper::Clipper2RectClipper;
pub use ffi::GridPoint;
pub use grid::IntegerGrid;
pub use lines::Clipper2RectLines;
pub use open_lines::{Clipper2OpenLines, OPEN_LINES_NAME};

/// The registry name.
pub const NAME: &str = "clipper2-rect";
