//! clip-virtual-box: Line clipping against polygons by multiple virtual boxes (MEB, 45-degree box, slope-adaptive box), after Wang et al. 2005.
//!
//! J. Wang, G. Lu, Q. Peng and X. Wu, *Line clipping against polygonal window algorithm based on
//! the multiple virtual boxes rejecting*, Journal of Zhejiang University SCIENCE A
//! 6(Suppl. I):100-107, 2005. One [`LineClipper`](clip_core::LineClipper), [`VirtualBox`], in two
//! registered variants: `virtual-box` (the paper's New2, with the 45° rotated box) and
//! `virtual-box-no45` (New1, without it). Any window: rings are read under even-odd, so concave
//! rings, holes, several parts and self-intersecting rings all work.
//!
//! Output follows the closed-set rule of the repository's `docs/DESIGN.md`: the maximal closed
//! parameter intervals of positive length whose points all lie in the closed window (interior or
//! boundary), touching intervals merged, isolated touch points dropped, pieces in the input's
//! direction, ordered by `t`.
//!
//! # The paper's steps and where they live
//!
//! | paper | code |
//! |---|---|
//! | MEB, Cohen-Sutherland codes (Fig. 2) | the window's bounding box; [`clip_core::Rect::rejects_segment`]: both endpoint codes sharing a bit reject |
//! | 45° rotated virtual box (Fig. 3, Lu et al. 2002) | `rotated_box`: the bounding box in `u = x + y`, `v = x - y`, coded the same way (New2 only) |
//! | slope-adaptive virtual box, `P1`, `P2` (Fig. 4) | `adaptive_box`: where the line meets the MEB's left/right sides (`\|k\| <= 1`) or bottom/top (`\|k\| > 1`) |
//! | Table 1 (box above/below or left/right of the MEB) | `adaptive_box::AdaptiveBox::new` returns `None`: the line misses the MEB |
//! | vertex codes +1/-1/0, Table 2, near-zero region | `vertex_codes`: by the box outside its band, by the exact line function inside it |
//! | `F = Σ f_i = ±N` | the code-sum reject in `clipper` |
//! | products of adjacent codes (Eqs. 1-3) | `intersections::intersect` |
//! | singular cases (Eqs. 4-6, Figs. 6-7) | `intersections::singular` |
//! | DISPLAY-ARRAY; sort; discard extension points; `M0`, `M1` by odd/even counts; Table 3 | [`clip_core::LineCrossings`] (shared with Liu) |
//! | the flow chart (Fig. 9) | `PreparedVirtualBox::clip_one` |
//!
//! "Positive region" is the left of the directed segment `a -> b` (`f(v) = (b - a) × (v - a) > 0`).
//! Intersections are ordered by the segment's own parameter `t` rather than by x or y, so `M0` is
//! the input's start and the pieces keep the input's direction.
//!
//! # Where this departs from the paper, and why
//!
//! - **Exact decisions.** Every sign that matters is exact ([`clip_core::predicates::orient2d`]):
//!   a vertex's code inside the near-zero band, the place of an intersection relative to `M0` and
//!   `M1`. Floating-point shortcuts are used only where they provably cannot change the outcome:
//!   the MEB test compares input coordinates; the 45° box compares rounded `x ± y`, and rounding to
//!   nearest is monotone, so a strict comparison of rounded values implies the exact one; the
//!   virtual box's band is widened by a bound on the rounding of `P1` and `P2` (about 1e-15
//!   relative), so a vertex outside it really lies on the side Table 2 says, and Table 1 only
//!   rejects lines that really miss the MEB.
//! - **Table 1's corners.** The paper compares `P1`, `P2` with "LT and RB ... of the adaptive
//!   virtual box", which would compare the box with itself; the test is meant against the MEB's
//!   top and bottom (left and right for steep lines), and that is what is done.
//! - **Eq. 6, an edge along the line.** The paper keeps the convex vertex of such an edge and drops
//!   the concave one, deciding convexity with the EXTREM-POLYGON cross products. That needs one
//!   simple ring of known orientation, and it can drop the edge itself, which the closed-set rule
//!   shows (it is boundary). Here a run of vertices on the line counts as one crossing (at its
//!   first vertex) when its neighbours lie on opposite sides of the line, none when on the same
//!   side, and its edges are added to the display as visible boundary. On a simple ring this gives
//!   the paper's pieces plus the boundary edges; it also holds for holes, several rings and
//!   self-intersecting rings, where convexity is not defined.
//! - **Eq. 5** (a vertex touched, neighbours on one side) is ignored as the paper says; under the
//!   closed-set rule the touch point either joins two pieces (merged) or stands alone (dropped).
//! - **Endpoints on the boundary.** `M0`'s Count1 counts intersections strictly after it, `M1`'s
//!   strictly before it; an intersection exactly at an endpoint then changes neither answer
//!   wrongly, and a segment starting on the boundary and leaving shows nothing.
//! - **Convex windows.** The paper's remark that a convex window could stop after the second
//!   intersection is not used: the same code serves every window.
//!
//! # Limits
//!
//! Parameters of the pieces' ends are rounded. Crossing parameters closer than 1e-12 (of the
//! segment) are taken as one point, so that two edges crossing the line at one point that is not
//! a vertex (two rings crossing each other on the segment, an edge through another ring's vertex)
//! neither split a piece nor leave a sliver; a true piece or gap shorter than that is dropped
//! (below the resolution of the rounded parameters; the oracle's tolerance is 1e-9). Coordinates
//! up to [`clip_core::MAX_COORDINATE`].
//!
//! # Counters
//!
//! [`PreparedVirtualBox::clip_batch_counted`] clips like the timed path and returns
//! [`StageCounts`]: how many segments each rejection stage removed.
//!
//! # Example
//!
//! ```
//! use clip_core::{LineClipper, Point, Polygons, Ring, Segment};
//! use clip_virtual_box::{PreparedVirtualBox, VirtualBox};
//!
//! // A U-shaped window: the segment crosses both arms and passes over the notch.
//! let u = Polygons::from(Ring::from(
//!     &[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)][..],
//! ));
//! let s = Segment::new(Point::new(-1.0, 2.0), Point::new(4.0, 2.0));
//! let mut out = Vec::new();
//! VirtualBox::NEW2.prepare(&u)?.clip_batch(&[s], &mut out)?;
//! let pieces: Vec<_> = out.iter().map(|p| (p.piece.a.x, p.piece.b.x)).collect();
//! assert_eq!(pieces, vec![(0.0, 1.0), (2.0, 3.0)]);
//!
//! // The paper's segment "e": inside the MEB of a triangle, its line missing the triangle.
//! // New1 rejects it by the code sum; New2's 45° box already rejects it.
//! let triangle = Polygons::from(Ring::from(&[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)][..]));
//! let e = [Segment::new(Point::new(3.0, 3.0), Point::new(4.0, 2.0))];
//! let new1 = PreparedVirtualBox::new(&triangle, false)?.clip_batch_counted(&e, &mut out)?;
//! let new2 = PreparedVirtualBox::new(&triangle, true)?.clip_batch_counted(&e, &mut out)?;
//! assert_eq!((new1.code_sum, new2.rotated_box), (1, 1));
//! # Ok::<(), clip_core::ClipError>(())
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod adaptive_box;
mod clipper;
mod intersections;
mod rotated_box;
mod vertex_codes;

pub use clipper::{PreparedVirtualBox, StageCounts, VirtualBox};
