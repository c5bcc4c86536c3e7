//! The active edge table (the paper's AET): the edges crossing the current scanline, ordered by x.

use std::cmp::Ordering;

use clip_core::predicates::{Orientation, accurate_crossing_point, on_line, orient, x_at_height_cmp};
use clip_core::{Point, Segment};

use crate::bounds::NONE;
use crate::order_index::OrderIndex;

/// Tables of at most this many edges are searched by a walk: a search tree over a table this
/// short costs more to keep than it saves. The scanbeam sweep, which walks the whole table in
/// every scanbeam anyway, never builds one.
const LINEAR_SEARCH_UP_TO: usize = 16;

/// Relative distance within which a computed crossing point counts as on an edge: a few dozen
/// ulps, the rounding of one crossing computation.
pub(crate) const ROUNDING: f64 = 4.0 * f64::EPSILON;

/// The largest error of [`Edge::x_at`] relative to the larger magnitude of the edge's ends' x:
/// with u = ε/2, its numerator's two products, difference and sum, and the division, err by at
/// most u·x_max (the product with `bot.x`), 2u·|x - bot.x| <= 4u·x_max (the other product) and
/// 2u·|x| (the sum and the quotient), 3.5 ε in all, below this bound. Two computed x farther apart than twice this (times the larger
/// magnitude) are in their exact order.
pub(crate) const X_AT_ERROR: f64 = 6.0 * f64::EPSILON;

/// An edge of a bound while it is active (the paper's edge record, Table 1). Never horizontal.
/// Aligned to a cache line: its 128 bytes then take two lines, never three, wherever the table's
/// buffer starts. The fields are laid out (`repr(C)`) so that what an event reads of the edges
/// around it, their ends, links and state, is the first line: where events fall at scattered
/// places in a long active list (edges ending in random order), each neighbour touched costs
/// one line missed instead of two.
#[derive(Clone, Debug)]
#[repr(C, align(64))]
pub(crate) struct Edge {
    // The first cache line: what an event reads of the edges around it (ends, links, state).
    /// Lower end.
    pub bot: Point,
    /// Upper end (`top.y > bot.y`).
    pub top: Point,
    /// Neighbours in the active edge table (`NONE` at the ends).
    pub prev: u32,
    pub next: u32,
    /// The last batch of new pairs this edge was returned in as a left edge.
    pub batch: u32,
    /// Output polygon this edge contributes to, or `NONE` (the paper's `poly`).
    pub outrec: u32,
    /// Input vertex at `top`.
    pub top_vertex: u32,
    /// Winding change when crossing this edge from left to right: +1 where the ring runs
    /// downwards, -1 where it runs upwards (counter-clockwise rings wind +1 inside).
    pub wind_dx: i32,
    /// Subject or clip.
    pub kind: u8,
    /// True when the bound walks the ring forwards.
    pub forward: bool,
    /// False once the bound has ended (at a local maximum).
    pub alive: bool,
    /// True while the edge waits to slide along a horizontal at the current scanline.
    pub moving: bool,
    /// True once a crossing on this edge other than at its bottom was taken or queued, or a
    /// vertex came within a near miss of it unrouted: its line has decided something above its
    /// bottom, so it can no longer be routed through a vertex (`near_misses`).
    pub tainted: bool,
    // The second: tolerances, positions along the sweep and the winding numbers.
    /// Magnitudes of the ends, kept with them for the tolerance tests (see [`Edge::set_ends`]).
    pub magnitude: EndMagnitudes,
    /// x at scanline `curr_y` (the paper's `xbot`), or where a sliding edge is.
    pub curr_x: f64,
    pub curr_y: f64,
    /// x at height `next_y`, computed once per scanbeam for its top (NaN height: none).
    pub next_x: f64,
    pub next_y: f64,
    /// Winding numbers (subject, clip) of the region just left of this edge.
    pub wind_left: [i32; 2],
}

// Two cache lines exactly (a field more would cost a third line per record), the second
// starting at `magnitude`.
const _: () = assert!(size_of::<Edge>() == 128 && std::mem::offset_of!(Edge, magnitude) == 64);

/// Magnitudes of an edge's ends, computed once per edge rather than per test.
#[derive(Clone, Copy, Debug)]
pub(crate) struct EndMagnitudes {
    /// max(|bot.x|, |top.x|).
    pub x_max: f64,
    /// The largest of the four coordinates' magnitudes.
    pub max: f64,
    /// |bot.x| + |top.x| + |bot.y| + |top.y|, added in that order.
    pub sum: f64,
}

impl EndMagnitudes {
    fn of(bot: Point, top: Point) -> EndMagnitudes {
        EndMagnitudes {
            x_max: bot.x.abs().max(top.x.abs()),
            max: bot.x.abs().max(top.x.abs()).max(bot.y.abs()).max(top.y.abs()),
            sum: bot.x.abs() + top.x.abs() + bot.y.abs() + top.y.abs(),
        }
    }
}

impl Edge {
    /// Moves the edge to `bot -> top`, its magnitudes with it.
    #[inline]
    pub(crate) fn set_ends(&mut self, bot: Point, top: Point) {
        self.bot = bot;
        self.top = top;
        self.magnitude = EndMagnitudes::of(bot, top);
    }

    /// Winding numbers of the region just right of this edge.
    #[inline]
    pub(crate) fn wind_right(&self) -> [i32; 2] {
        self.crossed(self.wind_left)
    }

    /// Winding numbers `w` after crossing this edge left to right. Both lanes are computed, none
    /// stored by index: a 4-byte store into the pair by a variable index, read back as 8 bytes,
    /// defeats store forwarding and stalled `SweepLine::cross` (about a quarter of scribble 20 ∩'s
    /// time in `perf`, under 1 % of its instructions).
    #[inline]
    pub(crate) fn crossed(&self, w: [i32; 2]) -> [i32; 2] {
        // `kind` is SUBJECT (0) or CLIP (1).
        let clip = i32::from(self.kind != 0);
        [w[0] + self.wind_dx * (1 - clip), w[1] + self.wind_dx * clip]
    }

    /// x where the edge crosses height `y`: exact at the ends and all along a vertical edge, and
    /// correctly rounded when the products and their sum are exact (integer grids), since the
    /// division comes last: then it is the value [`Edge::crossing_with`] computes for the same
    /// point, so a crossing on a scanline that a slide passes and the crossing of the edges
    /// through it are one point. (`x·dy / dy` is not always `x`: a vertical edge needs its case.)
    #[inline]
    pub(crate) fn x_at(&self, y: f64) -> f64 {
        let dx = self.top.x - self.bot.x;
        if y == self.top.y {
            self.top.x
        } else if y == self.bot.y || dx == 0.0 {
            self.bot.x
        } else {
            let dy = self.top.y - self.bot.y;
            (self.bot.x * dy + (y - self.bot.y) * dx) / dy
        }
    }

    /// x at `y`, from the scanbeam's cache when it is for `y`.
    #[inline]
    pub(crate) fn x_at_cached(&self, y: f64) -> f64 {
        if y == self.next_y { self.next_x } else { self.x_at(y) }
    }

    /// False when `p` (at a height within the edge's span) is clearly farther than
    /// `relative` times the coordinates' magnitude from the edge in x: a test without division,
    /// with twice the margin, done before [`Edge::offset_and_scale`].
    #[inline]
    pub(crate) fn maybe_near(&self, p: Point, relative: f64) -> bool {
        let d = self.top - self.bot;
        // (x_at(p.y) - p.x) * dy, with dy > 0.
        let off = (self.bot.x - p.x) * d.y + (p.y - self.bot.y) * d.x;
        // At least the largest magnitude `near` scales by.
        let sum = self.magnitude.sum + p.x.abs();
        off.abs() <= 2.0 * relative * sum * d.y
    }

    /// How far `p` lies from the edge in x, and the coordinates' magnitude: `p` is near within
    /// `relative` when the offset is at most `relative` times the magnitude. Within
    /// [`ROUNDING`]: a crossing point computed with another edge that, in exact arithmetic, lies
    /// on this one too.
    #[inline]
    pub(crate) fn offset_and_scale(&self, p: Point) -> (f64, f64) {
        let x = self.x_at(p.y);
        let scale = self.magnitude.max.max(p.x.abs());
        ((x - p.x).abs(), scale)
    }

    /// True when `p`, on a scanline where the edge's x is `x` (computed), is certainly off the
    /// edge: `x` is farther from `p.x` than its rounding can be (x_at errs by under 6 ulps of
    /// the ends' magnitude; the slack is ten times that). Spares the exact test for far edges.
    #[inline]
    pub(crate) fn clearly_off(&self, x: f64, p: Point) -> bool {
        (x - p.x).abs() > 64.0 * f64::EPSILON * self.magnitude.x_max
    }

    /// Where this edge and `other` cross, computed once and kept inside `[yb, yt]`: y clamped
    /// there (x then taken on the steeper edge), x clamped to the span of `xs`, the two edges'
    /// x at `yb` and `yt`. With a finite `max_error` (a certified sweep), a crossing whose
    /// quotient may err by more, or falls outside `[yb, yt]`, is computed from accurate
    /// determinants instead; and true comes back where it was still clamped onto an edge rising
    /// less than one per unit of x, whose x there is then off by more than its height's error.
    pub(crate) fn crossing_with(&self, other: &Edge, yb: f64, yt: f64, xs: [f64; 4], max_error: f64) -> (Point, bool) {
        // A swap at a vertex both edges start or end at: that vertex exactly, which the quotient
        // below can miss by an ulp (`bot.x * den` is rounded); the sweep of snap-rounded operands
        // must output no point but theirs. (Sharing an end, they meet nowhere else, or overlap.)
        if xs[0] == xs[2] && self.bot == other.bot {
            return (Point::new(xs[0], yb), false);
        }
        if xs[1] == xs[3] && self.top == other.top {
            return (Point::new(xs[1], yt), false);
        }
        let (d1, d2) = (self.top - self.bot, other.top - other.bot);
        let den = d1.cross(d2);
        let num = (other.bot - self.bot).cross(d2);
        // Division last: exact whenever the true point is representable and the products fit.
        let mut p = Point::new((self.bot.x * den + num * d1.x) / den, (self.bot.y * den + num * d1.y) / den);
        if !p.is_finite() {
            let s = num / den;
            p = Point::new(self.bot.x + s * d1.x, self.bot.y + s * d1.y);
        }
        let inside = |p: Point| p.y >= yb && p.y <= yt;
        // Edges at a small angle: the quotient above can be far off along them.
        if max_error.is_finite() && (!inside(p) || self.crossing_error(other) > max_error) {
            p = self.accurate_crossing(other).unwrap_or(p);
        }
        let mut off_flat = false;
        if !inside(p) {
            let y = if p.y > yt { yt } else { yb };
            let steeper = if (d1.x / d1.y).abs() <= (d2.x / d2.y).abs() { self } else { other };
            p = Point::new(steeper.x_at(y), y);
            let d = steeper.top - steeper.bot;
            off_flat = max_error.is_finite() && d.y < d.x.abs();
        }
        // On a vertical edge the crossing's x is that edge's, exactly.
        if d1.x == 0.0 || d2.x == 0.0 {
            return (Point::new(if d1.x == 0.0 { self.bot.x } else { other.bot.x }, p.y), off_flat);
        }
        let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        (Point::new(if p.x.is_finite() { p.x.clamp(lo, hi) } else { 0.5 * (lo + hi) }, p.y), off_flat)
    }

    /// A bound on how far the crossing with `other` that [`Edge::crossing_with`] computes from
    /// the quotient lies from the exact one, in each coordinate: the parameter `t = num / den`
    /// along this edge errs by under `4ε (num's terms + den's terms) / |den|` (each a difference
    /// of two products of differences), times the edge's extent, plus the final sums' rounding
    /// (`8ε` of the magnitudes).
    /// Large for edges at a small angle, where `den` cancels.
    #[inline]
    pub(crate) fn crossing_error(&self, other: &Edge) -> f64 {
        let (d1, d2) = (self.top - self.bot, other.top - other.bot);
        let w = other.bot - self.bot;
        let den = d1.cross(d2);
        let den_terms = (d1.x * d2.y).abs() + (d1.y * d2.x).abs();
        let num_terms = (w.x * d2.y).abs() + (w.y * d2.x).abs();
        let t_error = 4.0 * f64::EPSILON * (num_terms + den_terms) / den.abs();
        let along = d1.x.abs().max(d1.y.abs());
        t_error * along + 8.0 * f64::EPSILON * self.magnitude.max.max(other.magnitude.max)
    }

    /// The crossing with `other` from accurate determinants (`predicates::accurate_crossing_point`:
    /// about 8 ulps of this edge's extent off in each axis, and an ulp of the point), or `None`
    /// where that is not finite.
    #[cold]
    #[inline(never)]
    fn accurate_crossing(&self, other: &Edge) -> Option<Point> {
        let q = accurate_crossing_point(self.segment(), other.segment());
        q.is_finite().then_some(q)
    }

    /// True when this edge, left of `right` where both are active now, is right of it at the
    /// lower of their tops: they cross before either ends. Exact.
    #[inline]
    pub(crate) fn crosses_before_top(&self, right: &Edge) -> bool {
        if self.top.y <= right.top.y {
            orient(right.bot, right.top, self.top) == Orientation::Clockwise
        } else {
            orient(self.bot, self.top, right.top) == Orientation::CounterClockwise
        }
    }

    /// True when this edge passes strictly left of `other` at height `y` (within both spans),
    /// given their x there as [`Edge::x_at`] computes them: by those where they are farther
    /// apart than both can err, else exactly.
    #[inline(always)]
    pub(crate) fn left_of_at(&self, x: f64, other: &Edge, x_other: f64, y: f64) -> bool {
        if (x - x_other).abs() > 2.0 * X_AT_ERROR * self.magnitude.x_max.max(other.magnitude.x_max) {
            return x < x_other;
        }
        self.left_of_at_exactly(other, y)
    }

    /// [`Edge::left_of_at`] decided exactly: rare (x within rounding of each other), so out of
    /// line. Rounded x there would order two edges a pixel apart far from the origin by their
    /// rounding, and invent a crossing of snap-rounded edges, which meet only at vertices.
    #[cold]
    #[inline(never)]
    pub(crate) fn left_of_at_exactly(&self, other: &Edge, y: f64) -> bool {
        // Both ending at `y` (the case a sweep meets most): their tops are exact.
        if self.top.y == y && other.top.y == y {
            return self.top.x < other.top.x;
        }
        x_at_height_cmp(self.segment(), other.segment(), y) == Ordering::Less
    }

    /// Where this edge, at computed x `x` on scanline `y`, is passed by an edge moving along a
    /// horizontal from x `ends[0]` to `ends[1]` (the part still to pass: `lo` to `hi`), and
    /// whether that point is rounded. The point is `x` clamped to the part, exact where this edge
    /// is sliding (its x is an input vertex's), where it was clamped, or where it is an end of
    /// this edge or on its line; else the end of the horizontal this edge passes exactly through
    /// (snap-rounded operands meet only at vertices, and `x` can be ulps off the vertex), else
    /// `x`, rounded. Only a rounded point may join the chains of edges merely near it.
    pub(crate) fn passed_at(&self, x: f64, y: f64, lo: f64, hi: f64, ends: [f64; 2]) -> (Point, bool) {
        let p = Point::new(x.clamp(lo, hi), y);
        if self.moving || p.x != x || p == self.bot || p == self.top || on_line(self.segment(), p) {
            return (p, false);
        }
        for end in ends {
            let q = Point::new(end, y);
            if (lo..=hi).contains(&end) && !self.clearly_off(x, q) && on_line(self.segment(), q) {
                return (q, false);
            }
        }
        (p, true)
    }

    /// The edge as a segment, bottom to top.
    #[inline]
    pub(crate) fn segment(&self) -> Segment {
        Segment::new(self.bot, self.top)
    }

    /// True when the edge ends at or below `y`.
    #[inline]
    pub(crate) fn ends_by(&self, y: f64) -> bool {
        self.top.y <= y
    }

    /// Where `p` lies relative to the edge's line: `CounterClockwise` is left.
    #[inline]
    pub(crate) fn side_of(&self, p: Point) -> Orientation {
        orient(self.bot, self.top, p)
    }

    /// True when `p` lies exactly on the edge's line, decided exactly where the float
    /// determinant is zero; false where it is not, even for a point exactly on the line whose
    /// determinant rounds off zero (callers read false as "maybe off": safe). Cheap for the
    /// rounded crossings it mostly meets, which the exact test would take its slow path on.
    #[inline]
    pub(crate) fn surely_through(&self, p: Point) -> bool {
        (p - self.bot).cross(self.top - self.bot) == 0.0 && self.side_of(p) == Orientation::Collinear
    }
}

/// The active edges: an arena of edge records, their left-to-right order as a doubly linked
/// list (neighbours in O(1)), and a search tree over that order (`order_index`) where new edges
/// find their place in O(log n). A bound's record is reused for a later bound once the bound has
/// ended and its scanline is done, so the arena is as large as the widest active edge table, not
/// one record per bound.
#[derive(Debug, Default)]
pub(crate) struct ActiveEdges {
    pub edges: Vec<Edge>,
    first: u32,
    len: usize,
    /// The search tree over the order, kept only by the event sweep and only while the table
    /// is longer than [`LINEAR_SEARCH_UP_TO`] (built when it first is).
    index: OrderIndex,
    indexed: bool,
    /// Records free for new edges.
    free: Vec<u32>,
    /// Records of edges that ended on the current scanline: the scanline's work lists may still
    /// name them (and check `alive`), so they are freed only when it is done.
    ended: Vec<u32>,
    /// When set, the left edges of pairs that became adjacent (`new_pairs`), for the event
    /// sweep's crossing tests.
    track: bool,
    new_pairs: Vec<u32>,
    /// The batch of [`ActiveEdges::take_new_pairs`], stamped on the edges it returned.
    batch: u32,
}

impl ActiveEdges {
    /// Empties the table, keeping its buffers, with room for `records` edges (every record the
    /// sweep can make: two per local minimum); `track` records the edges whose neighbours change.
    ///
    /// Reserved, not grown: growing a vector of over-aligned records is an allocation, a copy
    /// and a free, into fresh pages each time, and with many edges active at once those copies
    /// and page faults (the allocator's heap churned with them) were a large part of the clip
    /// (PERFORMANCE.md). Reserved pages that are never written hold no memory.
    pub(crate) fn reset(&mut self, track: bool, records: usize) {
        self.edges.clear();
        self.edges.reserve(records);
        self.first = NONE;
        self.len = 0;
        self.index.reset(records);
        self.indexed = false;
        self.free.clear();
        self.ended.clear();
        self.track = track;
        self.new_pairs.clear();
        self.batch = 0;
    }

    /// The current scanline is done: the records of the edges that ended on it are free.
    #[inline]
    pub(crate) fn scanline_done(&mut self) {
        if !self.ended.is_empty() {
            self.free.append(&mut self.ended);
        }
    }

    /// Bytes of capacity the table holds.
    pub(crate) fn held_bytes(&self) -> usize {
        // Records written, not reserved: the reserve's untouched pages hold no memory.
        self.edges.len() * std::mem::size_of::<Edge>()
            + self.index.held_bytes()
            + 4 * (self.free.capacity() + self.ended.capacity() + self.new_pairs.capacity())
    }

    /// A new edge in the arena (not yet in the order).
    pub(crate) fn create(&mut self, bot: Point, top: Point, kind: u8, forward: bool, top_vertex: u32) -> u32 {
        let edge = Edge {
            bot,
            top,
            magnitude: EndMagnitudes::of(bot, top),
            curr_x: bot.x,
            curr_y: bot.y,
            next_x: bot.x,
            next_y: f64::NAN,
            kind,
            wind_dx: if forward { -1 } else { 1 },
            wind_left: [0, 0],
            outrec: NONE,
            top_vertex,
            forward,
            alive: true,
            moving: false,
            tainted: false,
            prev: NONE,
            next: NONE,
            batch: 0,
        };
        if let Some(id) = self.free.pop() {
            self.edges[id as usize] = edge;
            id
        } else {
            self.edges.push(edge);
            self.edges.len() as u32 - 1
        }
    }

    #[inline]
    pub(crate) fn get(&self, id: u32) -> &Edge {
        &self.edges[id as usize]
    }

    #[inline]
    pub(crate) fn get_mut(&mut self, id: u32) -> &mut Edge {
        &mut self.edges[id as usize]
    }

    /// Number of edges in the order.
    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.len
    }

    /// The leftmost edge, or `NONE`.
    #[inline]
    pub(crate) fn first(&self) -> u32 {
        self.first
    }

    /// The edge right of `id`, or `NONE`.
    #[inline]
    pub(crate) fn next(&self, id: u32) -> u32 {
        self.edges[id as usize].next
    }

    /// The edge left of `id`, or `NONE`.
    #[inline]
    pub(crate) fn prev(&self, id: u32) -> u32 {
        self.edges[id as usize].prev
    }

    /// The edges left to right.
    pub(crate) fn iter(&self) -> impl Iterator<Item = u32> + '_ {
        std::iter::successors((self.first != NONE).then_some(self.first), |&id| {
            let n = self.next(id);
            (n != NONE).then_some(n)
        })
    }

    /// Winding numbers just right of `left` (`NONE`: the outside, [0, 0]).
    #[inline]
    pub(crate) fn wind_right_of(&self, left: u32) -> [i32; 2] {
        if left == NONE { [0, 0] } else { self.get(left).wind_right() }
    }

    /// Records that `left` and its right neighbour `right` became adjacent.
    #[inline]
    fn paired(&mut self, left: u32, right: u32) {
        if self.track && left != NONE && right != NONE {
            self.new_pairs.push(left);
        }
    }

    /// The left edges of the adjacent pairs made since the last call, each once and still
    /// active with a right neighbour, into `out` (emptied first).
    pub(crate) fn take_new_pairs(&mut self, out: &mut Vec<u32>) {
        out.clear();
        self.batch = self.batch.wrapping_add(1);
        for &id in &self.new_pairs {
            let e = &mut self.edges[id as usize];
            if e.alive && e.next != NONE && e.batch != self.batch {
                e.batch = self.batch;
                out.push(id);
            }
        }
        self.new_pairs.clear();
    }

    /// Links `id` into the list between `left` and `right` (neighbours, either `NONE`).
    fn link(&mut self, id: u32, left: u32, right: u32) {
        self.edges[id as usize].prev = left;
        self.edges[id as usize].next = right;
        if left == NONE {
            self.first = id;
        } else {
            self.edges[left as usize].next = id;
        }
        if right != NONE {
            self.edges[right as usize].prev = id;
        }
        self.len += 1;
        self.paired(left, id);
        self.paired(id, right);
    }

    /// Puts a new edge from `p` (on the current scanline) towards `toward` where it belongs:
    /// before the first edge that passes right of `p`, or through `p` heading right of the new
    /// edge. Exact; a search of the order, which is sorted at the scanline: through the tree
    /// when there is one, else a walk from the left, which a short table makes cheaper.
    pub(crate) fn insert_at(&mut self, id: u32, p: Point, toward: Point) {
        let before = |e: &Edge| match e.side_of(p) {
            Orientation::Clockwise => true,
            Orientation::CounterClockwise => false,
            Orientation::Collinear => orient(p, toward, e.top) != Orientation::Clockwise,
        };
        let (left, right) = if self.indexed {
            let edges = &self.edges;
            self.index.insert_by(id, |k| before(&edges[k as usize]))
        } else {
            let (mut left, mut right) = (NONE, self.first);
            while right != NONE && before(&self.edges[right as usize]) {
                left = right;
                right = self.next(right);
            }
            (left, right)
        };
        self.link(id, left, right);
        self.index_if_long();
    }

    /// Puts a new edge right after `left` (first when `NONE`).
    pub(crate) fn insert_after(&mut self, id: u32, left: u32) {
        if self.indexed {
            self.index.insert_after(id, left);
        }
        let right = if left == NONE { self.first } else { self.next(left) };
        self.link(id, left, right);
        self.index_if_long();
    }

    /// Builds the search tree when the event sweep's table first grows past
    /// [`LINEAR_SEARCH_UP_TO`].
    #[inline]
    fn index_if_long(&mut self) {
        if self.track && !self.indexed && self.len > LINEAR_SEARCH_UP_TO {
            self.indexed = true;
            let mut left = NONE;
            let mut id = self.first;
            while id != NONE {
                self.index.insert_after(id, left);
                left = id;
                id = self.next(id);
            }
        }
    }

    /// The active edge whose bound runs the other way from `id`'s and ends at vertex `v` (its
    /// partner at a local maximum), and whether it lies right of `id`: searched outward from
    /// `id`, next to which it lies but for edges passing through the maximum.
    pub(crate) fn partner(&self, id: u32, v: u32) -> Option<(u32, bool)> {
        let forward = self.get(id).forward;
        let is_partner = |k: u32| {
            let e = self.get(k);
            e.top_vertex == v && e.forward != forward
        };
        let (mut l, mut r) = (self.prev(id), self.next(id));
        while l != NONE || r != NONE {
            if l != NONE {
                if is_partner(l) {
                    return Some((l, false));
                }
                l = self.prev(l);
            }
            if r != NONE {
                if is_partner(r) {
                    return Some((r, true));
                }
                r = self.next(r);
            }
        }
        None
    }

    /// Removes the adjacent edges `a` and `b = next(a)`.
    pub(crate) fn remove_pair(&mut self, a: u32) {
        let b = self.next(a);
        let (left, right) = (self.prev(a), self.next(b));
        for id in [a, b] {
            if self.indexed {
                self.index.remove(id);
            }
            let e = &mut self.edges[id as usize];
            e.alive = false;
            e.prev = NONE;
            e.next = NONE;
            self.ended.push(id);
        }
        if left == NONE {
            self.first = right;
        } else {
            self.edges[left as usize].next = right;
        }
        if right != NONE {
            self.edges[right as usize].prev = left;
        }
        self.len -= 2;
        self.paired(left, right);
    }

    /// Swaps `a` and its right neighbour.
    #[inline]
    pub(crate) fn swap(&mut self, a: u32) {
        let b = self.next(a);
        let (left, right) = (self.prev(a), self.next(b));
        if self.indexed {
            self.index.swap(a, b);
        }
        if left == NONE {
            self.first = b;
        } else {
            self.edges[left as usize].next = b;
        }
        if right != NONE {
            self.edges[right as usize].prev = a;
        }
        let ea = &mut self.edges[a as usize];
        ea.prev = b;
        ea.next = right;
        let eb = &mut self.edges[b as usize];
        eb.prev = left;
        eb.next = a;
        // Not b and a, which crossed (see `recheck`).
        self.paired(left, b);
        self.paired(a, right);
    }

    /// `left` and its right neighbour, just swapped at a scanline without crossing (an edge
    /// sliding along a horizontal past another), are tested again: their segments may still
    /// cross above it.
    #[inline]
    pub(crate) fn recheck(&mut self, left: u32) {
        let right = self.next(left);
        self.paired(left, right);
    }

    /// `id`'s segment changed in place (a bound's next edge): both its pairs are new.
    #[inline]
    pub(crate) fn segment_changed(&mut self, id: u32) {
        let (left, right) = (self.prev(id), self.next(id));
        self.paired(left, id);
        self.paired(id, right);
    }

    /// x of edge `id` on scanline `y`: where it slides for a sliding edge, else on its line,
    /// cached per scanline.
    #[inline]
    pub(crate) fn x_on(&mut self, id: u32, y: f64) -> f64 {
        let e = &mut self.edges[id as usize];
        if e.curr_y != y && !e.moving {
            e.curr_x = e.x_at(y);
            e.curr_y = y;
        }
        e.curr_x
    }
}
