//! The peer libraries (`geo`, Clipper2, i_overlay 9, GEOS, Clipper 1, clipper2-rust) behind
//! clip-core's traits, as differential references and performance baselines.
//!
//! This is the one place (with `clip-clipper2-rect`) that builds C++ (Clipper2, Clipper 1) and
//! links GEOS and `geo`: the algorithm crates, the oracles and the testkit stay free of them. Its tests and benches are
//! the cross-library ones: our clippers beside geo and Clipper2 on the same inputs
//! (`cargo bench -p clip-peers --bench vatti`), and Clipper2's `Polygons.txt` graded with
//! Clipper2's live ring counts ([`normalised_counts_agree`]).
//!
//! - [`GeoClipper`] and [`GeoLineClipper`]: `geo` 0.33's `BooleanOps` (i_overlay underneath). It
//!   snaps coordinates to an integer grid of about extent x 1e-9, so compare its output with a
//!   loose tolerance (`clip_oracle::GEO_TOLERANCE`).
//! - [`Clipper2Clipper`]: the C++ Clipper2 through the `clipper2` crate, on an integer grid scaled
//!   per call to the inputs' extent (see [`Clipper2Clipper`]), so it too is compared loosely.
//! - [`Clipper2RectClipper`] and [`Clipper2RectLines`]: Clipper2's dedicated rectangle clippers
//!   (`RectClip`, `RectClipLines`), from the clip-clipper2-rect crate (the C API needs `unsafe`),
//!   on the same grid; rectangle windows only, polygon output read under the input's fill rule
//!   like Sutherland-Hodgman's.
//! - [`Clipper2OpenLines`]: Clipper2's general engine clipping open paths (`AddOpenSubject`, one
//!   `Execute` per segment) against any window read even-odd, from the same crate and on the same
//!   kind of grid; a line peer whose boundary rules are Clipper2's, not the closed-set rule.
//! - [`IOverlayClipper`]: i_overlay 9's f64 overlay (`FloatOverlay`), called directly, every op
//!   under every fill rule.
//! - [`GeosClipper`]: GEOS (the `geos` crate, against the system libgeos); the adapter builds each
//!   operand's fill-rule region from faces of the noded rings, since GEOS takes only valid polygons.
//! - [`Clipper1Clipper`]: Clipper 1 through `geo-clipper`, which fixes the fill rule to non-zero,
//!   so it declares non-zero alone.
//! - [`Clipper2RustClipper`]: the pure-Rust port of Clipper2 (`clipper2-rust`) on the C++ peer's
//!   integer grid.
//!
//! There is no Clipper2 line clipper for other windows: the `clipper2` 0.6 crate's safe API
//! returns only the closed output of an operation and drops the open (line) output.
//!
//! Each adapter passes our ring list to its library faithfully (every ring, in order, with its own
//! orientation) and converts the result to docs/DESIGN.md's conventions; what each normalises is said
//! on its type.

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod clipper1;
mod clipper2;
mod clipper2_rust;
mod geo;
mod geos;
mod i_overlay;
mod ring_counts;

pub use self::clipper1::Clipper1Clipper;
pub use self::clipper2::Clipper2Clipper;
pub use self::clipper2_rust::Clipper2RustClipper;
pub use self::geo::{GeoClipper, GeoLineClipper};
pub use self::geos::GeosClipper;
pub use self::i_overlay::IOverlayClipper;
pub use self::ring_counts::{FINE_GRID_OVERLAPS, PEER_CRACKS, normalised_counts_agree, thin_rings};
pub use clip_clipper2_rect::{Clipper2OpenLines, Clipper2RectClipper, Clipper2RectLines, OPEN_LINES_NAME};
