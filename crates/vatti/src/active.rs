//! The active edge table (the paper's AET): the edges crossing the current scanbeam, ordered by x.

use clip_core::Point;
use clip_core::predicates::{Orientation, orient};

use crate::bounds::NONE;

/// Relative distance within which a computed crossing point counts as on an edge: a few dozen
/// ulps, the rounding of one crossing computation.
pub(crate) const ROUNDING: f64 = 4.0 * f64::EPSILON;

/// An edge of a bound while it is active (the paper's edge record, Table 1). Never horizontal.
#[derive(Clone, Debug)]
pub(crate) struct Edge {
    /// Lower end.
    pub bot: Point,
    /// Upper end (`top.y > bot.y`).
    pub top: Point,
    /// Magnitudes of the ends, kept with them for the tolerance tests (see [`Edge::set_ends`]).
    pub magnitude: EndMagnitudes,
    /// x at the current scanline (the paper's `xbot`).
    pub curr_x: f64,
    /// x at height `next_y`, computed once per scanbeam for its top (NaN height: none).
    pub next_x: f64,
    pub next_y: f64,
    /// Subject or clip.
    pub kind: u8,
    /// Winding change when crossing this edge from left to right: +1 where the ring runs
    /// downwards, -1 where it runs upwards (counter-clockwise rings wind +1 inside).
    pub wind_dx: i32,
    /// Winding numbers (subject, clip) of the region just left of this edge.
    pub wind_left: [i32; 2],
    /// Output polygon this edge contributes to, or `NONE` (the paper's `poly`).
    pub outrec: u32,
    /// Input vertex at `top`.
    pub top_vertex: u32,
    /// True when the bound walks the ring forwards.
    pub forward: bool,
    /// False once the bound has ended (at a local maximum).
    pub alive: bool,
    /// True while the edge waits to slide along a horizontal at the current scanline.
    pub moving: bool,
    /// Index in the active edge table.
    pub pos: u32,
}

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
    /// defeats store forwarding and stalled `Sweep::cross` (about a quarter of scribble 20 ∩'s
    /// time in `perf`, under 1 % of its instructions).
    #[inline]
    pub(crate) fn crossed(&self, w: [i32; 2]) -> [i32; 2] {
        // `kind` is SUBJECT (0) or CLIP (1).
        let clip = i32::from(self.kind != 0);
        [w[0] + self.wind_dx * (1 - clip), w[1] + self.wind_dx * clip]
    }

    /// x where the edge crosses height `y`: exact at the ends, and correctly rounded when the
    /// product fits (always for integer grids), since the division comes last.
    #[inline]
    pub(crate) fn x_at(&self, y: f64) -> f64 {
        if y == self.top.y {
            self.top.x
        } else if y == self.bot.y {
            self.bot.x
        } else {
            self.bot.x + ((y - self.bot.y) * (self.top.x - self.bot.x)) / (self.top.y - self.bot.y)
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

    /// True when `p`, on the current scanline, is certainly off the edge: `curr_x`, the edge's
    /// x there, is farther from `p.x` than its rounding can be (x_at errs by under 6 ulps of the
    /// ends' magnitude; the slack is ten times that). Spares the exact test for far edges.
    #[inline]
    pub(crate) fn clearly_off_scanline(&self, p: Point) -> bool {
        (self.curr_x - p.x).abs() > 64.0 * f64::EPSILON * self.magnitude.x_max
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
}

/// The active edges: an arena of edge records and their x order. A bound's record is reused
/// for a later bound once the bound has ended and its scanline is done, so the arena is as large
/// as the widest active edge table, not one record per bound.
#[derive(Debug, Default)]
pub(crate) struct ActiveEdges {
    pub edges: Vec<Edge>,
    pub order: Vec<u32>,
    /// Records free for new edges.
    free: Vec<u32>,
    /// Records of edges that ended on the current scanline: the scanline's work lists may still
    /// name them (and check `alive`), so they are freed only when it is done.
    ended: Vec<u32>,
}

impl ActiveEdges {
    /// Empties the table, keeping its buffers.
    pub(crate) fn reset(&mut self) {
        self.edges.clear();
        self.order.clear();
        self.free.clear();
        self.ended.clear();
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
        self.edges.capacity() * std::mem::size_of::<Edge>()
            + 4 * (self.order.capacity() + self.free.capacity() + self.ended.capacity())
    }

    /// A new edge in the arena (not yet in the order).
    pub(crate) fn create(&mut self, bot: Point, top: Point, kind: u8, forward: bool, top_vertex: u32) -> u32 {
        let edge = Edge {
            bot,
            top,
            magnitude: EndMagnitudes::of(bot, top),
            curr_x: bot.x,
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
            pos: NONE,
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

    #[inline]
    pub(crate) fn at(&self, pos: usize) -> u32 {
        self.order[pos]
    }

    #[inline]
    pub(crate) fn len(&self) -> usize {
        self.order.len()
    }

    #[inline]
    pub(crate) fn pos(&self, id: u32) -> usize {
        self.edges[id as usize].pos as usize
    }

    /// Winding numbers just right of position `pos - 1`: the region a new edge at `pos` has on
    /// its left.
    #[inline]
    pub(crate) fn wind_before(&self, pos: usize) -> [i32; 2] {
        if pos == 0 { [0, 0] } else { self.get(self.order[pos - 1]).wind_right() }
    }

    /// Puts edge `id` at `pos`.
    pub(crate) fn insert(&mut self, pos: usize, id: u32) {
        self.order.insert(pos, id);
        self.renumber(pos);
    }

    /// The active edge whose bound runs the other way from `id`'s and ends at vertex `v` (its
    /// partner at a local maximum): searched outward from `id`, next to which it lies but for
    /// edges passing through the maximum.
    pub(crate) fn partner(&self, id: u32, v: u32) -> Option<u32> {
        let (pos, forward) = (self.pos(id), self.get(id).forward);
        let is_partner = |k: u32| {
            let e = self.get(k);
            e.top_vertex == v && e.forward != forward
        };
        let n = self.order.len();
        for d in 1..n.max(1) {
            if d > pos && pos + d >= n {
                break;
            }
            if d <= pos && is_partner(self.order[pos - d]) {
                return Some(self.order[pos - d]);
            }
            if pos + d < n && is_partner(self.order[pos + d]) {
                return Some(self.order[pos + d]);
            }
        }
        None
    }

    /// Removes the two edges at `pos` and `pos + 1`.
    pub(crate) fn remove_pair(&mut self, pos: usize) {
        for id in [self.order[pos], self.order[pos + 1]] {
            self.edges[id as usize].alive = false;
            self.ended.push(id);
        }
        let n = self.order.len();
        self.order.copy_within(pos + 2..n, pos);
        self.order.truncate(n - 2);
        self.renumber(pos);
    }

    /// Swaps the adjacent edges at `pos` and `pos + 1`.
    #[inline]
    pub(crate) fn swap(&mut self, pos: usize) {
        self.order.swap(pos, pos + 1);
        let (a, b) = (self.order[pos], self.order[pos + 1]);
        self.edges[a as usize].pos = pos as u32;
        self.edges[b as usize].pos = pos as u32 + 1;
    }

    fn renumber(&mut self, from: usize) {
        for (i, &id) in self.order.iter().enumerate().skip(from) {
            self.edges[id as usize].pos = i as u32;
        }
    }

    /// Where a new edge from `p` (on the current scanline) towards `toward` goes: before the
    /// first edge that passes right of `p`, or through `p` heading right of the new edge.
    /// Exact; binary search over an order that is sorted at the scanline.
    pub(crate) fn insert_position(&self, p: Point, toward: Point) -> usize {
        self.order.partition_point(|&id| {
            let e = self.get(id);
            match e.side_of(p) {
                Orientation::Clockwise => true,
                Orientation::CounterClockwise => false,
                Orientation::Collinear => orient(p, toward, e.top) != Orientation::Clockwise,
            }
        })
    }
}
