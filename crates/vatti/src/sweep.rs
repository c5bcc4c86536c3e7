//! The sweep: scanlines bottom to top, local minima inserted, edge tops processed, and the
//! events that change the output (crossings, starts and ends of bounds).
//!
//! Two ways to find what happens between scanlines share everything else ([`Sweep`]): the
//! paper's, which visits every active edge in every scanbeam (x at the top, the sorted edge
//! table), and an event sweep, which touches an edge only where it starts, ends or crosses a
//! neighbour.

use clip_core::predicates::{Orientation, orient, through_crossing};
use clip_core::{Point, Trapezoid};

use crate::active::{ActiveEdges, Edge, ROUNDING};
use crate::bounds::{Bounds, LocalMinimum, NONE};
use crate::contribution::{Crossing, Rules, classify};
use crate::crossing_queue::{CrossingQueue, PendingCrossing};
use crate::edge_tops::EdgeTops;
use crate::intersections::IntersectionTable;
use crate::output::OutputBuilder;
use crate::rounding_certificate::RoundingCertificate;
use crate::scanbeam::{Scanbeams, height, height_key};
use crate::small_sort::insertion_sorted_by;

/// The rounding certificate's check of a crossing computed outside its range and clamped onto
/// an edge too flat for its x there to be within a crossing's error (`Edge::crossing_with`).
const OFF_FLAT: &str = "a crossing clamped onto a flat edge";

/// Ulps of the largest coordinate of a crossing's edges above a scanline within which the
/// crossing, computed, may lie below it exactly (`SweepLine::crossed_below`): a crossing's
/// height errs by a few ulps of the coordinates it is computed from (found an ulp and a half
/// above, by the `vatti` fuzz target); the test within this band is exact, so the band only
/// bounds the work.
const CROSSING_HEIGHT_SLACK: f64 = 64.0;

/// How the sweep finds the edges that end on a scanline and the crossings between scanlines.
/// Both give the same output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sweep {
    /// Vatti's: every vertex height is a scanline, and in every scanbeam every active edge's x
    /// at the top is computed and sorted (the sorted edge table) to find the crossings. Θ(n) per
    /// scanbeam where n edges are active: quadratic where many edges span many scanbeams
    /// (nested or concentric rings, combs, long spirals).
    Scanbeam,
    /// Event-driven (Bentley & Ottmann 1979): the active edges' tops wait in a heap, a pair of
    /// edges is tested for a crossing only when it becomes adjacent, and new edges find their
    /// place in a search tree. O((n + k) log n) for n edges and k crossings.
    Events,
}

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
    tops: EdgeTops,
    crossings: CrossingQueue,
    table: IntersectionTable,
    out: OutputBuilder,
    traps: Vec<Trapezoid>,
    ending: Vec<u32>,
    lefts: Vec<u32>,
    on_scanline: Vec<PendingCrossing>,
    maxima: Vec<u32>,
    settle: Vec<u32>,
    slides: Vec<Slide>,
    cert: RoundingCertificate,
}

impl SweepBuffers {
    /// Bytes the buffers hold (their capacity), to decide whether keeping them is worth it.
    pub(crate) fn held_bytes(&self) -> usize {
        use std::mem::size_of;
        self.ael.held_bytes()
            + self.tops.held_bytes()
            + self.crossings.held_bytes()
            + self.table.held_bytes()
            + self.out.held_bytes()
            + self.traps.capacity() * size_of::<Trapezoid>()
            + self.slides.capacity() * size_of::<Slide>()
            + 8 * self.beams.capacity()
            + 4 * (self.ending.capacity() + self.lefts.capacity() + self.maxima.capacity() + self.settle.capacity())
    }
}

/// Whether a sweep certifies its rounding (`rounding_certificate`), and whether it also routes
/// the near misses it meets (`near_misses`: the event sweep only).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Certify {
    No,
    Yes,
    Routing,
}

/// One run of the clipper over two operands.
pub(crate) struct SweepLine<'a> {
    pub kind: Sweep,
    pub rules: Rules,
    pub bounds: &'a Bounds,
    pub ael: ActiveEdges,
    /// The scanlines: every vertex height ([`Sweep::Scanbeam`]).
    beams: Scanbeams,
    /// The active edges by the height of their tops ([`Sweep::Events`]).
    tops: EdgeTops,
    /// Crossings found and not yet passed ([`Sweep::Events`]).
    crossings: CrossingQueue,
    /// The sorted edge and intersection tables ([`Sweep::Scanbeam`]).
    table: IntersectionTable,
    pub out: OutputBuilder,
    /// Trapezoids, when asked for.
    pub traps: Option<Vec<Trapezoid>>,
    next_minimum: usize,
    // Work lists reused between scanlines.
    ending: Vec<u32>,
    lefts: Vec<u32>,
    /// Crossings on the scanline of two edges going on above it, taken after its vertices.
    on_scanline: Vec<PendingCrossing>,
    maxima: Vec<u32>,
    settle: Vec<u32>,
    slides: Vec<Slide>,
    /// True while a crossing at a computed (rounded) point is processed: only such a point may
    /// join the chain of an edge it lies within rounding of; any other point is an exact input
    /// vertex.
    pub(crate) rounded_crossing: bool,
    /// The two edges whose crossing is being processed, while `rounded_crossing`: an edge
    /// through their exact crossing joins the chain too (`through_crossing`).
    pub(crate) crossing_pair: (u32, u32),
    /// Crossings taken out of the queue by [`SweepLine::crossed_below`] that wait for their height.
    waiting: Vec<PendingCrossing>,
    /// Whether rounding left the output's form as the exact arrangement's.
    pub(crate) cert: RoundingCertificate,
    /// True while a crossing between scanlines is processed (else points are on the scanline).
    between: bool,
    /// Whether near misses are routed (`near_misses`): the event sweep, certified, until a walk
    /// beside a vertex finds more edges within reach than it looks at.
    pub(crate) route: bool,
    /// Crossings put off because one edge's top is a near miss of the other (`near_misses`):
    /// the edge to route and the top it must go through.
    pub(crate) deferred: Vec<(u32, Point)>,
    /// The edges just routed through one vertex, whose output waits until all of them are.
    pub(crate) routed: Vec<u32>,
}

impl<'a> SweepLine<'a> {
    /// A sweep of the given kind over `bounds` in the given (emptied) buffers.
    pub(crate) fn new(
        kind: Sweep,
        bounds: &'a Bounds,
        rules: Rules,
        trapezoids: bool,
        certify: Certify,
        buffers: SweepBuffers,
    ) -> SweepLine<'a> {
        let SweepBuffers {
            mut ael,
            mut beams,
            mut tops,
            mut crossings,
            mut table,
            mut out,
            mut traps,
            mut ending,
            mut lefts,
            mut on_scanline,
            mut maxima,
            mut settle,
            mut slides,
            mut cert,
        } = buffers;
        ael.reset(kind == Sweep::Events, 2 * bounds.minima.len());
        if kind == Sweep::Scanbeam {
            beams.rebuild(&bounds.vertices);
        }
        tops.clear();
        crossings.clear();
        table.clear();
        out.reset(if trapezoids { 0 } else { bounds.vertices.len() });
        traps.clear();
        ending.clear();
        lefts.clear();
        on_scanline.clear();
        maxima.clear();
        settle.clear();
        slides.clear();
        SweepLine {
            kind,
            rules,
            bounds,
            ael,
            beams,
            tops,
            crossings,
            table,
            out,
            traps: trapezoids.then_some(traps),
            next_minimum: 0,
            ending,
            lefts,
            on_scanline,
            maxima,
            settle,
            slides,
            rounded_crossing: false,
            crossing_pair: (NONE, NONE),
            waiting: Vec::new(),
            cert: {
                cert.reset(certify != Certify::No && !trapezoids, bounds);
                cert
            },
            between: false,
            route: kind == Sweep::Events && certify == Certify::Routing,
            deferred: Vec::new(),
            routed: Vec::new(),
        }
    }

    /// The buffers back, for the next sweep (trapezoids, if any, moved out first).
    pub(crate) fn into_buffers(self) -> SweepBuffers {
        let SweepLine {
            ael,
            beams,
            tops,
            crossings,
            table,
            out,
            traps,
            ending,
            lefts,
            on_scanline,
            maxima,
            settle,
            slides,
            cert,
            ..
        } = self;
        SweepBuffers {
            ael,
            beams,
            tops,
            crossings,
            table,
            out,
            traps: traps.unwrap_or_default(),
            ending,
            lefts,
            on_scanline,
            maxima,
            settle,
            slides,
            cert,
        }
    }

    /// Runs the whole sweep. Every scanline is a distinct y above the previous one, taken from
    /// the finitely many vertex heights, so the loop ends.
    pub(crate) fn run(&mut self) {
        let Some(first) = self.bounds.minima.first() else { return };
        let mut y = self.bounds.minimum_y(first);
        loop {
            self.top_of_scanbeam(y);
            self.insert_local_minima(y);
            if self.kind == Sweep::Events {
                self.test_new_pairs(y);
                for c in self.on_scanline.drain(..) {
                    self.crossings.push(c.left, c.right, c.pt);
                }
            }
            // Its output would be thrown away: the snap-rounded operands are swept instead.
            if !self.cert.holds() {
                break;
            }
            let Some(next) = self.next_scanline(y) else { break };
            self.ael.scanline_done();
            self.process_intersections(y, next);
            y = next;
        }
        self.beams.release_if_large();
        if !self.deferred.is_empty() {
            self.cert.break_off("a near miss put off and not routed");
        }
    }

    /// The lowest scanline above `y`: a vertex height, where a local minimum starts or an active
    /// edge ends.
    fn next_scanline(&mut self, y: f64) -> Option<f64> {
        match self.kind {
            Sweep::Scanbeam => self.beams.next_above(y),
            Sweep::Events => {
                let minimum = self.bounds.minima.get(self.next_minimum).map(|m| height_key(self.bounds.minimum_y(m)));
                let lowest = match (minimum, self.tops.lowest()) {
                    (Some(m), Some(t)) => Some(m.min(t)),
                    (m, t) => m.or(t),
                };
                lowest.map(height)
            }
        }
    }

    // ---- edges ----

    /// Makes the active edge for the bound leaving vertex `from` towards `to`.
    fn new_edge(&mut self, from: u32, to: u32, kind: u8, forward: bool) -> u32 {
        let (bot, top) = (self.bounds.pt(from), self.bounds.pt(to));
        let id = self.ael.create(bot, top, kind, forward, to);
        if self.kind == Sweep::Events {
            self.tops.push_starting(top.y, id);
        }
        id
    }

    /// The other bound's edge ending at vertex `v`, opposite in direction to `id`, and whether
    /// it lies right of `id`.
    fn partner_at(&self, id: u32, v: u32) -> Option<(u32, bool)> {
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
        if self.cert.checking() {
            let flat = |q: u32| self.cert.is_flat_segment(p, self.bounds.pt(q));
            let counts = !flat(vx.prev) || (!m.horizontal && !flat(vx.next));
            self.cert.on_scanline(p, counts);
        }
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
        self.ael.insert_at(left, p, if m.horizontal { backward_top } else { self.ael.get(left).top });
        self.ael.insert_after(right, left);
        {
            let e = self.ael.get_mut(forward);
            e.curr_x = p.x;
            e.curr_y = p.y;
            // With a horizontal bottom the forward edge starts away from p: it slides there.
            e.moving = m.horizontal;
        }
        // Before the output starts here: an edge routed through `p` is not checked against it.
        if !m.horizontal {
            self.route_near_misses(p, left, false);
        }
        let wl = self.ael.wind_right_of(self.ael.prev(left));
        self.ael.get_mut(left).wind_left = wl;
        let wm = self.ael.get(left).wind_right();
        self.ael.get_mut(right).wind_left = wm;
        let (i0, i1) = (self.rules.inside(wl), self.rules.inside(wm));
        if i0 != i1 {
            if i1 { self.start_output(left, right, p) } else { self.start_output(right, left, p) }
        }
        if m.horizontal {
            let to = self.bounds.pt(fwd_from);
            if self.cert.checking() {
                let counts = !self.cert.is_flat_segment(to, self.bounds.pt(fwd_to));
                self.cert.horizontal(p, to);
                self.cert.on_scanline(to, counts);
            }
            self.slide(Slide { edge: forward, from_x: p.x, to_x: to.x, max_vertex: NONE }, p.y);
            self.ael.get_mut(forward).moving = false;
            self.add_point(forward, to);
            // An edge along the backward bound's line lies left of it (`insert_at`); the slide
            // ordered the forward bound with one along its line.
            let k = self.ael.prev(backward);
            if k != NONE
                && self.through_bottom(k, p)
                && orient(p, backward_top, self.ael.get(k).top) == Orientation::Collinear
            {
                self.order_coincident(k, backward, p);
            }
            self.route_near_misses(p, backward, true);
            self.route_near_misses(to, forward, true);
        } else {
            self.settle(right);
            self.settle(left);
            // Edges routed through `p` above, once the new pair's windings are set.
            for i in 0..self.settle.len() {
                let k = self.settle[i];
                self.settle(k);
            }
            self.settle.clear();
        }
    }

    // ---- top of scanbeam ----

    /// Edges reaching scanline `y`: intermediate vertices hand over to successor edges, local
    /// maxima end pairs of bounds, horizontals make edges slide. The edges ending here are
    /// taken in one order whichever sweep found them: by their tops' x, then vertex.
    fn top_of_scanbeam(&mut self, y: f64) {
        let mut ending = std::mem::take(&mut self.ending);
        match self.kind {
            Sweep::Scanbeam => {
                // The paper's pass over the whole table: every edge's x on the scanline.
                let mut id = self.ael.first();
                while id != NONE {
                    let e = self.ael.get_mut(id);
                    if e.top.y == y {
                        ending.push(id);
                    } else {
                        e.curr_x = e.x_at_cached(y);
                        e.curr_y = y;
                    }
                    id = e.next;
                }
            }
            Sweep::Events => self.tops.take_at(y, &mut ending),
        }
        if ending.len() > 1 {
            let edges = &self.ael.edges;
            let key = |id: &u32| {
                let e = &edges[*id as usize];
                (height_key(e.top.x), e.top_vertex, e.forward)
            };
            if !insertion_sorted_by(&mut ending, |a, b| key(a) < key(b)) {
                ending.sort_unstable_by_key(key);
            }
        }
        for &id in &ending {
            if self.route {
                let tp = self.ael.get(id).top;
                self.route_near_misses(tp, id, false);
            }
            if self.cert.checking() {
                self.certify_top(id);
            }
            let e = self.ael.get_mut(id);
            e.curr_x = e.top.x;
            e.curr_y = y;
            let (t, forward) = (e.top_vertex, e.forward);
            let u = self.bounds.along(t, forward);
            let (tp, up) = (self.bounds.pt(t), self.bounds.pt(u));
            if up.y > y {
                self.succeed(id, t, u);
                self.settle.push(id);
            } else if up.y < y {
                self.maxima.push(id);
            } else {
                let w = self.bounds.along(u, forward);
                if self.bounds.pt(w).y > y {
                    self.succeed(id, u, w);
                    let e = self.ael.get_mut(id);
                    e.curr_x = tp.x;
                    e.moving = true;
                    self.slides.push(Slide { edge: id, from_x: tp.x, to_x: up.x, max_vertex: NONE });
                } else if forward {
                    self.ael.get_mut(id).moving = true;
                    self.slides.push(Slide { edge: id, from_x: tp.x, to_x: up.x, max_vertex: u });
                }
            }
        }
        ending.clear();
        self.ending = ending;
        // The lists are read by index: the events below never add to them.
        for i in 0..self.maxima.len() {
            let id = self.maxima[i];
            let t = self.ael.get(id).top_vertex;
            let tp = self.bounds.pt(t);
            if let Some((partner, right)) = self.partner_at(id, t) {
                self.meet(id, partner, right, tp, tp.x, tp.x, tp.y);
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
                self.route_near_misses(to, s.edge, true);
            } else if let Some((partner, right)) = self.partner_at(s.edge, s.max_vertex) {
                let e = self.ael.get(s.edge);
                let tp = e.top;
                if e.outrec != NONE {
                    self.add_point(s.edge, tp);
                }
                let mp = self.bounds.pt(s.max_vertex);
                self.route_near_misses(mp, partner, true);
                self.meet(s.edge, partner, right, mp, s.from_x, s.to_x, y);
            }
            self.ael.get_mut(s.edge).moving = false;
        }
        self.maxima.clear();
        self.settle.clear();
        self.slides.clear();
    }

    /// Moves edge `id` on to its bound's next edge `from -> to` (an intermediate vertex at the
    /// old edge's top: its output chain, if any, gets the vertex). The bound keeps its edge
    /// record, place, winding counts and output chain, as Vatti's edge record does.
    fn succeed(&mut self, id: u32, from: u32, to: u32) {
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
        e.tainted = false;
        e.top_vertex = to;
        e.curr_x = top.x;
        e.curr_y = top.y;
        e.next_y = f64::NAN;
        self.ael.segment_changed(id);
        if self.kind == Sweep::Events {
            self.tops.push(next_top.y, id);
        }
    }

    /// Moves edge `id` across the edges between it and `partner` (on its `right` or left;
    /// crossings at the scanline, x clamped to `[from_x, to_x]`), then ends both bounds at `p`:
    /// AddLocalMax.
    #[allow(clippy::too_many_arguments)]
    fn meet(&mut self, id: u32, partner: u32, right: bool, p: Point, from_x: f64, to_x: f64, y: f64) {
        let (lo, hi) = (from_x.min(to_x), from_x.max(to_x));
        for _ in 0..self.ael.len() {
            let k = if right { self.ael.next(id) } else { self.ael.prev(id) };
            if k == partner || k == NONE {
                break;
            }
            // The crossings are at the other edges' x on this scanline: rounded, unless exact.
            let x = self.ael.x_on(k, y);
            let (q, rounded) = self.ael.get(k).passed_at(x, y, lo, hi, [from_x, to_x]);
            self.certify_passed(k, x, q);
            self.rounded_crossing = rounded;
            self.crossing_pair = (id, k);
            self.taint(k);
            self.cross(if right { id } else { k }, q);
            self.rounded_crossing = false;
            self.crossing_pair = (NONE, NONE);
        }
        if self.ael.next(id) == partner {
            self.end_pair(id, p);
        } else if self.ael.next(partner) == id {
            self.end_pair(partner, p);
        }
    }

    /// Marks active edge `k` as having decided something on its line above its bottom, so it is
    /// never routed (`near_misses`); only while routing, which alone reads the mark.
    #[inline]
    pub(crate) fn taint(&mut self, k: u32) {
        if self.route {
            self.ael.get_mut(k).tainted = true;
        }
    }

    /// [`SweepLine::taint`] for a crossing at `p`, unless `p` is the edge's bottom.
    #[inline]
    pub(crate) fn taint_unless_bottom(&mut self, k: u32, p: Point) {
        if self.route {
            let e = self.ael.get_mut(k);
            e.tainted |= e.bot != p;
        }
    }

    /// Queues edge `id` (starting on this scanline) to be ordered among the edges through its
    /// bottom once the scanline's edges have gone on ([`SweepLine::settle`]).
    pub(crate) fn settle_later(&mut self, id: u32) {
        self.settle.push(id);
    }

    /// Orders a new edge starting at its bottom among edges through the same point by
    /// direction above it: exact, with crossings at that point. Called on the scanline through
    /// its bottom.
    pub(crate) fn settle(&mut self, id: u32) {
        let (p, top) = (self.ael.get(id).bot, self.ael.get(id).top);
        // A neighbour along the same line above `p`, as (left, right) of the pair.
        let mut along = None;
        for _ in 0..self.ael.len() {
            let k = self.ael.next(id);
            if k == NONE || !self.through_bottom(k, p) {
                break;
            }
            match orient(p, top, self.ael.get(k).top) {
                Orientation::CounterClockwise => {
                    self.taint_unless_bottom(k, p);
                    self.cross(id, p)
                }
                Orientation::Collinear => {
                    along = Some((id, k));
                    break;
                }
                Orientation::Clockwise => break,
            }
        }
        for _ in 0..self.ael.len() {
            let k = self.ael.prev(id);
            if k == NONE || !self.through_bottom(k, p) {
                break;
            }
            match orient(p, top, self.ael.get(k).top) {
                Orientation::Clockwise => {
                    self.taint_unless_bottom(k, p);
                    self.cross(k, p)
                }
                Orientation::Collinear => {
                    along = along.or(Some((k, id)));
                    break;
                }
                Orientation::CounterClockwise => break,
            }
        }
        if let Some((l, r)) = along {
            self.order_coincident(l, r, p);
        }
    }

    /// Orders adjacent edges `l` and `r`, which run along one line above `p`, so that the
    /// zero-width region between them is inside exactly when the regions on both sides are,
    /// where an order does that (for edges of the two operands under ∩, ∪ and −, always): then
    /// neither bounds the result there, where the other order would output both, a gap or a
    /// sliver that the clean-up cancels again. Either order is a valid sweep, as they lie on
    /// one line. Property used: edges along one line from one point (the shared borders of
    /// layers that tile the plane: countries, tiles, grids).
    pub(crate) fn order_coincident(&mut self, l: u32, r: u32, p: Point) {
        // `settle` finds the pair before it may move the new edge away from it.
        if self.ael.next(l) != r {
            return;
        }
        let (el, er) = (self.ael.get(l), self.ael.get(r));
        let w = el.wind_left;
        let mid = el.crossed(w);
        let inside = |w| self.rules.inside(w);
        let out = inside(w);
        // Where the sides differ, one of the two bounds the result in either order.
        if inside(er.crossed(mid)) == out && inside(mid) != out && inside(er.crossed(w)) == out {
            self.taint_unless_bottom(l, p);
            self.taint_unless_bottom(r, p);
            self.cross(l, p);
        }
    }

    /// True when active edge `k` passes through `p` on the scanline and goes on above it.
    #[inline]
    fn through_bottom(&mut self, k: u32, p: Point) -> bool {
        let x = self.ael.x_on(k, p.y);
        let e = self.ael.get(k);
        !(e.moving || e.ends_by(p.y) || e.clearly_off(x, p) || e.side_of(p) != Orientation::Collinear)
    }

    // ---- events ----

    /// Swaps `a` and its right neighbour `b`, which cross at `p`, updating their winding counts
    /// and the output (see [`crate::contribution`]).
    pub(crate) fn cross(&mut self, a: u32, p: Point) {
        let b = self.ael.next(a);
        let (ea, eb) = (self.ael.get(a), self.ael.get(b));
        let wl = ea.wind_left;
        let mid = ea.wind_right();
        let right = eb.crossed(mid);
        let mid_after = eb.crossed(wl);
        let r = self.rules;
        let class = classify(r.inside(wl), r.inside(mid), r.inside(right), r.inside(mid_after));
        self.ael.get_mut(b).wind_left = wl;
        self.ael.get_mut(a).wind_left = mid_after;
        self.ael.swap(a);
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

    /// Removes `a` and its right neighbour, whose bounds meet at `p` (a local maximum).
    fn end_pair(&mut self, a: u32, p: Point) {
        let b = self.ael.next(a);
        if self.ael.get(a).outrec != NONE || self.ael.get(b).outrec != NONE {
            self.end_output(a, b, p);
        }
        self.ael.remove_pair(a);
    }

    // ---- crossings between scanlines ----

    /// Processes every crossing in the scanbeam `[yb, yt]`, emitting trapezoids between
    /// consecutive crossing heights when asked.
    fn process_intersections(&mut self, yb: f64, yt: f64) {
        let mut y_prev = yb;
        match self.kind {
            Sweep::Scanbeam => {
                self.table.build(&mut self.ael, yb, yt, self.cert.max_error());
                if self.table.off_flat {
                    self.cert.fail(OFF_FLAT);
                }
                let mut table = std::mem::take(&mut self.table.table);
                for i in 0..table.len() {
                    if self.ael.next(table[i].left) != table[i].right {
                        // Crossings at (nearly) one height may come in any order; take the next
                        // one that is adjacent now. One always is: the table holds exactly the
                        // inversions left.
                        match (i + 1..table.len()).find(|&j| self.ael.next(table[j].left) == table[j].right) {
                            Some(j) => table.swap(i, j),
                            None => break,
                        }
                    }
                    let c = table[i];
                    self.crossing(c.left, c.pt, &mut y_prev);
                }
                table.clear();
                self.table.table = table;
            }
            Sweep::Events => {
                loop {
                    while let Some(c) = self.crossings.pop_up_to(yt) {
                        // Dropped when an edge came between the pair, or one of them ended: the
                        // pair is tested again if it is ever adjacent again.
                        if !self.still_adjacent(c) {
                            continue;
                        }
                        if c.pt.y == yt && self.after_scanline(c.left, c.right, yt) {
                            self.on_scanline.push(c);
                            continue;
                        }
                        self.crossing(c.left, c.pt, &mut y_prev);
                        self.test_new_pairs(yb);
                    }
                    let Some(c) = self.crossed_below(yt) else { break };
                    let (el, er) = (self.ael.get(c.left), self.ael.get(c.right));
                    let xs = [el.x_at(yb), el.x_at(yt), er.x_at(yb), er.x_at(yt)];
                    let (p, off_flat) = el.crossing_with(er, yb, yt, xs, self.cert.max_error());
                    if off_flat {
                        self.cert.fail(OFF_FLAT);
                    }
                    self.crossing(c.left, p, &mut y_prev);
                    self.test_new_pairs(yb);
                }
                while let Some(c) = self.waiting.pop() {
                    self.crossings.push(c.left, c.right, c.pt);
                }
            }
        }
        if self.traps.is_some() && yt > y_prev {
            self.emit_slab(y_prev, yt);
        }
    }

    /// True when pending crossing `c`'s edges are still adjacent, in its order, and alive.
    #[inline]
    fn still_adjacent(&self, c: PendingCrossing) -> bool {
        self.ael.next(c.left) == c.right && self.ael.get(c.left).alive
    }

    /// The next crossing computed just above scanline `y` (the lowest ones, each within
    /// [`CROSSING_HEIGHT_SLACK`] ulps of its edges' largest coordinate) whose edges have crossed
    /// by `y` already, exactly: a crossing of a nearly horizontal edge can be computed an ulp or
    /// two above a scanline that it lies below, and the scanline's events (a horizontal sliding
    /// across both edges) need the pair in its order there. The others go to `waiting`, to be
    /// queued again.
    fn crossed_below(&mut self, y: f64) -> Option<PendingCrossing> {
        while let Some(c) = self.crossings.lowest() {
            if self.still_adjacent(c) {
                let (l, r) = (self.ael.get(c.left), self.ael.get(c.right));
                let band = CROSSING_HEIGHT_SLACK * f64::EPSILON * l.magnitude.max.max(r.magnitude.max);
                if c.pt.y > y + band {
                    return None;
                }
                let crossed = r.left_of_at_exactly(l, y);
                self.crossings.pop();
                if crossed {
                    return Some(c);
                }
                self.waiting.push(c);
            } else {
                self.crossings.pop();
            }
        }
        None
    }

    /// True when adjacent edges `l` and `r`, crossing on scanline `y`, cross after its vertices
    /// are taken: both go on above it and are still in order there (`r` not left of `l`, as the
    /// scanbeam sweep's table decides it: [`crate::active::Edge::left_of_at`]). So the table's
    /// order on a scanline is the same in both sweeps where the crossing is rounded onto it, and
    /// a horizontal passes them in that order.
    fn after_scanline(&mut self, l: u32, r: u32, y: f64) -> bool {
        if self.ael.get(l).top.y == y || self.ael.get(r).top.y == y {
            return false;
        }
        let (xl, xr) = (self.ael.x_on(l, y), self.ael.x_on(r, y));
        !self.ael.get(r).left_of_at(xr, self.ael.get(l), xl, y)
    }

    /// The crossing of `left` and its right neighbour at the computed point `p`, after the
    /// slab of trapezoids below it.
    #[inline(always)]
    fn crossing(&mut self, left: u32, p: Point, y_prev: &mut f64) {
        if self.traps.is_some() && p.y > *y_prev {
            self.emit_slab(*y_prev, p.y);
            *y_prev = p.y;
        }
        let right = self.ael.next(left);
        if self.cert.checking() {
            let (a, b) = (self.ael.get(left), self.ael.get(right));
            let key = |id: u32, e: &Edge| (u64::from(id) << 32) | u64::from(e.top_vertex);
            let counts = !(self.cert.is_flat(a) || self.cert.is_flat(b));
            self.cert.between_scanlines(p, [key(left, a), key(right, b)], counts);
        }
        // A point exactly on both edges is their exact crossing: nothing rounded (on integer
        // inputs past the coarse grids most crossings are). Asked only in a certified sweep,
        // where it decides whether a failed check matters.
        let exact = self.cert.certifying() && {
            let (a, b) = (self.ael.get(left), self.ael.get(right));
            a.surely_through(p) && b.surely_through(p)
        };
        self.rounded_crossing = !exact;
        self.between = true;
        self.crossing_pair = (left, right);
        self.taint(left);
        self.taint(right);
        self.cross(left, p);
        self.rounded_crossing = false;
        self.between = false;
        self.crossing_pair = (NONE, NONE);
    }

    /// Tests every pair of edges that became adjacent since the last test, queueing the
    /// crossings found, kept at or above scanline `y` (the last one passed). Not above the last
    /// crossing taken: crossings of several edges through one point round to points an ulp or
    /// two apart, and one rounded just below the last would move if kept above it.
    fn test_new_pairs(&mut self, y: f64) {
        let mut lefts = std::mem::take(&mut self.lefts);
        self.ael.take_new_pairs(&mut lefts);
        for &l in &lefts {
            let r = self.ael.next(l);
            self.test_pair(l, r, y);
        }
        self.lefts = lefts;
    }

    /// Queues the crossing of adjacent edges `l` and `r` if they cross before either ends, at
    /// their crossing point kept between height `y` and the lower top.
    #[inline]
    fn test_pair(&mut self, l: u32, r: u32, y: f64) {
        let (el, er) = (self.ael.get(l), self.ael.get(r));
        debug_assert!(!el.moving && !er.moving);
        if !el.crosses_before_top(er) {
            return;
        }
        if self.route && self.put_off_near_top(l, r, y) {
            return;
        }
        let (el, er) = (self.ael.get(l), self.ael.get(r));
        let yt = el.top.y.min(er.top.y);
        let xs = [el.x_at(y), el.x_at(yt), er.x_at(y), er.x_at(yt)];
        let (pt, off_flat) = el.crossing_with(er, y, yt, xs, self.cert.max_error());
        if off_flat {
            self.cert.fail(OFF_FLAT);
        }
        self.taint(l);
        self.taint(r);
        self.crossings.push(l, r, pt);
    }

    // ---- output glue ----

    fn start_output(&mut self, left: u32, right: u32, p: Point) {
        let rec = self.out.add_local_min(left, right, p);
        self.ael.get_mut(left).outrec = rec;
        self.ael.get_mut(right).outrec = rec;
        let rounded = self.rounded_crossing && !self.is_vertex_of(left, p) && !self.is_vertex_of(right, p);
        self.node_pair_neighbours(left, right, p, rounded);
    }

    /// The left and right one of `a` and `b` when they are adjacent.
    #[inline]
    fn adjacent(&self, a: u32, b: u32) -> Option<(u32, u32)> {
        if self.ael.next(a) == b {
            Some((a, b))
        } else if self.ael.next(b) == a {
            Some((b, a))
        } else {
            None
        }
    }

    /// [`SweepLine::node_neighbours`] of both `a` and `b`, which hold `p` in their chains already.
    /// When they are adjacent, one scan each way beyond the pair does what a scan from each edge
    /// would (each edge's scan passes its partner, which holds `p`), with either edge's line for
    /// the coincidence test.
    fn node_pair_neighbours(&mut self, a: u32, b: u32, p: Point, rounded: bool) {
        match self.adjacent(a, b) {
            Some((lo, hi)) => self.node_outward(a, b, lo, hi, p, rounded),
            None => {
                self.node_neighbours(a, p, rounded);
                self.node_neighbours(b, p, rounded);
            }
        }
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
        self.node_outward(id, id, id, id, p, rounded);
    }

    /// Gives `p` to the edges left of active edge `lo` and right of `hi`, outwards, each scan
    /// stopping at the first edge that does not pass through it ([`SweepLine::node_neighbour`]).
    #[inline]
    fn node_outward(&mut self, a: u32, b: u32, lo: u32, hi: u32, p: Point, rounded: bool) {
        let mut k = self.ael.prev(lo);
        while k != NONE && self.node_neighbour(a, b, k, p, rounded) {
            k = self.ael.prev(k);
        }
        // A crossing between scanlines is output where it was computed (and maybe clamped onto an
        // end of its edges), so it counts as rounded even where it lands on an input vertex,
        // unless it lies exactly on both edges.
        if rounded || (self.between && self.rounded_crossing) {
            self.cert.rounded_output();
        }
        if self.cert.checking() {
            if self.cert.flats_near(p) {
                self.certify_flats(p);
            }
            self.certify_beside(k, p, false);
        }
        let mut k = self.ael.next(hi);
        while k != NONE && self.node_neighbour(a, b, k, p, rounded) {
            k = self.ael.next(k);
        }
        if self.cert.checking() {
            self.certify_beside(k, p, true);
        }
    }

    /// The rounding certificate's test of output point `p` against `k`, the nearest edge on one
    /// side (`rightwards` or left) that does not pass through it, or `NONE`
    /// ([`crate::rounding_certificate`]): the nearest edge from `k` on that is not flat (and, on
    /// a scanline, spans it: edges with an end on it are apart from the point along it) must be
    /// clear of `p`.
    #[inline]
    fn certify_beside(&mut self, mut k: u32, p: Point, rightwards: bool) {
        while k != NONE {
            let e = self.ael.get(k);
            let skip = e.moving || self.cert.is_flat(e) || (!self.between && (e.bot.y == p.y || e.top.y <= p.y));
            if !skip {
                self.cert.clear_of(p, e);
                return;
            }
            k = if rightwards { e.next } else { e.prev };
        }
    }

    /// The rounding certificate's record of edge `k` passed at `p` on the scanline by a slide,
    /// where its x there was computed as `x`: where that was clamped into the slide's part still
    /// to pass, `k` runs within rounding of the point the slide passed last (or its end), and the
    /// point `k` gets is not on it.
    #[inline]
    pub(crate) fn certify_passed(&mut self, k: u32, x: f64, p: Point) {
        let counts = !self.cert.is_flat(self.ael.get(k));
        self.cert.on_scanline(p, counts);
        if p.x != x && !self.ael.get(k).moving {
            self.cert.rounded_output();
            self.cert.fail("a slide passing an edge within rounding of its last point");
        }
    }

    /// The rounding certificate's record of the top of edge `id`, ending on this scanline: an
    /// input vertex, and the horizontal edge and vertex after it where the bound runs on along
    /// the scanline.
    #[inline]
    fn certify_top(&mut self, id: u32) {
        let e = self.ael.get(id);
        let (t, forward, tp) = (e.top_vertex, e.forward, e.top);
        let u = self.bounds.along(t, forward);
        let up = self.bounds.pt(u);
        // It counts unless every edge at it is flat (the bound's next one, where it goes on up).
        let counts = !self.cert.is_flat(e) || (up.y > tp.y && !self.cert.is_flat_segment(tp, up));
        self.cert.on_scanline(tp, counts);
        if up.y == tp.y {
            self.certify_horizontal_top(tp, u, forward);
        }
    }

    /// [`SweepLine::certify_top`] of a bound running on along the scanline from `tp` to vertex
    /// `u`.
    #[cold]
    #[inline(never)]
    fn certify_horizontal_top(&mut self, tp: Point, u: u32, forward: bool) {
        let up = self.bounds.pt(u);
        self.cert.horizontal(tp, up);
        let w = self.bounds.pt(self.bounds.along(u, forward));
        self.cert.on_scanline(up, w.y > up.y && !self.cert.is_flat_segment(up, w));
    }

    /// The rounding certificate's test of output point `p` against the flat edges near it.
    #[cold]
    #[inline(never)]
    fn certify_flats(&mut self, p: Point) {
        let (a, b) = self.crossing_pair;
        let pair = [a, b].map(|id| (id != NONE).then(|| self.ael.get(id).segment()));
        self.cert.clear_of_flats(p, pair);
    }

    /// [`SweepLine::node_neighbours`] for active edge `k`: gives it `p` if it passes through it
    /// (lying on the line of `id` or `also` counts); false when the search should stop there.
    #[inline(always)]
    fn node_neighbour(&mut self, id: u32, also: u32, k: u32, p: Point, rounded: bool) -> bool {
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
        // On it: within rounding, exactly, along the line of `id` or `also`, or through the exact
        // crossing that a rounded `p` stands for.
        let on = within_rounding
            || e.side_of(p) == Orientation::Collinear
            || self.coincident(id, k)
            || (also != id && self.coincident(also, k))
            || (rounded && self.through_crossing(k));
        if !near || !on {
            return false;
        }
        if rounded && self.cert.checking() && k != self.crossing_pair.0 && k != self.crossing_pair.1 {
            self.cert.fail("an edge within rounding of a rounded point");
        }
        if e.outrec != NONE && p != e.bot && p != e.top {
            let left = self.is_left(k);
            self.out.add(e.outrec, left, p);
        }
        true
    }

    /// True when active edge `k` passes exactly through the exact crossing of the pair being
    /// processed (`predicates::through_crossing`, where f64 holds it exactly): the pair's rounded
    /// point is then `k`'s too, however far off `k` rounding put it. An edge at a small angle to
    /// the sweep line passes several times the rounding off such a point in x.
    fn through_crossing(&self, k: u32) -> bool {
        let (a, b) = self.crossing_pair;
        a != NONE && {
            let (ea, eb) = (self.ael.get(a), self.ael.get(b));
            through_crossing(self.ael.get(k).segment(), ea.segment(), eb.segment()) == Some(true)
        }
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

    /// [`SweepLine::add_point`] to `a`, whose neighbour `b` passes through `p` too and needs no point
    /// of its own there (it holds no chain, or `a`'s, which gets `p` now): `a`'s search would
    /// only pass `b`, so it starts beyond the pair, with either edge's line for the coincidence
    /// test (as [`SweepLine::node_pair_neighbours`]).
    fn add_point_beside(&mut self, a: u32, b: u32, p: Point) {
        let (rec, rec_b) = (self.ael.get(a).outrec, self.ael.get(b).outrec);
        let pair = self.adjacent(a, b);
        let Some((lo, hi)) = pair.filter(|_| rec != NONE && (rec_b == NONE || rec_b == rec)) else {
            self.add_point(a, p);
            return;
        };
        let left = self.is_left(a);
        self.out.add(rec, left, p);
        let rounded = self.rounded_crossing && !self.is_vertex_of(a, p);
        self.node_outward(a, b, lo, hi, p, rounded);
    }

    /// [`SweepLine::add_point`] to `a` and then to `b`, both contributing, with one neighbour
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

#[cfg(test)]
mod tests {
    use clip_core::{BoolOp, FillRule, Point, Polygons, Ring};

    use super::Sweep;
    use crate::Vatti;

    fn ring(points: &[(f64, f64)]) -> Ring {
        Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    /// Operands that share edges along lines that are not horizontal, in both orders side by
    /// side and both ways round: a square and the square right of it, a triangle and the one
    /// across its slanted edge, a square and a taller rectangle that shares part of its side.
    fn pairs() -> Vec<(Ring, Ring)> {
        let square = ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let right = ring(&[(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)]);
        let below = ring(&[(0.0, 0.0), (2.0, 0.0), (0.0, 3.0)]);
        let above = ring(&[(2.0, 0.0), (2.0, 3.0), (0.0, 3.0)]);
        let tall = ring(&[(1.0, -1.0), (3.0, -1.0), (3.0, 2.0), (1.0, 2.0)]);
        let mut pairs = Vec::new();
        for (a, b) in [(square.clone(), right), (below, above), (square, tall)] {
            for (a, b) in [(a.clone(), b.clone()), (b.reversed(), a.reversed())] {
                pairs.push((a.clone(), b.clone()));
                pairs.push((b, a));
            }
        }
        pairs
    }

    /// Where two operands run along one line, the sweep orders their edges so that no
    /// zero-width gap or sliver between them is output (`SweepLine::order_coincident`): the
    /// raw rings already touch nowhere, in either sweep, for ∩, ∪ and − under every fill rule.
    /// (Under ⊕ the region between is outside in either order: two regions side by side come
    /// out as two rings sharing the edge, which the clean-up joins.)
    #[test]
    fn edges_along_one_line_leave_no_gap_or_sliver_between_them() {
        for (a, b) in pairs() {
            let (a, b) = (Polygons::new(vec![a]), Polygons::new(vec![b]));
            for sweep in [Sweep::Scanbeam, Sweep::Events] {
                for op in [BoolOp::Intersection, BoolOp::Union, BoolOp::Difference] {
                    for fill in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative] {
                        let (a, b) = crate::swept_operands(&a, &b, sweep, false);
                        let touched = Vatti::sweep(
                            sweep,
                            &a,
                            &b,
                            op,
                            fill,
                            false,
                            false,
                            super::Certify::No,
                            |raw, touches, _, _, _| {
                                touches.find(raw);
                                touches.touched.contains(&true)
                            },
                        );
                        assert!(!touched, "{a:?} {op:?} {b:?}, {fill:?}, {sweep:?}: raw rings touch");
                    }
                }
            }
        }
    }
}
