//! Liu's line clipper for any window: vertices classified by the line's sign, sign-changing edges crossed.

use clip_core::{
    ClipError, LineCapabilities, LineClipper, LineCrossings, LineFrame, LineSide, Polygons, PreparedWindow, Segment,
    VisiblePiece, WindowKind, validate_segments, validate_window,
};

use crate::ring_table::RingTable;

/// Liu Yong-Kui's line clipper (the baseline of Wang et al.'s Table 4), registered as `liu`.
///
/// Takes any window: its rings are read under even-odd, so holes, several parts and
/// self-intersecting rings work. See the crate documentation for the algorithm.
#[derive(Clone, Copy, Debug, Default)]
pub struct Liu;

impl LineClipper for Liu {
    fn name(&self) -> &'static str {
        "liu"
    }

    fn capabilities(&self) -> LineCapabilities {
        LineCapabilities { window: WindowKind::Any }
    }

    fn prepare(&self, window: &Polygons) -> Result<Box<dyn PreparedWindow>, ClipError> {
        Ok(Box::new(PreparedLiu::new(window)?))
    }
}

/// How many segments of a batch each stage of [`PreparedLiu`] settled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LiuCounts {
    /// Segments in the batch.
    pub segments: usize,
    /// Zero-length segments (nothing visible).
    pub zero_length: usize,
    /// Rejected by the bounding box (both ends beyond one side).
    pub bounding_box: usize,
    /// Classified against every vertex, but the line meets no edge.
    pub no_crossing: usize,
    /// Segments with at least one visible piece.
    pub visible: usize,
}

/// A window prepared for [`Liu`]: the flat vertex table and the bounding box.
#[derive(Clone, Debug)]
pub struct PreparedLiu {
    table: RingTable,
}

/// Per-batch working memory, so the per-segment loop does not allocate.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    /// The line function at every stored vertex (exact sign, rounded magnitude).
    pub sides: Vec<f64>,
    pub crossings: LineCrossings,
}

impl PreparedLiu {
    /// Prepares `window` (any rings, even-odd); a degenerate window is an error.
    pub fn new(window: &Polygons) -> Result<PreparedLiu, ClipError> {
        validate_window(window)?;
        Ok(PreparedLiu { table: RingTable::new(window) })
    }

    /// Clips like [`PreparedWindow::clip_batch`] and reports how many segments each stage settled.
    /// A separate entry point, so the timed path carries no counters.
    pub fn clip_batch_counted(
        &self,
        segments: &[Segment],
        out: &mut Vec<VisiblePiece>,
    ) -> Result<LiuCounts, ClipError> {
        let mut counts = LiuCounts::default();
        self.run::<true>(segments, out, &mut counts)?;
        Ok(counts)
    }

    fn run<const COUNT: bool>(
        &self,
        segments: &[Segment],
        out: &mut Vec<VisiblePiece>,
        counts: &mut LiuCounts,
    ) -> Result<(), ClipError> {
        validate_segments(segments)?;
        let mut scratch = Scratch::default();
        for (index, &s) in segments.iter().enumerate() {
            if COUNT {
                counts.segments += 1;
            }
            if s.a == s.b {
                if COUNT {
                    counts.zero_length += 1;
                }
                continue;
            }
            if self.table.misses_bounds(s) {
                if COUNT {
                    counts.bounding_box += 1;
                }
                continue;
            }
            match self.clip_met(index, s, out, &mut scratch) {
                None if COUNT => counts.no_crossing += 1,
                Some(written) if COUNT && written > 0 => counts.visible += 1,
                _ => {}
            }
        }
        Ok(())
    }

    /// One segment of positive length that the bounding box did not reject: `None` when its line
    /// meets no edge, else the number of pieces written.
    #[inline(always)]
    fn clip_met(&self, index: usize, s: Segment, out: &mut Vec<VisiblePiece>, scratch: &mut Scratch) -> Option<usize> {
        let frame = LineFrame::near(s, &self.table.bounds);
        cross_by_vertex_sides(&self.table, &frame, scratch);
        if scratch.crossings.is_empty() {
            return None;
        }
        Some(scratch.crossings.emit(index, &frame, out))
    }
}

impl PreparedWindow for PreparedLiu {
    /// The bounding box first over the whole batch, without branches, then the segments it kept.
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError> {
        validate_segments(segments)?;
        let mut scratch = Scratch::default();
        let mut kept = Vec::new();
        self.table.bounds.keep_meeting(segments, &mut kept);
        for &index in &kept {
            self.clip_met(index, segments[index], out, &mut scratch);
        }
        Ok(())
    }
}

/// Liu's core for one segment: the sign of the line function at every vertex (exact), then the
/// crossings of the edges whose end signs differ, into `scratch.crossings` (cleared first).
///
/// A vertex on the line counts as lying on the negative side (a symbolic shift of the line to the
/// positive side), which resolves it by its neighbours: one crossing at the vertex when they lie on
/// opposite sides, two coinciding crossings (a touch) or none when on the same side. Edges with
/// both ends on the line are recorded as boundary along the line.
pub(crate) fn cross_by_vertex_sides(table: &RingTable, frame: &LineFrame, scratch: &mut Scratch) {
    let Scratch { sides, crossings } = scratch;
    crossings.clear();
    let points = &table.points;
    // The line function with b - a formed once and orient2d's first stage inlined, in two passes:
    // the rounded values with NaN where rounding could flip the sign (straight-line code the
    // compiler vectorises), then the adaptive predicate for those few.
    let line = LineSide::new(frame.a, frame.b);
    sides.resize(points.len(), 0.0);
    for (f, v) in sides.iter_mut().zip(points) {
        let (value, bound) = line.estimate(v.x, v.y);
        *f = if value.abs() > bound { value } else { f64::NAN };
    }
    for (f, &v) in sides.iter_mut().zip(points) {
        if f.is_nan() {
            *f = line.side(v);
        }
    }
    let mut on_line = false;
    for ring in &table.rings {
        let (ring_sides, ring_points) = (&sides[ring.start..=ring.end], &points[ring.start..=ring.end]);
        for (k, f) in ring_sides.windows(2).enumerate() {
            let (fp, fq) = (f[0], f[1]);
            on_line |= fp == 0.0;
            if (fp > 0.0) == (fq > 0.0) {
                continue;
            }
            let (p, q) = (ring_points[k], ring_points[k + 1]);
            if fp == 0.0 || fq == 0.0 {
                let v = if fp == 0.0 { p } else { q };
                crossings.record(frame.place(v), frame.param(v));
            } else {
                let (place, t) = frame.edge_crossing(p, q, fp, fq);
                crossings.record(place, t);
            }
        }
    }
    if on_line {
        for ring in &table.rings {
            for i in ring.clone().filter(|&i| sides[i] == 0.0 && sides[i + 1] == 0.0) {
                let (p, q) = (points[i], points[i + 1]);
                crossings.along((frame.place(p), frame.param(p)), (frame.place(q), frame.param(q)));
            }
        }
    }
}
