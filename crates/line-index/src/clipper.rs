//! The clipper: the window prepared into an edge tree once, then per segment a walk of the tree along its ray.

use clip_core::predicates::orient2d;
use clip_core::{
    Along, ClipError, LineCapabilities, LineClipper, LineCrossings, LineFrame, LineSide, Point, Polygons,
    PreparedWindow, Rect, Segment, VisiblePiece, WindowKind, WindowRings, validate_segments, validate_window,
};

use crate::edge_tree::{EdgeTree, LEAF_EDGES};
use crate::ray_box::Ray;

/// Line clipping through a box hierarchy over the window's edges, registered as `indexed`. Any
/// window (rings read under even-odd). See the crate documentation.
#[derive(Clone, Copy, Debug, Default)]
pub struct LineIndex;

impl LineClipper for LineIndex {
    fn name(&self) -> &'static str {
        "indexed"
    }

    fn capabilities(&self) -> LineCapabilities {
        LineCapabilities { window: WindowKind::Any }
    }

    fn prepare(&self, window: &Polygons) -> Result<Box<dyn PreparedWindow>, ClipError> {
        Ok(Box::new(PreparedLineIndex::new(window)?))
    }
}

/// How many segments of a batch each stage settled, and how much of the tree they walked.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct IndexCounts {
    /// Segments in the batch.
    pub segments: usize,
    /// Zero-length segments (nothing visible).
    pub zero_length: usize,
    /// Rejected by the window's bounding box (both ends beyond one side).
    pub bounding_box: usize,
    /// Walked the tree and met no edge, or only edges behind the start.
    pub no_crossing: usize,
    /// Segments with at least one visible piece.
    pub visible: usize,
    /// Tree nodes whose box was tested, over the batch.
    pub nodes_tested: usize,
    /// Leaves whose edges were classified, over the batch.
    pub leaves_scanned: usize,
}

/// A window prepared for [`LineIndex`]: the vertices ring after ring (each ring closed by a
/// repeat of its first vertex), their x and y apart for the vertex loop, the bounding box and the
/// edge tree.
#[derive(Clone, Debug)]
pub struct PreparedLineIndex {
    points: Vec<Point>,
    xs: Vec<f64>,
    ys: Vec<f64>,
    bounds: Rect,
    tree: EdgeTree,
}

impl PreparedLineIndex {
    /// Prepares `window` (any rings, even-odd) in O(n) time; a degenerate window is an error.
    pub fn new(window: &Polygons) -> Result<PreparedLineIndex, ClipError> {
        validate_window(window)?;
        let rings = WindowRings::new(window);
        let tree = EdgeTree::new(&rings);
        let (xs, ys) = rings.points.iter().map(|p| (p.x, p.y)).unzip();
        Ok(PreparedLineIndex { points: rings.points, xs, ys, bounds: window.bounds(), tree })
    }

    /// Bytes held by the prepared window (vertices, their coordinate arrays and the tree).
    pub fn memory_bytes(&self) -> usize {
        self.points.len() * (size_of::<Point>() + 2 * size_of::<f64>())
            + self.tree.nodes.len() * size_of::<crate::edge_tree::Node>()
    }

    /// Clips like [`PreparedWindow::clip_batch`] and reports what each stage settled and how
    /// much of the tree was walked. A separate entry point, so the timed path carries no counters.
    pub fn clip_batch_counted(
        &self,
        segments: &[Segment],
        out: &mut Vec<VisiblePiece>,
    ) -> Result<IndexCounts, ClipError> {
        validate_segments(segments)?;
        let mut counts = IndexCounts::default();
        let mut crossings = LineCrossings::default();
        for (index, &s) in segments.iter().enumerate() {
            self.clip_one::<true>(index, s, out, &mut crossings, &mut counts);
        }
        Ok(counts)
    }

    /// One segment: bounding-box reject, then the tree walked along the ray from `a` through `b`,
    /// every crossing at or after the start recorded, and the pieces read off by parity.
    #[inline]
    fn clip_one<const COUNT: bool>(
        &self,
        index: usize,
        s: Segment,
        out: &mut Vec<VisiblePiece>,
        crossings: &mut LineCrossings,
        counts: &mut IndexCounts,
    ) {
        if COUNT {
            counts.segments += 1;
        }
        let (a, b) = (s.a, s.b);
        if a == b {
            if COUNT {
                counts.zero_length += 1;
            }
            return;
        }
        if self.bounds.rejects_segment(a, b) {
            if COUNT {
                counts.bounding_box += 1;
            }
            return;
        }
        crossings.clear();
        let ray = Ray::new(a, b);
        let side = LineSide::new(a, b);
        let frame = LineFrame::new(s);
        // Crossings at or after the start, counted: every ring crosses the line an even number
        // of times, so their parity is the parity of those before the start, not looked for.
        let mut found = 0u32;
        let nodes = &self.tree.nodes;
        let mut i = 0;
        while i < nodes.len() {
            let node = &nodes[i];
            if COUNT {
                counts.nodes_tested += 1;
            }
            if ray.misses(&node.bounds) {
                i = node.skip as usize;
                continue;
            }
            if node.is_leaf() {
                if COUNT {
                    counts.leaves_scanned += 1;
                }
                found += self.leaf(node.first as usize, node.end as usize, &side, &frame, crossings);
            }
            i += 1;
        }
        if found % 2 == 1 {
            crossings.record(Along::Before, 0.0);
        }
        if crossings.is_empty() {
            if COUNT {
                counts.no_crossing += 1;
            }
            return;
        }
        let written = crossings.emit(index, &frame, out);
        if COUNT && written > 0 {
            counts.visible += 1;
        }
    }

    /// Liu's rule on one leaf's edges `first..end`: the exact sign of the line function at each
    /// vertex, a crossing for each edge whose signs differ (a vertex on the line counting as on
    /// the negative side), edges on the line recorded as boundary. Records the crossings at or
    /// after the start and returns how many there were.
    #[inline(always)]
    fn leaf(&self, first: usize, end: usize, side: &LineSide, frame: &LineFrame, crossings: &mut LineCrossings) -> u32 {
        let count = end + 1 - first;
        let (xs, ys, points) = (&self.xs[first..=end], &self.ys[first..=end], &self.points[first..=end]);
        let mut f = [0.0f64; LEAF_EDGES + 1];
        // Signs as bit masks over the run's vertices: which were too close to call in f64, which
        // are positive, which are on the line.
        let mut unsure = 0u32;
        for (k, (&x, &y)) in xs.iter().zip(ys).enumerate() {
            let (value, bound) = side.estimate(x, y);
            f[k] = value;
            unsure |= u32::from(value.abs() <= bound) << k;
        }
        while unsure != 0 {
            let k = unsure.trailing_zeros() as usize;
            f[k] = orient2d(frame.a, frame.b, points[k]);
            unsure &= unsure - 1;
        }
        let (mut positive, mut zero) = (0u32, 0u32);
        for (k, &v) in f[..count].iter().enumerate() {
            positive |= u32::from(v > 0.0) << k;
            zero |= u32::from(v == 0.0) << k;
        }
        // Edge k runs from vertex k to k + 1: it crosses where their signs differ, and lies on the
        // line where both are zero.
        let edges = (1u32 << (count - 1)) - 1;
        let mut crossed = (positive ^ (positive >> 1)) & edges;
        let mut along = zero & (zero >> 1) & edges;
        let mut found = 0;
        while crossed != 0 {
            let k = crossed.trailing_zeros() as usize;
            crossed &= crossed - 1;
            let (p, q, fp, fq) = (points[k], points[k + 1], f[k], f[k + 1]);
            let (place, t) = if fp == 0.0 {
                (frame.place(p), frame.param(p))
            } else if fq == 0.0 {
                (frame.place(q), frame.param(q))
            } else {
                frame.edge_crossing(p, q, fp, fq)
            };
            if place != Along::Before {
                crossings.record(place, t);
                found += 1;
            }
        }
        while along != 0 {
            let k = along.trailing_zeros() as usize;
            along &= along - 1;
            let (p, q) = (points[k], points[k + 1]);
            crossings.along((frame.place(p), frame.param(p)), (frame.place(q), frame.param(q)));
        }
        found
    }
}

impl PreparedWindow for PreparedLineIndex {
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError> {
        validate_segments(segments)?;
        let mut crossings = LineCrossings::default();
        let mut counts = IndexCounts::default();
        for (index, &s) in segments.iter().enumerate() {
            self.clip_one::<false>(index, s, out, &mut crossings, &mut counts);
        }
        Ok(())
    }
}
