//! clip-raster: scanline polygon fill and Vatti trapezoid fill into a frame buffer.
//!
//! The fill stage of Table 3 of B. R. Vatti, *A generic solution to polygon clipping*,
//! Communications of the ACM 35(7):56-63, 1992 (sections "Results" and "Trapezoid Generation"):
//! Method 1 fills the clipper's trapezoids `(Xleft, Xright, Ybot, DXleft, DXright, Ytop)` with the
//! paper's incremental loop ([`fill_trapezoids`]); Method 2 fills the clipped polygon with a
//! scanline fill ([`fill_polygons`]: edge table, active edge table, even-odd or non-zero). Both
//! draw into a [`FrameBuffer`], by default the paper's 1280 x 1024, one byte per pixel.
//!
//! # The sampling rule (shared)
//!
//! Pixel `(i, j)` covers `[i, i + 1) x [j, j + 1)`; it is lit when its centre `(i + 0.5, j + 0.5)`
//! is inside the region. Ties are half-open: a centre exactly on a left edge or on the lowest-y
//! edge is in, one exactly on a right edge or the highest-y edge is out. Rows grow with y, so
//! with row 0 shown at the top (as displays do) this is the usual top-left rule; abutting
//! regions never share or miss a pixel. One module ([`sampling`]) holds the rule and both fills
//! use it: rows `ceil(y_bottom - 0.5) .. ceil(y_top - 0.5)`, columns likewise, and sides walked by
//! `x += dx` from an anchor at the bottom of a trapezoid or slab ([`sampling::SideWalk`]).
//!
//! The incremental loop accumulates rounding in `x`, so a fill only agrees with another to the
//! bit if both walk from the same anchor. The scanline fill re-anchors every active edge at each
//! vertex height, with [`sampling::edge_x_at`]; a trapezoid anchored the same way (a slab
//! decomposition at vertex heights, which is how the tests build them) therefore lights exactly
//! the same pixels. Trapezoids anchored elsewhere (Vatti's, whose scanbeams also stop at the
//! other polygon's vertices and at crossings) can differ only where a pixel centre lies within
//! rounding of an edge.
//!
//! # Vocabulary
//!
//! | paper | code |
//! |---|---|
//! | trapezoid `(Xleft, Xright, Ybot, DXleft, DXright, Ytop)` | [`clip_core::Trapezoid`] |
//! | `DrawLine(Xleft, Xright, Y)` | one row's span in [`fill_trapezoids`] |
//! | `Xleft = Xleft + DXleft` | [`sampling::SideWalk::step`] |
//! | scanline fill (Method 2) | [`fill_polygons`] |
//! | 1,280 x 1,024 resolution | [`FrameBuffer::default`] |
//!
//! # Limits
//!
//! Rows and columns outside the buffer are skipped (the geometry is not otherwise clipped). The
//! scanline fill takes any rings under any [`clip_core::FillRule`]; non-finite input is a
//! [`clip_core::ClipError`].
//!
//! # Example
//!
//! ```
//! use clip_core::{FillRule, Polygons, Ring, Trapezoid};
//! use clip_raster::{FrameBuffer, fill_polygons, fill_trapezoids};
//!
//! // A triangle as a polygon and as one trapezoid (its top side has zero length).
//! let triangle = Polygons::from(Ring::from(&[(0.0, 0.0), (10.0, 0.0), (0.0, 10.0)][..]));
//! let mut by_scanline = FrameBuffer::default();
//! fill_polygons(&mut by_scanline, &triangle, FillRule::EvenOdd, 1).unwrap();
//! assert_eq!(by_scanline.lit_count(), 45); // centres with i + j + 1 < 10
//!
//! let trapezoid = Trapezoid { x_left: 0.0, x_right: 10.0, y_bottom: 0.0, dx_left: 0.0, dx_right: -1.0, y_top: 10.0 };
//! let mut by_trapezoid = FrameBuffer::default();
//! fill_trapezoids(&mut by_trapezoid, &[trapezoid], 1).unwrap();
//! assert_eq!(by_trapezoid, by_scanline);
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod frame;
pub mod sampling;
mod scanline;
mod trapezoid_fill;

pub use frame::{DEFAULT_HEIGHT, DEFAULT_WIDTH, FrameBuffer};
pub use scanline::fill_polygons;
pub use trapezoid_fill::fill_trapezoids;
