//! The clipper: the window prepared into an edge tree once, then per segment a walk of the tree along its ray.

use clip_core::predicates::{orient_sign, orient2d};
use clip_core::{
    Along, ClipError, LineCapabilities, LineClipper, LineCrossings, LineFrame, LineSide, Point, Polygons,
    PreparedWindow, Rect, Segment, VisiblePiece, WindowKind, WindowRings, validate_segments, validate_window,
};

use core::ops::Range;

use crate::edge_tree::{EdgeTree, LEAF_EDGES, MAX_X, MAX_Y, MIN_X, MIN_Y, Node, WAYS};
use crate::ray_box::Ray;

/// Segments whose `|dx| + |dy|` is below this fraction of the box's width + height locate their
/// start and look only at the edges near the segment (see `clip_one`).
const SHORT: f64 = 0.25;

/// Windows of at most this many leaves clip every segment along its ray: with so few edges, one
/// walk is cheaper than locating the start and walking again.
const SHORT_FROM_LEAVES: usize = 4;

/// A segment's line function, and one bound over the window's bounding box beyond which its
/// rounded values have exact signs.
struct Line {
    side: LineSide,
    sign_bound: f64,
    /// A gap `|fp - fq|` above which a crossing's rounded end values are kept as they are
    /// ([`LineSide::crossing_gap_bound`]).
    trusted_gap: f64,
}

/// Slots of a walk's stack: each level pops one node and pushes at most WAYS - 1, and a node
/// writes WAYS slots from the top whichever children it pushes (see `visit`), so a tree of D
/// levels writes below 3 D + 4; u32 leaf indices allow at most 17 levels. A power of two, so
/// an index masked by `STACK - 1` needs no bounds check.
const STACK: usize = 64;

/// What a batch's walks share: the stack of nodes to visit, kept from segment to segment rather
/// than zeroed for each walk, and the counters of [`PreparedLineIndex::clip_batch_counted`].
struct WalkState {
    stack: [usize; STACK],
    counts: IndexCounts,
}

impl WalkState {
    fn new() -> WalkState {
        WalkState { stack: [0; STACK], counts: IndexCounts::default() }
    }
}

/// What the horizontal ray found about a segment's start.
enum Start {
    /// Not on the boundary: inside (true) or outside the window.
    Inside(bool),
    /// On an edge or a vertex.
    OnBoundary,
}

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

/// A window prepared for [`LineIndex`]: the vertices' x and y apart, ring after ring (each ring
/// closed by a repeat of its first vertex), the bounding box and the edge tree. The coordinates
/// are held once: against a large window the vertices are most of the memory a batch reads, and
/// a window evicted by other work is read back from memory at that cost.
#[derive(Clone, Debug)]
pub struct PreparedLineIndex {
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
        // Padded with copies of the last vertex: a leaf reads a fixed number of coordinates.
        let last = rings.points.last().copied().unwrap_or(Point::ZERO);
        let padded = rings.points.iter().chain(core::iter::repeat_n(&last, LEAF_EDGES));
        let (xs, ys) = padded.map(|p| (p.x, p.y)).unzip();
        Ok(PreparedLineIndex { xs, ys, bounds: window.bounds(), tree })
    }

    /// Reads one value per cache line of the vertices and the tree, in order.
    fn touch(&self) {
        const PER_LINE: usize = 64 / size_of::<f64>();
        let sum = |v: &[f64]| v.iter().step_by(PER_LINE).fold(0.0, |s, &x| s + x);
        let nodes: f64 = self.tree.nodes.iter().map(|n| n.sides[MIN_X][0] + n.sides[MAX_X][0]).sum();
        core::hint::black_box(sum(&self.xs) + sum(&self.ys) + nodes);
    }

    /// Vertex `k`.
    #[inline(always)]
    fn point(&self, k: usize) -> Point {
        Point::new(self.xs[k], self.ys[k])
    }

    /// Bytes held by the prepared window (the vertices' coordinate arrays and the tree).
    pub fn memory_bytes(&self) -> usize {
        (self.xs.len() + self.ys.len()) * size_of::<f64>()
            + self.tree.nodes.len() * (size_of::<Node>() + 1)
            + self.tree.leaves.len() * size_of::<Range<u32>>()
    }

    /// Clips like [`PreparedWindow::clip_batch`] and reports what each stage settled and how
    /// much of the tree was walked. A separate entry point, so the timed path carries no counters.
    pub fn clip_batch_counted(
        &self,
        segments: &[Segment],
        out: &mut Vec<VisiblePiece>,
    ) -> Result<IndexCounts, ClipError> {
        validate_segments(segments)?;
        let mut state = WalkState::new();
        let mut crossings = LineCrossings::default();
        for (index, &s) in segments.iter().enumerate() {
            self.clip_one::<true>(index, s, None, out, &mut crossings, &mut state);
        }
        Ok(state.counts)
    }

    /// One segment: bounding-box reject, then the tree walked along the ray from `a` through `b`,
    /// every crossing at or after the start recorded, and the pieces read off by parity.
    /// `root_entered`, when known, is [`Self::root_entry`] of the segment.
    #[inline]
    fn clip_one<const COUNT: bool>(
        &self,
        index: usize,
        s: Segment,
        root_entered: Option<u32>,
        out: &mut Vec<VisiblePiece>,
        crossings: &mut LineCrossings,
        state: &mut WalkState,
    ) {
        if COUNT {
            state.counts.segments += 1;
        }
        let (a, b) = (s.a, s.b);
        if a == b {
            if COUNT {
                state.counts.zero_length += 1;
            }
            return;
        }
        if self.bounds.rejects_segment(a, b) {
            if COUNT {
                state.counts.bounding_box += 1;
            }
            return;
        }
        crossings.clear();
        let ray = Ray::new(a, b, &self.bounds);
        let side = LineSide::new(a, b);
        let line = Line {
            side,
            sign_bound: side.sign_bound(&self.bounds),
            trusted_gap: side.crossing_gap_bound(&self.bounds),
        };
        let frame = LineFrame::near(s, &self.bounds);
        // An end strictly outside the bounding box is outside the window, so the crossings on the
        // segment alone give the parity at the other end: only the boxes meeting the segment are
        // walked. Otherwise a segment short beside the window: its crossings and the exact place
        // of its start, found along a horizontal ray to the nearer side of the box, cost less
        // than everything along the ray through it. A start on the boundary has no place that
        // tells the parity just after it: those segments take the ray.
        let (a_outside, b_outside) = (self.bounds.outcode(a) != 0, self.bounds.outcode(b) != 0);
        if a_outside | b_outside {
            // The batch's pass over the root (`root_entry`) has tested its children already.
            let root_entered =
                root_entered.unwrap_or_else(|| Self::root_entry(&self.tree.nodes[0], self.tree.present[0], &ray, &s));
            let found = self.walk::<COUNT, true, false>(Some(root_entered), &ray, &line, &frame, crossings, state);
            // With the start outside, the crossings on the segment give the end's parity; with
            // the end outside, the start's. Counted without a branch on which end it is (it is
            // random in a batch spread over the screen).
            let odd = found & 1;
            crossings.count_beyond(odd & u32::from(!a_outside), odd & u32::from(a_outside));
        } else {
            let start = if self.tree.leaves.len() > SHORT_FROM_LEAVES
                && (b.x - a.x).abs() + (b.y - a.y).abs() < SHORT * (self.bounds.width() + self.bounds.height())
            {
                self.locate::<COUNT>(a, state)
            } else {
                Start::OnBoundary
            };
            if let Start::Inside(inside) = start {
                let found = self.walk::<COUNT, true, false>(None, &ray, &line, &frame, crossings, state);
                // The crossings on the segment toggle the parity from the start's to the end's.
                if (found + u32::from(inside)) % 2 == 1 {
                    crossings.record(Along::After, 1.0);
                }
                if inside {
                    crossings.record(Along::Before, 0.0);
                }
            } else if self.exit_length(b, b - a) <= self.exit_length(a, a - b) {
                // Crossings at or after the start, counted: every ring crosses the line an even
                // number of times, so their parity is the parity of those before the start.
                let found = self.walk::<COUNT, false, false>(None, &ray, &line, &frame, crossings, state);
                if found % 2 == 1 {
                    crossings.record(Along::Before, 0.0);
                }
            } else {
                // The same from the end backwards, where the line leaves the box sooner that way:
                // crossings at or before the end, and the parity of those after it.
                let back = Ray::new(b, a, &self.bounds);
                let found = self.walk::<COUNT, false, true>(None, &back, &line, &frame, crossings, state);
                if found % 2 == 1 {
                    crossings.record(Along::After, 1.0);
                }
            }
        }
        if crossings.is_empty() {
            if COUNT {
                state.counts.no_crossing += 1;
            }
            return;
        }
        let written = crossings.emit(index, &frame, out);
        if COUNT && written > 0 {
            state.counts.visible += 1;
        }
    }

    /// The children of `root` whose boxes the closed segment `s` (the ray `ray` from its start,
    /// of positive length) can meet, as bits. Branch-free.
    #[inline(always)]
    fn root_entry(root: &Node, present: u8, ray: &Ray, s: &Segment) -> u32 {
        ray.segment_hits(root, &s.bounds()) & u32::from(present)
    }

    /// How far the ray from `p` in direction `d` runs inside the bounding box, in units of `|d|`
    /// (rounded: it only chooses a direction to walk).
    fn exit_length(&self, p: Point, d: Point) -> f64 {
        let along = |p: f64, d: f64, lo: f64, hi: f64| {
            if d > 0.0 {
                (hi - p) / d
            } else if d < 0.0 {
                (lo - p) / d
            } else {
                f64::INFINITY
            }
        };
        along(p.x, d.x, self.bounds.min.x, self.bounds.max.x).min(along(p.y, d.y, self.bounds.min.y, self.bounds.max.y))
    }

    /// Walks the tree from the root's children `root_entered` (tested here when `None`): along
    /// the ray from the start (`ON_SEGMENT` false; from the end backwards when `BACKWARD`), or
    /// over the boxes meeting the closed segment of `frame` (`ON_SEGMENT` true); records the
    /// crossings at or after the start (on the segment) and returns how many there were.
    #[inline(always)]
    fn walk<const COUNT: bool, const ON_SEGMENT: bool, const BACKWARD: bool>(
        &self,
        root_entered: Option<u32>,
        ray: &Ray,
        line: &Line,
        frame: &LineFrame,
        crossings: &mut LineCrossings,
        state: &mut WalkState,
    ) -> u32 {
        let segment = &Segment::new(frame.a, frame.b).bounds();
        let mut found = 0;
        self.visit::<COUNT>(
            root_entered,
            |node| {
                if ON_SEGMENT { ray.segment_hits(node, segment) } else { ray.hits(node) }
            },
            |range, node, i| {
                // A leaf whose box lies strictly between the segment's ends (across its line) has
                // every crossing inside the segment: they need no placing.
                let inside = ray.within_span(node, i);
                found += self.leaf::<ON_SEGMENT, BACKWARD>(
                    range.start as usize,
                    range.end as usize,
                    inside,
                    line,
                    frame,
                    crossings,
                )
            },
            state,
        );
        found
    }

    /// Visits the tree from the root: `hits` tells which children of a node to enter (of the
    /// root too, unless `root_entered` already says), `leaf` is called with the edges of each
    /// leaf entered, its parent and its slot there.
    #[inline(always)]
    fn visit<const COUNT: bool>(
        &self,
        root_entered: Option<u32>,
        hits: impl Fn(&Node) -> u32,
        mut leaf: impl FnMut(&Range<u32>, &Node, usize),
        state: &mut WalkState,
    ) {
        let (nodes, present, lowest) = (&self.tree.nodes, &self.tree.present, self.tree.lowest as usize);
        let root = &nodes[0];
        let mut entered = root_entered.unwrap_or_else(|| hits(root) & u32::from(present[0]));
        if let [leaf_edges] = &self.tree.leaves[..] {
            // One leaf (up to 16 edges): the root holds it alone, no stack.
            if entered != 0 {
                leaf(leaf_edges, root, present[0].trailing_zeros() as usize);
            }
            return;
        }
        let stack = &mut state.stack;
        let mut top = 0;
        let mut at = 0;
        loop {
            if COUNT {
                state.counts.nodes_tested += 1;
            }
            let next = if at >= lowest {
                // The lowest level: the children are leaves `4 (at - lowest) + i`.
                let node = &nodes[at];
                while entered != 0 {
                    let i = entered.trailing_zeros() as usize;
                    entered &= entered - 1;
                    if COUNT {
                        state.counts.leaves_scanned += 1;
                    }
                    leaf(&self.tree.leaves[WAYS * (at - lowest) + i], node, i);
                }
                if top == 0 {
                    return;
                }
                top -= 1;
                stack[top]
            } else if entered != 0 {
                // The first child entered is visited next, straight from the node: on the way
                // down to one leaf (most walks against a large window) the next node's address
                // then waits only for this node's test, not also for a store to the stack and
                // its reload. The others are stacked without a branch on how many there are (one
                // or two children of a node entered is random in a batch, and mispredicted once
                // per walk): every slot is written, the top moves by the child's bit.
                let first = WAYS * at + 1 + entered.trailing_zeros() as usize;
                let rest = entered & (entered - 1);
                for i in 0..WAYS {
                    stack[top & (STACK - 1)] = WAYS * at + 1 + i;
                    top += ((rest >> i) & 1) as usize;
                }
                first
            } else if top == 0 {
                return;
            } else {
                top -= 1;
                stack[top]
            };
            at = next;
            entered = hits(&nodes[at]) & u32::from(present[at]);
        }
    }

    /// The exact place of `a` in the window (even-odd), by the crossings of a horizontal ray from
    /// `a` to the nearer side of the bounding box, edges taken half-open in y; or that `a` lies on
    /// the boundary.
    fn locate<const COUNT: bool>(&self, a: Point, state: &mut WalkState) -> Start {
        let rightwards = self.bounds.max.x - a.x <= a.x - self.bounds.min.x;
        let mut odd = false;
        let mut on_boundary = false;
        self.visit::<COUNT>(
            None,
            |node| {
                let mut mask = 0;
                for i in 0..WAYS {
                    let ahead = if rightwards { node.sides[MAX_X][i] >= a.x } else { node.sides[MIN_X][i] <= a.x };
                    mask |= u32::from(ahead & (node.sides[MIN_Y][i] <= a.y) & (a.y <= node.sides[MAX_Y][i])) << i;
                }
                mask
            },
            |range, _, _| {
                for k in range.start as usize..range.end as usize {
                    let (p, q) = (self.point(k), self.point(k + 1));
                    if p == a {
                        on_boundary = true;
                    } else if (p.y > a.y) != (q.y > a.y) {
                        let o = orient_sign(p, q, a);
                        on_boundary |= o == 0.0;
                        // `a` left of an upward edge (right of a downward one): the edge is to its
                        // right.
                        odd ^= ((o > 0.0) == (q.y > p.y)) == rightwards;
                    } else if p.y == a.y && q.y == a.y && p.x.min(q.x) <= a.x && a.x <= p.x.max(q.x) {
                        on_boundary = true;
                    }
                }
            },
            state,
        );
        if on_boundary { Start::OnBoundary } else { Start::Inside(odd) }
    }

    /// Liu's rule on one leaf's edges `first..end`: the exact sign of the line function at each
    /// vertex, a crossing for each edge whose signs differ (a vertex on the line counting as on
    /// the negative side), edges on the line recorded as boundary. Records the crossings at or
    /// after the start (at or before the end when `BACKWARD`; only those on the segment when
    /// `ON_SEGMENT`) and returns how many there were.
    #[inline(always)]
    fn leaf<const ON_SEGMENT: bool, const BACKWARD: bool>(
        &self,
        first: usize,
        end: usize,
        inside: bool,
        line: &Line,
        frame: &LineFrame,
        crossings: &mut LineCrossings,
    ) -> u32 {
        let count = end + 1 - first;
        // A fixed number of vertices (the arrays are padded past the last ring), so the loop is
        // unrolled and vectorised; the bits past the leaf's own are masked off.
        let (xs, ys) = (&self.xs[first..first + LEAF_EDGES + 1], &self.ys[first..first + LEAF_EDGES + 1]);
        let point = |k: usize| Point::new(xs[k], ys[k]);
        let mut f = [0.0f64; LEAF_EDGES + 1];
        // Signs as bit masks over the run's vertices: which are positive, and which were too close
        // to call in f64 (one error bound for the whole window).
        let (mut positive, mut unsure) = (0u64, 0u64);
        for (k, (&x, &y)) in xs.iter().zip(ys).enumerate() {
            let value = line.side.value(x, y);
            f[k] = value;
            positive |= u64::from(value > line.sign_bound) << k;
            unsure |= u64::from(value.abs() <= line.sign_bound) << k;
        }
        let own = (1u64 << count) - 1;
        let (mut positive, mut unsure) = (positive & own, unsure & own);
        // The exact sign for those; the magnitudes of a crossing's ends are made accurate below,
        // and only as far as placing the crossing needs.
        let approximate = unsure;
        let mut zero = 0u64;
        while unsure != 0 {
            let k = unsure.trailing_zeros() as usize;
            f[k] = orient_sign(frame.a, frame.b, point(k));
            positive |= u64::from(f[k] > 0.0) << k;
            zero |= u64::from(f[k] == 0.0) << k;
            unsure &= unsure - 1;
        }
        // Edge k runs from vertex k to k + 1: it crosses where their signs differ, and lies on the
        // line where both are zero.
        let edges = (1u64 << (count - 1)) - 1;
        let mut crossed = (positive ^ (positive >> 1)) & edges;
        let mut along = zero & (zero >> 1) & edges;
        let mut found = 0;
        while crossed != 0 {
            let k = crossed.trailing_zeros() as usize;
            crossed &= crossed - 1;
            let (p, q, mut fp, mut fq) = (point(k), point(k + 1), f[k], f[k + 1]);
            if (approximate >> k) & 0b11 != 0 {
                (fp, fq) = (orient2d(frame.a, frame.b, p), orient2d(frame.a, frame.b, q));
            } else if (fp - fq).abs() <= line.trusted_gap {
                (fp, fq) = line.side.crossing_values(p, q, fp, fq);
            }
            let (place, t) = if fp == 0.0 {
                (frame.place(p), frame.param(p))
            } else if fq == 0.0 {
                (frame.place(q), frame.param(q))
            } else if inside {
                (Along::Inside, frame.crossing_param(p, q, fp, fq))
            } else {
                frame.edge_crossing(p, q, fp, fq)
            };
            // Behind the walk's start, or past the segment's far end when only the segment is walked.
            let left_out = if BACKWARD { place == Along::After } else { place == Along::Before }
                || (ON_SEGMENT && place == Along::After);
            if !left_out {
                crossings.record(place, t);
                found += 1;
            }
        }
        while along != 0 {
            let k = along.trailing_zeros() as usize;
            along &= along - 1;
            let (p, q) = (point(k), point(k + 1));
            crossings.along((frame.place(p), frame.param(p)), (frame.place(q), frame.param(q)));
        }
        found
    }
}

impl PreparedWindow for PreparedLineIndex {
    fn clip_batch(&self, segments: &[Segment], out: &mut Vec<VisiblePiece>) -> Result<(), ClipError> {
        validate_segments(segments)?;
        let mut crossings = LineCrossings::default();
        let mut state = WalkState::new();
        // The bounding box over the whole batch first, without branches (see
        // `Rect::keep_meeting`), then the segments it kept.
        let mut kept = Vec::new();
        self.bounds.keep_meeting(segments, &mut kept);
        // Then the root's child boxes, also over the batch: a segment with an end outside the
        // bounding box that meets none of them lies wholly outside. The children it meets are
        // kept beside its index: its walk starts from them rather than testing the root again.
        // The root and the box are copied out first: the loop's stores into `kept` and `roots`
        // could alias the tree for all the compiler knows, and it reloaded them per segment.
        let (root, present, bounds) = (self.tree.nodes[0], self.tree.present[0], self.bounds);
        let mut roots = vec![0u32; kept.len()];
        let mut n = 0;
        for k in 0..kept.len() {
            let index = kept[k];
            let s = segments[index];
            let entered = Self::root_entry(&root, present, &Ray::new(s.a, s.b, &bounds), &s);
            (kept[n], roots[n]) = (index, entered);
            n += usize::from((entered != 0) | ((bounds.outcode(s.a) | bounds.outcode(s.b)) == 0));
        }
        kept.truncate(n);
        // A batch that walks the tree more often than it has leaves reaches most of the window:
        // read it in order first, one load per cache line, at streaming speed, rather than by
        // a dependent miss per node and leaf when other work has evicted it.
        if kept.len() >= self.tree.leaves.len() {
            self.touch();
        }
        for (&index, &root_entered) in kept.iter().zip(&roots) {
            self.clip_one::<false>(index, segments[index], Some(root_entered), out, &mut crossings, &mut state);
        }
        Ok(())
    }
}
