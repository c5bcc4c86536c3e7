//! clip-cyrus-beck: Cyrus-Beck parametric line clipping (convex windows) and a Liu-style line clipper (any window).
//!
//! Two [`LineClipper`](clip_core::LineClipper)s, both following the closed-set rule of the
//! repository's `docs/DESIGN.md`: the visible part of a segment is the set of maximal closed
//! parameter intervals of positive length whose points all lie in the closed window (interior or
//! boundary, even-odd interior), adjacent intervals merged, isolated touch points dropped, pieces
//! in the input's direction and order.
//!
//! - [`CyrusBeck`] (`cyrus-beck`): M. Cyrus and J. Beck, *Generalized two- and three-dimensional
//!   clipping*, Computers & Graphics 3(1):23-28, 1978; parametric clipping against one convex ring.
//!   For each edge the edge function `g(t) = n · (P(t) - v)` (inner normal `n`) at the two ends
//!   decides: both outside (a zero counts as outside unless both are zero) rejects the segment;
//!   outside-to-inside gives an entering parameter, inside-to-outside a leaving one; the piece is
//!   `[max entering, min leaving]`. A segment on an edge's line keeps its overlap with that edge.
//! - [`Liu`] (`liu`): the line clipper for concave polygonal windows of Liu Yong-Kui et al. (1999),
//!   as described and used as the baseline ("LIU") of Table 4 in J. Wang, G. Lu, Q. Peng and X. Wu,
//!   *Line clipping against polygonal window algorithm based on the multiple virtual boxes
//!   rejecting*, Journal of Zhejiang University SCIENCE A 6(Suppl. I):100-107, 2005. It follows
//!   that description, not Liu et al.'s own paper. Any window. Each vertex is classified by the
//!   sign of the segment's line function `f(v) = (b - a) × (v - a)`; only edges whose end signs
//!   differ are intersected; the intersections are sorted by `t` and the segment is cut into
//!   alternately inside and outside intervals by even-odd parity.
//!
//! # What the Liu baseline includes
//!
//! The paper measures its gains against Liu and says polygon clippers "commonly adopt a minimal
//! enclosing box (MEB) ... to encode the endpoints of line segments". So `liu` keeps that
//! Cohen-Sutherland reject against the window's bounding box (as does `cyrus-beck`); it has none
//! of the paper's further boxes (45° box, slope-adaptive box, code-sum reject), which are what
//! `clip-virtual-box` adds. Nothing else is held back: one flat vertex array, no allocation per
//! segment, only sign-changing edges intersected, an insertion sort of the few crossings.
//!
//! # Exactness
//!
//! Every decision is an exact sign ([`clip_core::predicates::orient2d`], Shewchuk's adaptive
//! predicate) or an exact coordinate comparison: which side of the line a vertex lies on, whether
//! an edge's crossing lies before, at, inside or after the segment's ends, where a vertex on the
//! line lies along it. Only the parameters of the pieces' ends are rounded. Degenerate incidences:
//!
//! - a vertex on the line (Liu) counts as lying on the negative side, a symbolic shift of the line
//!   that resolves it by its neighbours: opposite sides give one crossing at the vertex, the same
//!   side a touch (no change of parity, and no split of a piece: touching pieces are merged);
//! - an edge along the line is boundary, so it is visible; it is united with the inside intervals;
//! - in `cyrus-beck`, entering and leaving through two edges that meet at a vertex is settled by the
//!   exact side of that vertex (the segment cuts the corner or passes it), so a segment through a
//!   vertex from outside gives nothing rather than a rounding-sized piece; for the rare non-adjacent
//!   pair whose parameters are within 1e-9 the exact vertex-sign evaluation decides instead.
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
//! # Example
//!
//! ```
//! use clip_core::{LineClipper, Point, Polygons, Ring, Segment};
//! use clip_cyrus_beck::{CyrusBeck, Liu};
//!
//! // A U-shaped window: the segment crosses both arms and passes over the notch.
//! let u = Polygons::from(Ring::from(
//!     &[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)][..],
//! ));
//! let s = Segment::new(Point::new(-1.0, 2.0), Point::new(4.0, 2.0));
//! let mut out = Vec::new();
//! Liu.prepare(&u)?.clip_batch(&[s], &mut out)?;
//! let pieces: Vec<_> = out.iter().map(|p| (p.piece.a.x, p.piece.b.x)).collect();
//! assert_eq!(pieces, vec![(0.0, 1.0), (2.0, 3.0)]);
//!
//! // Cyrus-Beck needs a convex window.
//! assert!(CyrusBeck.prepare(&u).is_err());
//! # Ok::<(), clip_core::ClipError>(())
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod cyrus_beck;
mod liu;
mod ring_table;

pub use cyrus_beck::{CyrusBeck, CyrusBeckCounts, PreparedCyrusBeck};
pub use liu::{Liu, LiuCounts, PreparedLiu};
