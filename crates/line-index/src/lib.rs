//! clip-line-index: line clipping against large polygonal windows through a box hierarchy over the window's edges.
//!
//! One [`LineClipper`](clip_core::LineClipper), [`LineIndex`], registered as `indexed`. Any
//! window: rings are read under even-odd, so concave rings, holes, several parts and
//! self-intersecting rings all work. Output follows the closed-set rule of the repository's
//! `docs/DESIGN.md`: the maximal closed parameter intervals of positive length whose points all lie
//! in the closed window (interior or boundary), touching intervals merged, isolated touch points
//! dropped, pieces in the input's direction, ordered by `t`.
//!
//! # Why
//!
//! Liu's clipper and Wang et al.'s virtual boxes (J. Wang, G. Lu, Q. Peng and X. Wu, *Line
//! clipping against polygonal window algorithm based on the multiple virtual boxes rejecting*,
//! Journal of Zhejiang University SCIENCE A 6(Suppl. I):100-107, 2005) classify every window vertex
//! for every segment their boxes do not reject, so their cost grows linearly with the window.
//! V. Skala, *O(lg N) line clipping algorithm in E2*, Computers & Graphics 18(4), 1994
//! (doi:10.1016/0097-8493(94)90064-7), shows a line can be clipped against a convex window in
//! O(log n). This crate carries the idea to any window, without convexity, through a spatial
//! index: only the edges near the segment's line are looked at.
//!
//! # The algorithm
//!
//! Preparation lays the rings out in one vertex array (each ring closed by a repeat of its first
//! vertex) and builds a four-way bounding-box tree over **runs of 16 consecutive edges** in ring
//! order (leaves), each node grouping four consecutive runs, or four consecutive nodes, every leaf
//! at the same depth. A leaf's box hugs its piece of the boundary, so a line meets few of them; a
//! node keeps its four children's boxes side by side, so they are tested together with
//! straight-line arithmetic. The nodes are stored as a four-way heap (the children of node `k` are
//! nodes `4 k + 1` to `4 k + 4`, or on the lowest level four consecutive leaves), so a walk finds
//! the next node from its parent's test alone, without reading a stored child index.
//!
//! Per batch, two branch-free passes first (a segment's fate is random in a batch spread over a
//! screen, and a per-segment early out mispredicts on a large share of it): zero-length segments
//! and those the window's bounding box rejects (both ends beyond one side, Cohen-Sutherland) are
//! dropped, then those with an end outside the bounding box that meet none of the root's child
//! boxes (they lie wholly outside); the children a segment meets are kept for its walk, which
//! starts from them without testing the root again. When more segments are left than the tree has leaves, the
//! batch will reach most of the window, so the vertices and nodes are first read in order, one
//! load per cache line: a window evicted by other work then comes back at streaming speed instead
//! of by a dependent miss per node and leaf (see `PERFORMANCE.md`). Per segment `a -> b` left:
//!
//! 1. an end strictly outside the bounding box is outside the window, so only the boxes meeting
//!    the **segment** are walked, and the crossings on it give the other end's parity;
//! 2. otherwise the tree is walked along the **ray** from `a` through `b` (the line from the start
//!    on): a child is skipped when its box lies wholly on one side of the line or behind `a`;
//! 3. in each leaf reached, Liu's rule: the exact sign of the line function at each vertex (a
//!    fixed-length, vectorised pass over the leaf's coordinates), a crossing for each edge whose
//!    end signs differ, placed exactly before, at, inside or after the segment's ends
//!    ([`clip_core::LineFrame::edge_crossing`]); edges on the line are boundary. A leaf whose box
//!    lies strictly between the perpendiculars to the segment at its ends (decided exactly at the
//!    box's extreme corners) has all its crossings inside the segment, and skips that placing;
//! 4. the crossings go to [`clip_core::LineCrossings`], shared with Liu and the virtual-box clipper,
//!    which sorts them and reads the pieces off by parity. Crossings before the start are not
//!    looked for: every ring crosses a line an even number of times, so their parity is that of
//!    the crossings found, and one stand-in crossing before the start records it.
//!
//! A **short segment** (`|dx| + |dy|` below a quarter of the bounding box's width + height, on a
//! window of more than 4 leaves) does not walk the rest of its line: the exact place of its start
//! comes from a horizontal ray to the nearer side of the box (edges half-open in y, exact
//! orientation), and only the boxes meeting the segment itself are walked; the crossings on it
//! turn the start's parity into the end's. A start on the boundary has no place that tells which
//! side the segment leaves into, so those segments take the ray of step 2.
//!
//! The result is Liu's, crossing for crossing, for every segment.
//!
//! # Exactness
//!
//! Every decision is exact. A vertex's side is the rounded line function accepted beyond one
//! error bound taken for the whole bounding box (Shewchuk's first bound of `orient2d` with the
//! largest products a point of the box can give, [`clip_core::LineSide::sign_bound`]) and the
//! exact predicate otherwise, so it is `orient2d`'s sign. A crossing's place is exact; its
//! parameter comes from the rounded values at the edge's ends where they place it as accurately as
//! two values above `orient2d`'s trust fraction would, or within 1e-14 of the segment
//! ([`clip_core::LineSide::crossing_values`]), and from `orient2d`'s accurate magnitudes
//! otherwise: short edges near the line, on a finely sampled boundary, cost no exact expansion. A
//! box is skipped only when a rounded two-product expression of exact coordinates at its extreme
//! corner clears the same kind of error bound, so a box the ray (or segment) touches is never
//! skipped (each comparison is taken as the sign of a rounded difference of two finite values,
//! which is the exact one, so one `max` over them decides a box); the horizontal ray compares
//! coordinates only. Degenerate incidences are Liu's: a vertex on the line counts
//! as on its negative side (one crossing when its neighbours lie on opposite sides, a touch
//! otherwise); an edge along the line is boundary, so visible.
//!
//! # Cost and memory
//!
//! - **Preparation**: O(n) time for n window edges (one pass to lay out the vertices, one to build
//!   the tree bottom-up over the runs); no sorting.
//! - **Memory**: 16 bytes per vertex (its x and y, held once, in two arrays), one node of 129
//!   bytes (two cache lines of boxes and a byte of which slots are used) per 2.5 to 3 leaves, and
//!   8 bytes per leaf: about 20 bytes per edge, 192 KiB at 10^4 edges (measured by
//!   `reproduce beyond-paper`). [`PreparedLineIndex::memory_bytes`]
//!   reports it. The size matters beside other work: a window evicted from the caches is read
//!   back at that cost, which was a third of the time per segment at 10^4 edges in
//!   `reproduce beyond-paper` while the vertices were also held as points (38 bytes per edge).
//! - **Per segment**: the boxes the ray meets at each level of the tree, about O(k log(n / k))
//!   for k crossings on a boundary a line meets a bounded number of times (smooth or lobed
//!   windows, holes), plus 17 vertex signs per leaf reached. Against windows of one leaf (up to
//!   16 edges) the tree is its root, and the cost is Liu's with a filtered sign.
//!
//! # Limits
//!
//! - The bound above is not a worst case: a boundary that zig-zags across the segment's line n
//!   times has n crossings, and a segment running close along a long stretch of boundary reaches
//!   every leaf of that stretch. It never does worse than visiting each node once (O(n)).
//! - Parameters of the pieces' ends are rounded. Crossing parameters closer than 1e-12 (of the
//!   segment) are taken as one point, as in every line clipper here ([`clip_core::PARAMETER_SNAP`]).
//! - Coordinates up to [`clip_core::MAX_COORDINATE`].
//!
//! # Counters
//!
//! [`PreparedLineIndex::clip_batch_counted`] clips like the timed path and returns
//! [`IndexCounts`]: what each stage settled and how many nodes and leaves were visited.
//!
//! # Example
//!
//! ```
//! use clip_core::{LineClipper, Point, Polygons, Ring, Segment};
//! use clip_line_index::LineIndex;
//!
//! // A U-shaped window: the segment crosses both arms and passes over the notch.
//! let u = Polygons::from(Ring::from(
//!     &[(0.0, 0.0), (3.0, 0.0), (3.0, 3.0), (2.0, 3.0), (2.0, 1.0), (1.0, 1.0), (1.0, 3.0), (0.0, 3.0)][..],
//! ));
//! let s = Segment::new(Point::new(-1.0, 2.0), Point::new(4.0, 2.0));
//! let mut out = Vec::new();
//! LineIndex.prepare(&u)?.clip_batch(&[s], &mut out)?;
//! let pieces: Vec<_> = out.iter().map(|p| (p.piece.a.x, p.piece.b.x)).collect();
//! assert_eq!(pieces, vec![(0.0, 1.0), (2.0, 3.0)]);
//! # Ok::<(), clip_core::ClipError>(())
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

mod clipper;
mod edge_tree;
mod ray_box;

pub use clipper::{IndexCounts, LineIndex, PreparedLineIndex};
