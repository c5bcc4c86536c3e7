//! The sweep: scanbeams bottom to top, local minima inserted, edge tops processed, and the
//! events that change the output (crossings, starts and ends of bounds).

use clip_core::predicates::{Orientation, orient};
use clip_core::{Point, Trapezoid};

use crate::active::{ActiveEdges, ROUNDING};
use crate::bounds::{Bounds, LocalMinimum, NONE};
use crate::contribution::{Crossing, Rules, classify};
use crate::intersections::{Intersection, TopX};
use crate::output::OutputBuilder;
use crate::scanbeam::Scanbeams;

/// A pending slide along a horizontal edge at the current scanline.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Slide {
    /// The edge that slides.
    pub edge: u32,
    /// Where it starts and where it stops.
    pub from_x: f64,
    pub to_x: f64,
    /// For a horizontal local maximum, the vertex where the partner bound ends; else `NONE`.
    pub max_vertex: u32,
}

/// The sweep's buffers between runs, so a thread's next clip can reuse them.
#[derive(Debug, Default)]
pub(crate) struct SweepBuffers {
    ael: ActiveEdges,
    beams: Scanbeams,
    out: OutputBuilder,
    traps: Vec<Trapezoid>,
    maxima: Vec<u32>,
    settle: Vec<u32>,
    slides: Vec<Slide>,
    xtop: Vec<TopX>,
    sorted: Vec<u32>,
    table: Vec<Intersection>,
}

impl SweepBuffers {
    /// Bytes the buffers hold (their capacity), to decide whether keeping them is worth it.
    pub(crate) fn held_bytes(&self) -> usize {
        use std::mem::size_of;
        self.ael.held_bytes()
            + self.out.held_bytes()
            + self.traps.capacity() * size_of::<Trapezoid>()
            + self.table.capacity() * size_of::<Intersection>()
            + self.slides.capacity() * size_of::<Slide>()
            + self.xtop.capacity() * size_of::<TopX>()
            + 8 * (self.beams.capacity() + self.maxima.capacity() + self.settle.capacity() + self.sorted.capacity())
    }
}

/// One run of the clipper over two operands.
pub(crate) struct Sweep<'a> {
    pub rules: Rules,
    pub bounds: &'a Bounds,
    pub ael: ActiveEdges,
    pub beams: Scanbeams,
    pub out: OutputBuilder,
    /// Trapezoids, when asked for.
    pub traps: Option<Vec<Trapezoid>>,
    next_minimum: usize,
    // Work lists reused between scanlines.
    maxima: Vec<u32>,
    settle: Vec<u32>,
    slides: Vec<Slide>,
    /// The sorted edge table's x values at the scanbeam top, and its order (reused buffers).
    pub(crate) xtop: Vec<TopX>,
    pub(crate) sorted: Vec<u32>,
    /// The intersection table's buffer, reused between scanbeams.
    pub(crate) table: Vec<Intersection>,
    /// True while a crossing at a computed (rounded) point is processed: only such a point may
    /// join the chain of an edge it lies within rounding of; any other point is an exact input
    /// vertex.
    pub(crate) rounded_crossing: bool,
}

impl<'a> Sweep<'a> {
    /// A sweep over `bounds` in the given (emptied) buffers.
    pub(crate) fn new(bounds: &'a Bounds, rules: Rules, trapezoids: bool, buffers: SweepBuffers) -> Sweep<'a> {
        let SweepBuffers {
            mut ael,
            mut beams,
            mut out,
            mut traps,
            mut maxima,
            mut settle,
            mut slides,
            mut xtop,
            mut sorted,
            mut table,
        } = buffers;
        ael.reset();
        beams.rebuild(&bounds.vertices);
        out.reset(if trapezoids { 0 } else { bounds.vertices.len() });
        traps.clear();
        maxima.clear();
        settle.clear();
        slides.clear();
        xtop.clear();
        sorted.clear();
        table.clear();
        Sweep {
            rules,
            bounds,
            ael,
            beams,
            out,
            traps: trapezoids.then_some(traps),
            next_minimum: 0,
            maxima,
            settle,
            slides,
            xtop,
            sorted,
            table,
            rounded_crossing: false,
        }
    }

    /// The buffers back, for the next sweep (trapezoids, if any, moved out first).
    pub(crate) fn into_buffers(self) -> SweepBuffers {
        let Sweep { ael, beams, out, traps, maxima, settle, slides, xtop, sorted, table, .. } = self;
        SweepBuffers { ael, beams, out, traps: traps.unwrap_or_default(), maxima, settle, slides, xtop, sorted, table }
    }

    /// Runs the whole sweep. Every scanline is a distinct y above the previous one, taken from
    /// the finitely many vertex heights, so the loop ends.
    pub(crate) fn run(&mut self) {
        let Some(first) = self.bounds.minima.first() else { return };
        let mut y = self.bounds.minimum_y(first);
        loop {
            self.top_of_scanbeam(y);
            self.insert_local_minima(y);
            // The minima's heights are among the scanlines.
            let Some(next) = self.beams.next_above(y) else { break };
            self.ael.scanline_done();
            self.process_intersections(y, next);
            y = next;
        }
        self.beams.release_if_large();
    }

    // ---- edges ----

    /// Makes the active edge for the bound leaving vertex `from` towards `to`.
    fn new_edge(&mut self, from: u32, to: u32, kind: u8, forward: bool) -> u32 {
        let (bot, top) = (self.bounds.pt(from), self.bounds.pt(to));
        self.ael.create(bot, top, kind, forward, to)
    }

    /// The other bound's edge ending at vertex `v`, opposite in direction to `id`.
    fn partner_at(&self, id: u32, v: u32) -> Option<u32> {
        if !self.ael.get(id).alive {
            return None;
        }
        self.ael.partner(id, v)
    }

    // ---- local minima ----

    fn insert_local_minima(&mut self, y: f64) {
        while let Some(&m) = self.bounds.minima.get(self.next_minimum) {
            if self.bounds.minimum_y(&m) != y {
                break;
            }
            self.next_minimum += 1;
            self.insert_local_minimum(m);
        }
    }

    /// AddEdges for one local minimum: both bounds enter the table side by side at its vertex;
    /// with a horizontal bottom the forward bound then slides to the horizontal's other end.
    fn insert_local_minimum(&mut self, m: LocalMinimum) {
        let v = m.vertex;
        let vx = self.bounds.vertices[v as usize];
        let p = vx.pt;
        let backward = self.new_edge(v, vx.prev, m.kind, false);
        let (fwd_from, fwd_to) = if m.horizontal {
            let u = vx.next;
            (u, self.bounds.vertices[u as usize].next)
        } else {
            (v, vx.next)
        };
        let forward = self.new_edge(fwd_from, fwd_to, m.kind, true);
        // Which goes left: by direction at `p`; with a horizontal bottom, the forward bound sits on
        // the side of the horizontal's far end, next to where the backward bound belongs.
        let (backward_top, forward_top) = (self.ael.get(backward).top, self.ael.get(forward).top);
        let forward_left = if m.horizontal {
            self.bounds.pt(fwd_from).x < p.x
        } else {
            orient(p, backward_top, forward_top) == Orientation::CounterClockwise
        };
        let (left, right) = if forward_left { (forward, backward) } else { (backward, forward) };
        let pos = self.ael.insert_position(p, if m.horizontal { backward_top } else { self.ael.get(left).top });
        self.ael.get_mut(forward).curr_x = p.x;
        // With a horizontal bottom the forward edge starts away from p: it slides there.
        self.ael.get_mut(forward).moving = m.horizontal;
        let wl = self.ael.wind_before(pos);
        self.ael.get_mut(left).wind_left = wl;
        self.ael.insert(pos, left);
        let wm = self.ael.get(left).wind_right();
        self.ael.get_mut(right).wind_left = wm;
        self.ael.insert(pos + 1, right);
        let (i0, i1) = (self.rules.inside(wl), self.rules.inside(wm));
        if i0 != i1 {
            if i1 { self.start_output(left, right, p) } else { self.start_output(right, left, p) }
        }
        if m.horizontal {
            let to = self.bounds.pt(fwd_from);
            self.slide(Slide { edge: forward, from_x: p.x, to_x: to.x, max_vertex: NONE }, p.y);
            self.ael.get_mut(forward).moving = false;
            self.add_point(forward, to);
        } else {
            self.settle(right);
            self.settle(left);
        }
    }

    // ---- top of scanbeam ----

    /// Edges reaching scanline `y`: intermediate vertices hand over to successor edges, local
    /// maxima end pairs of bounds, horizontals make edges slide.
    fn top_of_scanbeam(&mut self, y: f64) {
        for pos in 0..self.ael.len() {
            let id = self.ael.at(pos);
            let e = self.ael.get_mut(id);
            if e.top.y != y {
                e.curr_x = e.x_at_cached(y);
                continue;
            }
            e.curr_x = e.top.x;
            let (t, forward) = (e.top_vertex, e.forward);
            let u = self.bounds.along(t, forward);
            let (tp, up) = (self.bounds.pt(t), self.bounds.pt(u));
            if up.y > y {
                let s = self.succeed(pos, t, u);
                self.settle.push(s);
            } else if up.y < y {
                self.maxima.push(id);
            } else {
                let w = self.bounds.along(u, forward);
                if self.bounds.pt(w).y > y {
                    let s = self.succeed(pos, u, w);
                    let e = self.ael.get_mut(s);
                    e.curr_x = tp.x;
                    e.moving = true;
                    self.slides.push(Slide { edge: s, from_x: tp.x, to_x: up.x, max_vertex: NONE });
                } else if forward {
                    self.ael.get_mut(id).moving = true;
                    self.slides.push(Slide { edge: id, from_x: tp.x, to_x: up.x, max_vertex: u });
                }
            }
        }
        // The lists are read by index: the events below never add to them.
        for i in 0..self.maxima.len() {
            let id = self.maxima[i];
            if !self.ael.get(id).alive {
                continue;
            }
            let t = self.ael.get(id).top_vertex;
            let tp = self.bounds.pt(t);
            if let Some(partner) = self.partner_at(id, t) {
                self.meet(id, partner, tp, tp.x, tp.x, tp.y);
            }
        }
        for i in 0..self.settle.len() {
            let id = self.settle[i];
            if self.ael.get(id).alive {
                self.settle(id);
            }
        }
        for i in 0..self.slides.len() {
            let s = self.slides[i];
            if s.max_vertex == NONE {
                self.slide(s, y);
                self.ael.get_mut(s.edge).moving = false;
                let to = Point::new(s.to_x, y);
                self.add_point(s.edge, to);
                self.settle(s.edge);
            } else if let Some(partner) = self.partner_at(s.edge, s.max_vertex) {
                let e = self.ael.get(s.edge);
                let tp = e.top;
                if e.outrec != NONE {
                    self.add_point(s.edge, tp);
                }
                let mp = self.bounds.pt(s.max_vertex);
                self.meet(s.edge, partner, mp, s.from_x, s.to_x, y);
            }
            self.ael.get_mut(s.edge).moving = false;
        }
        self.maxima.clear();
        self.settle.clear();
        self.slides.clear();
    }

    /// Moves the edge at `pos` on to its bound's next edge `from -> to` (an intermediate vertex
    /// at the old edge's top: its output chain, if any, gets the vertex). The bound keeps its
    /// edge record, winding counts and output chain, as Vatti's edge record does.
    fn succeed(&mut self, pos: usize, from: u32, to: u32) -> u32 {
        let id = self.ael.at(pos);
        let (rec, top) = {
            let e = self.ael.get(id);
            (e.outrec, e.top)
        };
        if rec != NONE {
            self.add_point(id, top);
        }
        let (bot, next_top) = (self.bounds.pt(from), self.bounds.pt(to));
        let e = self.ael.get_mut(id);
        e.set_ends(bot, next_top);
        e.top_vertex = to;
        e.curr_x = top.x;
        e.next_y = f64::NAN;
        id
    }

    /// Moves edge `id` across the edges between it and `partner` (crossings at the
    /// scanline, x clamped to `[from_x, to_x]`), then ends both bounds at `p`: AddLocalMax.
    fn meet(&mut self, id: u32, partner: u32, p: Point, from_x: f64, to_x: f64, y: f64) {
        let (lo, hi) = (from_x.min(to_x), from_x.max(to_x));
        let n = self.ael.len();
        for _ in 0..n {
            let (pos, ppos) = (self.ael.pos(id), self.ael.pos(partner));
            if pos + 1 == ppos || ppos + 1 == pos {
                break;
            }
            // The crossings are at the other edges' rounded x on this scanline.
            self.rounded_crossing = true;
            if ppos > pos {
                let k = self.ael.at(pos + 1);
                let x = self.ael.get(k).curr_x.clamp(lo, hi);
                self.cross(pos, Point::new(x, y));
            } else {
                let k = self.ael.at(pos - 1);
                let x = self.ael.get(k).curr_x.clamp(lo, hi);
                self.cross(pos - 1, Point::new(x, y));
            }
            self.rounded_crossing = false;
        }
        let (pos, ppos) = (self.ael.pos(id), self.ael.pos(partner));
        if pos + 1 == ppos || ppos + 1 == pos {
            self.end_pair(pos.min(ppos), p);
        }
    }

    /// Orders a new edge starting at its bottom among edges through the same point by
    /// direction above it: exact, with crossings at that point. Called on the current scanline,
    /// where every active edge's `curr_x` is its x there.
    fn settle(&mut self, id: u32) {
        let (p, top) = (self.ael.get(id).bot, self.ael.get(id).top);
        let n = self.ael.len();
        for _ in 0..n {
            let pos = self.ael.pos(id);
            if pos + 1 >= self.ael.len() {
                break;
            }
            let k = self.ael.get(self.ael.at(pos + 1));
            if k.moving || k.ends_by(p.y) || k.clearly_off_scanline(p) || k.side_of(p) != Orientation::Collinear {
                break;
            }
            if orient(p, top, k.top) != Orientation::CounterClockwise {
                break;
            }
            self.cross(pos, p);
        }
        for _ in 0..n {
            let pos = self.ael.pos(id);
            if pos == 0 {
                break;
            }
            let k = self.ael.get(self.ael.at(pos - 1));
            if k.moving || k.ends_by(p.y) || k.clearly_off_scanline(p) || k.side_of(p) != Orientation::Collinear {
                break;
            }
            if orient(p, top, k.top) != Orientation::Clockwise {
                break;
            }
            self.cross(pos - 1, p);
        }
    }

    // ---- events ----

    /// Swaps the adjacent edges at `pos` and `pos + 1`, which cross at `p`, updating their
    /// winding counts and the output (see [`crate::contribution`]).
    pub(crate) fn cross(&mut self, pos: usize, p: Point) {
        let (a, b) = (self.ael.at(pos), self.ael.at(pos + 1));
        let (ea, eb) = (self.ael.get(a), self.ael.get(b));
        let wl = ea.wind_left;
        let mid = ea.wind_right();
        let right = eb.crossed(mid);
        let mid_after = eb.crossed(wl);
        let r = self.rules;
        let class = classify(r.inside(wl), r.inside(mid), r.inside(right), r.inside(mid_after));
        self.ael.get_mut(b).wind_left = wl;
        self.ael.get_mut(a).wind_left = mid_after;
        self.ael.swap(pos);
        match class {
            Crossing::Nothing => {}
            Crossing::AToB => {
                self.add_point_beside(a, b, p);
                self.hand_over(a, b);
            }
            Crossing::BToA => {
                self.add_point_beside(b, a, p);
                self.hand_over(b, a);
            }
            Crossing::LocalMin { b_is_left } => {
                if b_is_left {
                    self.start_output(b, a, p)
                } else {
                    self.start_output(a, b, p)
                }
            }
            Crossing::LocalMax => self.end_output(a, b, p),
            Crossing::Pinch { b_is_left } => {
                let (ra, rb) = (self.ael.get(a).outrec, self.ael.get(b).outrec);
                if ra == rb {
                    self.end_output(a, b, p);
                    if b_is_left { self.start_output(b, a, p) } else { self.start_output(a, b, p) }
                } else {
                    self.add_point_both(a, b, p);
                    self.swap_outputs(a, b);
                }
            }
        }
    }

    /// Removes the adjacent pair at `pos`, whose bounds meet at `p` (a local maximum).
    fn end_pair(&mut self, pos: usize, p: Point) {
        let (a, b) = (self.ael.at(pos), self.ael.at(pos + 1));
        if self.ael.get(a).outrec != NONE || self.ael.get(b).outrec != NONE {
            self.end_output(a, b, p);
        }
        self.ael.remove_pair(pos);
    }

    // ---- output glue ----

    fn start_output(&mut self, left: u32, right: u32, p: Point) {
        let rec = self.out.add_local_min(left, right, p);
        self.ael.get_mut(left).outrec = rec;
        self.ael.get_mut(right).outrec = rec;
        let rounded = self.rounded_crossing && !self.is_vertex_of(left, p) && !self.is_vertex_of(right, p);
        self.node_pair_neighbours(left, right, p, rounded);
    }

    /// [`Sweep::node_neighbours`] of both `a` and `b`, which hold `p` in their chains already.
    /// When they are adjacent, one scan each way beyond the pair does what a scan from each edge
    /// would (each edge's scan passes its partner, which holds `p`), with either edge's line for
    /// the coincidence test.
    fn node_pair_neighbours(&mut self, a: u32, b: u32, p: Point, rounded: bool) {
        let (pa, pb) = (self.ael.pos(a), self.ael.pos(b));
        let (lo, hi) = (pa.min(pb), pa.max(pb));
        if hi != lo + 1 {
            self.node_neighbours(a, p, rounded);
            self.node_neighbours(b, p, rounded);
            return;
        }
        self.node_outward(a, b, lo, hi, p, rounded);
    }

    /// True when edges `a` and `b` lie on one line (exact).
    fn coincident(&self, a: u32, b: u32) -> bool {
        let (ea, eb) = (self.ael.get(a), self.ael.get(b));
        !ea.moving && ea.side_of(eb.bot) == Orientation::Collinear && ea.side_of(eb.top) == Orientation::Collinear
    }

    /// True when `p` is an end of edge `id`: an input vertex, exact.
    fn is_vertex_of(&self, id: u32, p: Point) -> bool {
        let e = self.ael.get(id);
        p == e.bot || p == e.top
    }

    /// Output vertex `p` also goes into the chains of contributing edges that pass exactly
    /// through it (coincident edges lie next to `id`), so overlapping output edges share their
    /// end points and cancel in the clean-up. Only a `rounded` point (a computed crossing) may be
    /// within rounding of an edge instead of on it: an input vertex is exact, and far from the
    /// origin the rounding allowance (ulps of the magnitude) spans whole input edges.
    #[inline]
    fn node_neighbours(&mut self, id: u32, p: Point, rounded: bool) {
        let pos = self.ael.pos(id);
        self.node_outward(id, id, pos, pos, p, rounded);
    }

    /// Gives `p` to the edges left of active position `lo` and right of `hi`, outwards, each
    /// scan stopping at the first edge that does not pass through it ([`Sweep::node_neighbour`]).
    #[inline]
    fn node_outward(&mut self, a: u32, b: u32, lo: usize, hi: usize, p: Point, rounded: bool) {
        for k in (0..lo).rev() {
            if !self.node_neighbour(a, b, k, p, rounded) {
                break;
            }
        }
        for k in hi + 1..self.ael.len() {
            if !self.node_neighbour(a, b, k, p, rounded) {
                break;
            }
        }
    }

    /// [`Sweep::node_neighbours`] for the edge at active position `pos`: gives it `p` if it
    /// passes through it (lying on the line of `id` or `also` counts); false when the search
    /// should stop there.
    #[inline(always)]
    fn node_neighbour(&mut self, id: u32, also: u32, pos: usize, p: Point, rounded: bool) -> bool {
        let k = self.ael.at(pos);
        let e = self.ael.get(k);
        if e.moving {
            // A sliding edge sits at the slide's x, not on its own line: look past it.
            return true;
        }
        // Through p exactly; or on the same line as `id`, or within rounding of p, when p is a
        // rounded crossing that several edges share (the cheap test first).
        if p.y < e.bot.y || p.y > e.top.y || !e.maybe_near(p, 1e-9) {
            return false;
        }
        let (offset, scale) = e.offset_and_scale(p);
        // Within rounding of a rounded point first: it spares the exact test, which on a point
        // that close to the line mostly takes the slow, adaptive path.
        let (near, within_rounding) = (offset <= 1e-9 * scale, rounded && offset <= ROUNDING * scale);
        if !near
            || (!within_rounding
                && e.side_of(p) != Orientation::Collinear
                && !self.coincident(id, k)
                && (also == id || !self.coincident(also, k)))
        {
            self.out.near_miss |= near && !rounded;
            return false;
        }
        if e.outrec != NONE && p != e.bot && p != e.top {
            let left = self.is_left(k);
            self.out.add(e.outrec, left, p);
        }
        true
    }

    /// True when `id` feeds the left end of its output polygon.
    #[inline]
    fn is_left(&self, id: u32) -> bool {
        let rec = self.ael.get(id).outrec;
        rec != NONE && self.out.rec(rec).left_edge == id
    }

    /// AddLeft or AddRight, by the edge's side.
    pub(crate) fn add_point(&mut self, id: u32, p: Point) {
        let rec = self.ael.get(id).outrec;
        if rec != NONE {
            let left = self.is_left(id);
            self.out.add(rec, left, p);
            let rounded = self.rounded_crossing && !self.is_vertex_of(id, p);
            self.node_neighbours(id, p, rounded);
        }
    }

    /// [`Sweep::add_point`] to `a`, whose neighbour `b` passes through `p` too and needs no point
    /// of its own there (it holds no chain, or `a`'s, which gets `p` now): `a`'s search would
    /// only pass `b`, so it starts beyond the pair, with either edge's line for the coincidence
    /// test (as [`Sweep::node_pair_neighbours`]).
    fn add_point_beside(&mut self, a: u32, b: u32, p: Point) {
        let (rec, rec_b) = (self.ael.get(a).outrec, self.ael.get(b).outrec);
        let (pa, pb) = (self.ael.pos(a), self.ael.pos(b));
        let (lo, hi) = (pa.min(pb), pa.max(pb));
        if rec == NONE || (rec_b != NONE && rec_b != rec) || hi != lo + 1 {
            self.add_point(a, p);
            return;
        }
        let left = self.is_left(a);
        self.out.add(rec, left, p);
        let rounded = self.rounded_crossing && !self.is_vertex_of(a, p);
        self.node_outward(a, b, lo, hi, p, rounded);
    }

    /// [`Sweep::add_point`] to `a` and then to `b`, both contributing, with one neighbour
    /// search for the pair.
    fn add_point_both(&mut self, a: u32, b: u32, p: Point) {
        let (ra, rb) = (self.ael.get(a).outrec, self.ael.get(b).outrec);
        if ra == NONE || rb == NONE {
            self.add_point(a, p);
            self.add_point(b, p);
            return;
        }
        let (a_left, b_left) = (self.is_left(a), self.is_left(b));
        self.out.add(ra, a_left, p);
        self.out.add(rb, b_left, p);
        // Each edge's own search may take rounded matches when `p` is not its vertex.
        let rounded = self.rounded_crossing && (!self.is_vertex_of(a, p) || !self.is_vertex_of(b, p));
        self.node_pair_neighbours(a, b, p, rounded);
    }

    /// `to` takes over `from`'s output chain, on the same side.
    fn hand_over(&mut self, from: u32, to: u32) {
        let rec = self.ael.get(from).outrec;
        if rec == NONE {
            return;
        }
        let r = self.out.rec_mut(rec);
        if r.left_edge == from {
            r.left_edge = to;
        } else {
            r.right_edge = to;
        }
        self.ael.get_mut(from).outrec = NONE;
        self.ael.get_mut(to).outrec = rec;
    }

    /// Two edges of different output polygons exchange them, each keeping its side.
    fn swap_outputs(&mut self, a: u32, b: u32) {
        let (ra, rb) = (self.ael.get(a).outrec, self.ael.get(b).outrec);
        let (a_left, b_left) = (self.is_left(a), self.is_left(b));
        if ra != NONE {
            let r = self.out.rec_mut(ra);
            if a_left { r.left_edge = b } else { r.right_edge = b }
        }
        if rb != NONE {
            let r = self.out.rec_mut(rb);
            if b_left { r.left_edge = a } else { r.right_edge = a }
        }
        self.ael.get_mut(a).outrec = rb;
        self.ael.get_mut(b).outrec = ra;
    }

    /// AddLocalMax: both edges stop contributing at `p`; one polygon closes, or two join.
    fn end_output(&mut self, a: u32, b: u32, p: Point) {
        let (ra, rb) = (self.ael.get(a).outrec, self.ael.get(b).outrec);
        if ra == NONE || rb == NONE {
            // Only reachable if the contribution bookkeeping were inconsistent: keep the point.
            self.add_point(a, p);
            self.add_point(b, p);
            self.ael.get_mut(a).outrec = NONE;
            self.ael.get_mut(b).outrec = NONE;
            return;
        }
        if ra == rb {
            self.add_point_beside(a, b, p);
            self.out.close(ra);
        } else {
            self.add_point_both(a, b, p);
            // The polygon whose right end is here comes first.
            let (x, y) = if self.is_left(a) { (rb, ra) } else { (ra, rb) };
            self.out.append(x, y);
            let moved = self.out.rec(x).right_edge;
            if moved != NONE {
                self.ael.get_mut(moved).outrec = x;
            }
        }
        self.ael.get_mut(a).outrec = NONE;
        self.ael.get_mut(b).outrec = NONE;
    }
}
