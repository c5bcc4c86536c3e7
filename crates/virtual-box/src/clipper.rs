//! The clipper: per-window preparation and the per-segment pipeline of the paper's Fig. 9.

use core::ops::Range;

use clip_core::{
    ClipError, LineCapabilities, LineClipper, LineCrossings, LineFrame, Point, Polygons, PreparedWindow, Rect, Segment,
    VisiblePiece, WindowKind, WindowRings, retain_indices, validate_segments, validate_window,
};

use crate::adaptive_box::AdaptiveBox;
use crate::intersections::intersect;
use crate::rotated_box::RotatedBox;
use crate::vertex_codes::encode;

/// Wang et al.'s line clipper by multiple virtual boxes, for any window (rings read even-odd).
///
/// With `rotated_box` it is the paper's New2, registered as `virtual-box`; without, New1,
/// registered as `virtual-box-no45`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VirtualBox {
    /// Reject by the 45° rotated box after the MEB (New2) or not (New1).
    pub rotated_box: bool,
}

impl VirtualBox {
    /// The paper's New2, with the 45° rotated box (`virtual-box`).
    pub const NEW2: VirtualBox = VirtualBox { rotated_box: true };
    /// The paper's New1, without the 45° rotated box (`virtual-box-no45`).
    pub const NEW1: VirtualBox = VirtualBox { rotated_box: false };
}

impl Default for VirtualBox {
    fn default() -> VirtualBox {
        VirtualBox::NEW2
    }
}

impl LineClipper for VirtualBox {
    fn name(&self) -> &'static str {
        if self.rotated_box { "virtual-box" } else { "virtual-box-no45" }
    }

    fn capabilities(&self) -> LineCapabilities {
        LineCapabilities { window: WindowKind::Any }
    }

    fn prepare(&self, window: &Polygons) -> Result<Box<dyn PreparedWindow>, ClipError> {
        Ok(Box::new(PreparedVirtualBox::new(window, self.rotated_box)?))
    }
}

/// How many segments of a batch each stage settled: the rejections in the paper's order, then
/// the segments that reached the intersection stage and those with a visible piece.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StageCounts {
    /// Segments in the batch.
    pub segments: usize,
    /// Zero-length segments (nothing visible).
    pub zero_length: usize,
    /// Rejected by the MEB's Cohen-Sutherland codes.
    pub meb: usize,
    /// Rejected by the 45° rotated box (always 0 for New1).
    pub rotated_box: usize,
    /// Rejected by the slope-adaptive virtual box (Table 1).
    pub virtual_box: usize,
    /// Rejected by the sum of the vertex codes (`F = ±N`).
    pub code_sum: usize,
    /// Reached the intersection stage.
    pub intersected: usize,
    /// Segments with at least one visible piece.
    pub visible: usize,
}

/// A window prepared for [`VirtualBox`]: every ring's vertices in one flat array (each ring
/// closed by a repeat of its first vertex), the MEB and the 45° rotated box.
#[derive(Clone, Debug)]
pub struct PreparedVirtualBox {
    points: Vec<Point>,
    /// The x and the y of `points`, apart, for the box's branch-free pass over one of them.
    xs: Vec<f64>,
    ys: Vec<f64>,
    rings: Vec<Range<usize>>,
    meb: Rect,
    rotated: RotatedBox,
    rotated_box: bool,
}

/// What happened to one segment.
enum Stage {
    ZeroLength,
    Meb,
    RotatedBox,
    VirtualBox,
    CodeSum,
    Intersected(usize),
}

/// Per-batch working memory, so the per-segment pipeline does not allocate.
#[derive(Debug)]
struct Scratch {
    codes: Vec<i8>,
    sides: Vec<f64>,
    display: LineCrossings,
}

impl Scratch {
    fn for_window(w: &PreparedVirtualBox) -> Scratch {
        let n = w.points.len();
        Scratch { codes: vec![0; n], sides: vec![0.0; n], display: LineCrossings::default() }
    }
}

impl PreparedVirtualBox {
    /// Prepares `window` (any rings, even-odd) for New2 (`rotated_box`) or New1; a degenerate
    /// window is an error.
    pub fn new(window: &Polygons, rotated_box: bool) -> Result<PreparedVirtualBox, ClipError> {
        validate_window(window)?;
        let WindowRings { points, rings } = WindowRings::new(window);
        let meb = window.bounds();
        let rotated = RotatedBox::new(window.points());
        let (xs, ys) = points.iter().map(|p| (p.x, p.y)).unzip();
        Ok(PreparedVirtualBox { points, xs, ys, rings, meb, rotated, rotated_box })
    }

    /// Clips like [`PreparedWindow::clip_batch`] and reports how many segments each stage
    /// settled. A separate entry point, so the timed path carries no counters.
    pub fn clip_batch_counted(
        &self,
        segments: &[Segment],
        out: &mut Vec<VisiblePiece>,
    ) -> Result<StageCounts, ClipError> {
        validate_segments(segments)?;
        let mut scratch = Scratch::for_window(self);
        let mut c = StageCounts { segments: segments.len(), ..StageCounts::default() };
        for (index, &s) in segments.iter().enumerate() {
            let stage = if self.rotated_box {
                self.clip_one::<true>(index, s, out, &mut scratch)
            } else {
                self.clip_one::<false>(index, s, out, &mut scratch)
            };
            match stage {
                Stage::ZeroLength => c.zero_length += 1,
                Stage::Meb => c.meb += 1,
                Stage::RotatedBox => c.rotated_box += 1,
                Stage::VirtualBox => c.virtual_box += 1,
                Stage::CodeSum => c.code_sum += 1,
                Stage::Intersected(written) => {
                    c.intersected += 1;
                    c.visible += usize::from(written > 0);
                }
            }
        }
        Ok(c)
    }

    /// The timed path: the paper's early outs in its order, each as one branch-free pass over the
    /// segments the previous ones kept (MEB, 45° box, virtual box), then the vertex codes and the
    /// intersections for those left. A per-segment early out mispredicts whenever the stage a
    /// segment stops at is random (as in `wang-t4`), costing more than the test itself.
    fn clip_all<const ROTATED: bool>(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) {
        let mut scratch = Scratch::for_window(self);
        let mut kept = Vec::new();
        self.meb.keep_meeting(segments, &mut kept);
        if ROTATED {
            retain_indices(&mut kept, |i| !self.rotated.rejects(segments[i].a, segments[i].b));
        }
        retain_indices(&mut kept, |i| AdaptiveBox::new(segments[i].a, segments[i].b, &self.meb).is_some());
        for &index in &kept {
            self.clip_one::<ROTATED>(index, segments[index], out, &mut scratch);
        }
    }

    /// The pipeline of Fig. 9 for one segment (inlined into the batch loop: a call per segment
    /// costs about as much as the MEB test).
    #[inline(always)]
    fn clip_one<const ROTATED: bool>(
        &self,
        index: usize,
        s: Segment,
        out: &mut Vec<VisiblePiece>,
        scratch: &mut Scratch,
    ) -> Stage {
        let (a, b) = (s.a, s.b);
        if a == b {
            return Stage::ZeroLength;
        }
        // The MEB alone first: it settles about 60% of wang-t4's segments, and timed stage by
        // stage (reproduce wang-table4) the two boxes evaluated together cost those segments
        // 3.3 ns against Liu's 1.8 for the MEB alone.
        if self.meb.rejects_segment(a, b) {
            return Stage::Meb;
        }
        if ROTATED && self.rotated.rejects(a, b) {
            return Stage::RotatedBox;
        }
        let Some(vbox) = AdaptiveBox::new(a, b, &self.meb) else {
            return Stage::VirtualBox;
        };
        let minor = if vbox.steep() { &self.xs } else { &self.ys };
        let sum = encode(minor, &self.points, &vbox, a, b, &mut scratch.codes, &mut scratch.sides);
        // The sum runs over the stored vertices, which repeat each ring's first one: it is ±(their
        // number) exactly when the paper's F = ±N, every vertex strictly on one side.
        if sum.unsigned_abs() as usize == self.points.len() {
            return Stage::CodeSum;
        }
        let frame = LineFrame::near(s, &self.meb);
        intersect(&self.points, &self.rings, &scratch.codes, &scratch.sides, &frame, &mut scratch.display);
        Stage::Intersected(scratch.display.emit(index, &frame, out))
    }
}

impl PreparedWindow for PreparedVirtualBox {
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError> {
        validate_segments(segments)?;
        if self.rotated_box {
            self.clip_all::<true>(segments, out)
        } else {
            self.clip_all::<false>(segments, out)
        }
        Ok(())
    }
}
