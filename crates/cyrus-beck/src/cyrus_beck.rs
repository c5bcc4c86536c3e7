//! Cyrus-Beck parametric clipping against a convex window: entering and leaving parameters per edge.

use clip_core::predicates::{Orientation, orient, orient2d, orient2d_inline};
use clip_core::{
    ClipError, LineCapabilities, LineClipper, LineFrame, Polygons, PreparedWindow, Ring, Segment, VisiblePiece,
    WindowKind, convex_window, validate_segments,
};

use crate::liu::{Scratch, cross_by_vertex_sides};
use crate::ring_table::RingTable;

/// Cyrus and Beck's parametric line clipper for one convex window (either orientation), registered
/// as `cyrus-beck`. A window that is not a single convex ring is refused by `prepare` with
/// [`ClipError::WindowNotConvex`].
#[derive(Clone, Copy, Debug, Default)]
pub struct CyrusBeck;

impl LineClipper for CyrusBeck {
    fn name(&self) -> &'static str {
        "cyrus-beck"
    }

    fn capabilities(&self) -> LineCapabilities {
        LineCapabilities { window: WindowKind::Convex }
    }

    fn prepare(&self, window: &Polygons) -> Result<Box<dyn PreparedWindow>, ClipError> {
        Ok(Box::new(PreparedCyrusBeck::new(window)?))
    }
}

/// How many segments of a batch each stage of [`PreparedCyrusBeck`] settled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CyrusBeckCounts {
    /// Segments in the batch.
    pub segments: usize,
    /// Zero-length segments (nothing visible).
    pub zero_length: usize,
    /// Rejected by the bounding box (both ends beyond one side).
    pub bounding_box: usize,
    /// Rejected by one edge: the whole segment in its closed outer half-plane.
    pub outside_edge: usize,
    /// Entering parameter not below the leaving one: the segment passes a corner outside.
    pub empty_span: usize,
    /// Lying along an edge: the overlap with that edge is the answer.
    pub along_edge: usize,
    /// Entering and leaving parameters from non-adjacent edges within rounding of each other,
    /// settled by the exact vertex-sign evaluation instead.
    pub exact_fallback: usize,
    /// Segments with at least one visible piece.
    pub visible: usize,
}

/// Parameters of entering and leaving edges closer than this (and not settled exactly by a shared
/// vertex) send the segment to the exact evaluation.
const NEAR: f64 = 1e-9;

/// A convex window prepared for [`CyrusBeck`]: counter-clockwise, collinear vertices dropped (so
/// strictly convex), closed by a repeat of the first vertex. The edge normals are implicit in the
/// exact orientation predicate, which evaluates `n_i . (p - v_i)` with an exact sign.
#[derive(Clone, Debug)]
pub struct PreparedCyrusBeck {
    table: RingTable,
}

/// What happened to one segment.
enum Outcome {
    ZeroLength,
    BoundingBox,
    OutsideEdge,
    EmptySpan,
    AlongEdge(usize),
    Fallback(usize),
    Span(usize),
}

impl PreparedCyrusBeck {
    /// Prepares a convex window (one ring, either orientation).
    pub fn new(window: &Polygons) -> Result<PreparedCyrusBeck, ClipError> {
        let (ring, orientation) = convex_window(window, "cyrus-beck")?;
        let mut points = ring.points;
        if orientation == Orientation::Clockwise {
            points.reverse();
        }
        let n = points.len();
        let corners: Vec<_> = (0..n)
            .filter(|&i| orient(points[(i + n - 1) % n], points[i], points[(i + 1) % n]) != Orientation::Collinear)
            .map(|i| points[i])
            .collect();
        Ok(PreparedCyrusBeck { table: RingTable::new(&Polygons::from(Ring::new(corners))) })
    }

    /// Clips like [`PreparedWindow::clip_batch`] and reports how many segments each stage settled.
    /// A separate entry point, so the timed path carries no counters.
    pub fn clip_batch_counted(
        &self,
        segments: &[Segment],
        out: &mut Vec<VisiblePiece>,
    ) -> Result<CyrusBeckCounts, ClipError> {
        validate_segments(segments)?;
        let mut scratch = Scratch::default();
        let mut c = CyrusBeckCounts { segments: segments.len(), ..Default::default() };
        for (index, &s) in segments.iter().enumerate() {
            let written = match self.clip_one(index, s, out, &mut scratch) {
                Outcome::ZeroLength => {
                    c.zero_length += 1;
                    0
                }
                Outcome::BoundingBox => {
                    c.bounding_box += 1;
                    0
                }
                Outcome::OutsideEdge => {
                    c.outside_edge += 1;
                    0
                }
                Outcome::EmptySpan => {
                    c.empty_span += 1;
                    0
                }
                Outcome::AlongEdge(w) => {
                    c.along_edge += 1;
                    w
                }
                Outcome::Fallback(w) => {
                    c.exact_fallback += 1;
                    w
                }
                Outcome::Span(w) => w,
            };
            c.visible += (written > 0) as usize;
        }
        Ok(c)
    }

    #[inline]
    fn clip_one(&self, index: usize, s: Segment, out: &mut Vec<VisiblePiece>, scratch: &mut Scratch) -> Outcome {
        if s.a == s.b {
            return Outcome::ZeroLength;
        }
        if self.table.misses_bounds(s) {
            return Outcome::BoundingBox;
        }
        if s.reaches_far_past(&self.table.bounds) {
            // Its parameters from the edge functions at its ends, ga / (ga - gb), cannot tell the
            // window's edges apart: the exact crossings along its part near the window instead.
            return Outcome::Fallback(self.crossed(index, s, out, scratch));
        }
        let pts = &self.table.points;
        let n = pts.len() - 1;
        let (mut t_in, mut t_out) = (0.0, 1.0);
        let (mut enter, mut leave) = (usize::MAX, usize::MAX);
        for i in 0..n {
            let (p, q) = (pts[i], pts[i + 1]);
            // The edge function: positive on the inner side of a counter-clockwise edge.
            // orient2d's first stage inlined: the call into robust only near the edge's line.
            let ga = orient2d_inline(p, q, s.a);
            let gb = orient2d_inline(p, q, s.b);
            if ga < 0.0 {
                if gb <= 0.0 {
                    return Outcome::OutsideEdge;
                }
                let t = ga / (ga - gb);
                if enter == usize::MAX || t > t_in {
                    (t_in, enter) = (t, i);
                }
            } else if ga > 0.0 {
                if gb < 0.0 {
                    let t = ga / (ga - gb);
                    if leave == usize::MAX || t < t_out {
                        (t_out, leave) = (t, i);
                    }
                }
            } else if gb < 0.0 {
                return Outcome::OutsideEdge;
            } else if gb == 0.0 {
                return Outcome::AlongEdge(self.along_edge(index, s, i, out, scratch));
            }
        }
        if enter != usize::MAX && leave != usize::MAX {
            // Entering and leaving through two edges meeting at a vertex: the segment cuts that
            // corner (a piece) or passes it outside (none) by the exact side of the vertex.
            let cuts_corner = if leave == (enter + 1) % n {
                Some(orient2d(s.a, s.b, pts[leave]) < 0.0)
            } else if enter == (leave + 1) % n {
                Some(orient2d(s.a, s.b, pts[enter]) > 0.0)
            } else {
                None
            };
            match cuts_corner {
                Some(false) => return Outcome::EmptySpan,
                None if t_out - t_in < NEAR => return Outcome::Fallback(self.crossed(index, s, out, scratch)),
                _ => {}
            }
        }
        if t_in >= t_out {
            return Outcome::EmptySpan;
        }
        let before = out.len();
        LineFrame::new(s).push_piece(out, index, (t_in, t_out));
        Outcome::Span(out.len() - before)
    }

    /// The pieces of `s` from the crossings of its line with every edge (Liu's classification,
    /// exact), for the segments Cyrus-Beck's parameters cannot place.
    fn crossed(&self, index: usize, s: Segment, out: &mut Vec<VisiblePiece>, scratch: &mut Scratch) -> usize {
        let frame = LineFrame::near(s, &self.table.bounds);
        cross_by_vertex_sides(&self.table, &frame, scratch);
        scratch.crossings.emit(index, &frame, out)
    }

    /// The segment lies on the line of edge `i`: its overlap with that edge is what is visible.
    fn along_edge(
        &self,
        index: usize,
        s: Segment,
        i: usize,
        out: &mut Vec<VisiblePiece>,
        scratch: &mut Scratch,
    ) -> usize {
        let frame = LineFrame::near(s, &self.table.bounds);
        let (p, q) = (self.table.points[i], self.table.points[i + 1]);
        let crossings = &mut scratch.crossings;
        crossings.clear();
        crossings.along((frame.place(p), frame.param(p)), (frame.place(q), frame.param(q)));
        crossings.emit(index, &frame, out)
    }
}

impl PreparedWindow for PreparedCyrusBeck {
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError> {
        validate_segments(segments)?;
        let mut scratch = Scratch::default();
        for (index, &s) in segments.iter().enumerate() {
            self.clip_one(index, s, out, &mut scratch);
        }
        Ok(())
    }
}
