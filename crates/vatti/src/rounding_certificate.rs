//! Proofs that rounding left the sweep's output with the exact arrangement's form: for operands
//! on a coarse grid or with only horizontal and vertical edges, before the sweep
//! ([`rounding_is_harmless`]); for any others, built as the
//! sweep goes ([`RoundingCertificate`]): every output point far from every edge and event it is
//! not on.
//!
//! The sweep decides everything on the input segments exactly, but crossing points are rounded
//! to f64 (a slide's crossings in x only). Each output vertex then sits within `r` of its exact
//! place in each coordinate ([`MOVE_ULPS`]). Moving vertices by at most that changes no
//! incidence, order or side as long as every output vertex stays farther than `2√2·r` from every
//! output edge it is not on: a vertex must touch an edge before two edges can cross, and an edge
//! moves by no more than its ends. The certificate holds when the sweep met nothing within the
//! clearance `δ` ([`CLEARANCE_ULPS`]) of the points it output. It is checked locally, in O(1) per
//! event, by three tests:
//!
//! 1. **Events apart.** No two events (input vertices, crossings, a slide's crossings,
//!    horizontal edges as events as wide as they are) lie within a box of `2W × 2H` of each
//!    other (`H = δ + 2r`, `W = 2H/s + 2δ`, `s` the least rise per unit of x of the edges that
//!    are not flat: at least `4H/D`, so `W ≤ D/2 + 2δ`, `D` 2^-16 of the operands' largest
//!    coordinate), unless both lie on one scanline (exactly: vertices, and a slide's crossings,
//!    which move along it), both are crossings of one edge, or neither counts (crossings of a
//!    flat edge, vertices of flat edges only: they cannot come between a point and an edge that
//!    is not flat).
//! 2. **Flat edges on their own.** An edge rising less than `4H/D` per unit of x (and not
//!    horizontal) is checked against every output point near it, on a list of its own. Any other
//!    edge within `δ` of a point runs at most `H/s ≤ D/4` in x within `H` of the point's height,
//!    so it crosses the point's box from bottom to top, with no end in it (test 1).
//! 3. **Neighbours clear.** At each output point `p`, the nearest edge on either side in the
//!    table that does not pass through `p` and is not flat is farther than `δ` from it; on a
//!    scanline, the nearest edge *spanning* it, past edges that end or start on it.
//!
//! Why 3 suffices: let `e` pass within `δ` of `p` at `q`, and `k` be the nearest neighbour on
//! `e`'s side. Inside the box no two edges cross and none ends (1; crossings of `p`'s own edges do
//! not come between `k` and `e`), and `k` and `e` span it (2), so `k` lies between `p`'s edges and
//! `e` at every height there; the segment `pq` runs from one side of `k` to the other inside the
//! box, so it meets `k`, which is then within `δ`. On a scanline, edges that end or start on it
//! stay on one side of it but for that end, which is a point of the scanline; a point of the
//! scanline moves along it, so it cannot reach them.
//!
//! A crossing whose computed point lies exactly on both its edges is the exact crossing, not a
//! rounded point (integer inputs have many): where every point output is exact and the events
//! came in their exact order, the output is the exact one whatever the checks found.
//!
//! Where the certificate fails and some output point was rounded, the caller sweeps the
//! snap-rounded operands instead (`snap_fallback`), whose output is valid by construction.
//! Property used: none of the input's shape. It fails where features come within `δ` of each
//! other: nearly coincident edges, vertices a few ulps off an edge, three edges through a
//! crossing f64 cannot hold; and where events lie within `H` in height and `W` in x: the box is
//! narrow where every edge that is not flat is steep (rings of many vertices, grids of polygons:
//! events on one height far apart), as wide as `D` where some edge nearly is flat.

use clip_core::predicates::{on_coarse_grid, on_segment};
use clip_core::{Point, Polygons, Segment};

use crate::active::{Edge, X_AT_ERROR};
use crate::bounds::Bounds;

/// The largest error accepted for a crossing's quotient, in ulps (2^-52) of the operands'
/// largest coordinate: where a crossing's error bound is larger (edges at a small angle), it is
/// recomputed from accurate determinants (`Edge::crossing_with`; those err by under 17 ulps).
pub(crate) const CROSSING_ERROR_ULPS: f64 = 32.0;

/// The most an output point moves from its exact place in each coordinate, in ulps of the
/// largest coordinate: a crossing's error, plus as much again and an edge's x on a scanline (6
/// ulps) where it was clamped into its range and taken on the steeper edge, rising at least one
/// per unit of x (else the certificate fails), plus 6 for x clamped between the edges' ends.
const MOVE_ULPS: f64 = 2.0 * CROSSING_ERROR_ULPS + 12.0;

/// The clearance `δ`, in ulps of the largest coordinate: over twice the largest move of a point
/// (`√2` times [`MOVE_ULPS`]), so a point stays clear of edges that moved by as much.
pub(crate) const CLEARANCE_ULPS: f64 = 256.0;

const _: () = assert!(CLEARANCE_ULPS > 2.0 * 1.4143 * MOVE_ULPS);

/// A near miss (`near_misses`): a vertex within this many ulps of the largest coordinate of an
/// edge it is not on, as the snap fallback's pixel.
const PIXEL_ULPS: f64 = 4.0;

/// `D` as a fraction of the largest coordinate: edges rising less than `4H/D` per unit of x are
/// flat, and two events within `D/2 + 2δ` in x of each other (and `H` in height) fail. Smaller
/// makes more edges flat (each checked against the output points near it), larger more events
/// fail.
const REACH: f64 = 1.0 / 65536.0;

/// Comparisons of one event with earlier ones within reach in height before the certificate
/// gives up (fails): events that count piled near one height are where it fails anyway. Events
/// that do not count (a flat edge's crossings) pile up harmlessly, and are compared only with
/// events whose box meets their extent ([`EventRun`]).
const COMPARISONS: usize = 64;

/// Binary digits up to which integer coordinates, on any power-of-two scale, make the sweep's
/// rounding harmless ([`rounding_is_harmless`]; the bounds there hold up to 9).
const HARMLESS_DIGITS: u32 = 9;

/// True when rounding cannot change the form of the sweep's output, so it needs no certificate:
/// the operands are on a coarse grid ([`coarse_grid`]) or every edge is horizontal or
/// vertical ([`axis_parallel`]).
pub(crate) fn rounding_is_harmless(subject: &Polygons, clip: &Polygons) -> bool {
    coarse_grid(subject, clip) || axis_parallel(subject, clip)
}

/// True when every coordinate of `subject` and `clip` is an integer below 2^m (m =
/// [`HARMLESS_DIGITS`]) in units of one power of two (`predicates::on_coarse_grid`). In those
/// units:
/// - every product in a crossing's computation is exact, so a crossing is the exact one rounded
///   once, and an edge's x on a scanline twice: under 2^(m-51) off;
/// - a crossing is a fraction with a denominator below 2^(2m+3), so two distinct crossing heights
///   differ by at least 2^-(4m+6), over an ulp: the sweep takes its events in their exact order,
///   and its decisions, which are exact predicates, are those of exact arithmetic;
/// - a crossing or vertex off a segment's line lies at least 2^-(3m+5) from it, and two distinct
///   points at least 2^-(4m+6) apart: rounding moves no point onto, across or within rounding of
///   an edge or point it is not on, so the rounded output meets itself exactly where the exact
///   one does.
///
/// Such inputs (several edges through one crossing, rows of vertices) are where the certificate
/// would fail. Property used: coordinates of few binary digits (grids, pixel and tile
/// coordinates).
fn coarse_grid(subject: &Polygons, clip: &Polygons) -> bool {
    fn coarse<'a>(points: impl Iterator<Item = &'a Point>) -> bool {
        on_coarse_grid(points.flat_map(|q| [q.x, q.y]), HARMLESS_DIGITS)
    }
    let points = || [subject, clip].into_iter().flat_map(|p| p.rings.iter().flat_map(|r| &r.points));
    // Every 61st point first: an input off the grid, or spanning more digits, mostly shows it
    // there, before a pass over every point (integer spirals reach their far coordinates late).
    coarse(points().step_by(61)) && coarse(points())
}

/// True when every edge of `subject` and `clip` is horizontal or vertical. Then nothing the sweep
/// outputs is rounded: vertical edges cross only horizontal ones, on the scanline of the
/// horizontal, at the vertical's x (`Edge::x_at` is exact along a vertical edge), and every
/// event is at an input vertex's height, so the events come in their exact order. The output is
/// the exact arrangement's, with every coordinate an input's. Property used: rectilinear
/// operands (layouts, raster outlines, tiles, boxes), at any coordinates.
fn axis_parallel(subject: &Polygons, clip: &Polygons) -> bool {
    subject.edges().chain(clip.edges()).all(|e| e.a.x == e.b.x || e.a.y == e.b.y)
}

/// The certificate's state over one sweep.
#[derive(Debug, Default)]
pub(crate) struct RoundingCertificate {
    /// False for sweeps whose rounding is harmless anyway (coarse grids, axis-parallel edges,
    /// snap-rounded operands).
    enabled: bool,
    /// The largest accepted error of a crossing's quotient, and `r`: the most a point moves.
    max_error: f64,
    moves: f64,
    /// `δ`: how far from an output point every edge it is not on must be, and that grown by what
    /// the computed distances err by.
    clearance: f64,
    clearance_reach: f64,
    /// `H = δ + 2r` and `W = 2H/s + 2δ`: the box within which two events may not lie (heights err
    /// by `r`; `s` the least rise of an edge that is not flat), and the least rise per unit of x
    /// of an edge that is not flat, `4H/D`.
    height: f64,
    reach: f64,
    least_rise: f64,
    /// Edges that rise less than `4H/D` per unit of x (and are not horizontal) are checked
    /// against every output point near them instead: they can pass near a point far from it
    /// in the table. Sorted by their lower end; those from `next_flat` on are not reached yet.
    flats: Vec<Segment>,
    next_flat: usize,
    /// Flat edges whose span, grown by `δ`, the sweep has reached.
    near_flats: Vec<Segment>,
    /// The highest event height so far: events come in order of height, within their rounding.
    max_y: f64,
    /// Events within reach in height of the sweep, but those of the current scanline.
    recent: Events,
    /// The current scanline's height and events.
    row_y: f64,
    row: Events,
    /// True once some check failed, and the first one that did.
    failed: bool,
    failure: Option<&'static str>,
    /// `enabled && !failed`, kept as one flag: it is read at every event.
    checking: bool,
    /// True once a rounded point was output.
    rounded: bool,
    /// True once an event came below another taken before it by more than their rounding.
    out_of_order: bool,
    /// True once the sweep's decisions may not be those of any one input (a near miss it put
    /// off was not routed, see `near_misses`): the output is not certified whatever it holds.
    broken: bool,
    /// The least rise per unit of x of the edges that are not flat (`s`, kept from `reset`): a
    /// split edge's parts must rise as much, or the event box would be too narrow for them.
    steep_rise: f64,
    /// The distance within which a vertex is a near miss of an edge (`near_misses`): four ulps
    /// of the largest coordinate, as the snap fallback's pixel.
    pixel: f64,
    /// How far in x a non-flat edge within `pixel` of a point can lie from it on the point's
    /// scanline, with what its computed x errs by.
    pixel_reach: f64,
}

impl RoundingCertificate {
    /// Clears the certificate for a sweep of `bounds` (the buffers are kept); `enabled` false
    /// checks nothing, and the certificate always holds.
    pub(crate) fn reset(&mut self, enabled: bool, bounds: &Bounds) {
        (self.enabled, self.checking) = (enabled, enabled);
        (self.failed, self.failure, self.out_of_order, self.broken) = (false, None, false, false);
        self.rounded = false;
        self.flats.clear();
        self.near_flats.clear();
        self.recent.clear();
        self.row.clear();
        (self.next_flat, self.max_y, self.row_y) = (0, f64::NEG_INFINITY, f64::NAN);
        self.max_error = f64::INFINITY;
        if !enabled {
            return;
        }
        // Coordinates are finite (validated), so a plain comparison (one `maxsd`) does what
        // `f64::max` does with its NaN handling.
        let larger = |m: f64, c: f64| if m > c.abs() { m } else { c.abs() };
        let magnitude = bounds.vertices.iter().fold(0.0f64, |m, v| larger(larger(m, v.pt.x), v.pt.y));
        let unit = f64::EPSILON * magnitude.max(f64::MIN_POSITIVE);
        self.max_error = CROSSING_ERROR_ULPS * unit;
        self.moves = MOVE_ULPS * unit;
        self.clearance = CLEARANCE_ULPS * unit;
        self.height = self.clearance + 2.0 * self.moves;
        self.clearance_reach = self.clearance + 2.0 * X_AT_ERROR * magnitude;
        self.least_rise = 4.0 * self.height / (REACH * magnitude);
        let least_rise = self.least_rise;
        // The least rise of the edges that are not flat (infinity for none, or vertical ones
        // only), computed with a relative error under 2^-50.
        let mut steep_rise = f64::INFINITY;
        for v in &bounds.vertices {
            let w = bounds.vertices[v.next as usize].pt;
            let (dx, dy) = ((w.x - v.pt.x).abs(), (w.y - v.pt.y).abs());
            if dy != 0.0 && !at_least(dy, least_rise * dx) {
                self.flats.push(if v.pt.y < w.y { Segment::new(v.pt, w) } else { Segment::new(w, v.pt) });
            } else if dx != 0.0 && dy != 0.0 {
                steep_rise = steep_rise.min(dy / dx);
            }
        }
        // An edge rising at least `s` runs at most `H/s` in x within `H` of a height: at most
        // `D/4`, as `s >= 4H/D`, and less where every edge that is not flat is steeper.
        let s = (steep_rise * (1.0 - 1e-12)).max(least_rise);
        self.reach = 2.0 * self.height / s + 2.0 * self.clearance;
        self.steep_rise = s;
        self.pixel = PIXEL_ULPS * unit;
        // Within `pixel` of a point, an edge rising `s` per unit of x lies within
        // `pixel * sqrt(1 + 1 / s^2)` of it in x.
        self.pixel_reach = self.pixel * (1.0 + 1.0 / s) + 2.0 * X_AT_ERROR * magnitude;
        self.flats.sort_unstable_by(|a, b| a.a.y.total_cmp(&b.a.y));
    }

    /// True when the output's form is the exact arrangement's: every check held, or nothing
    /// rounded was output and the events came in their exact order (then every decision was
    /// exact and every output point is exact).
    pub(crate) fn holds(&self) -> bool {
        !(self.failed && (self.rounded || self.out_of_order || self.broken))
    }

    /// `Ok` where the certificate [holds](RoundingCertificate::holds), else the first check that
    /// failed.
    pub(crate) fn verdict(&self) -> Result<(), &'static str> {
        if self.holds() { Ok(()) } else { Err(self.failure.unwrap_or("a check")) }
    }

    /// True while checks are made.
    #[inline]
    pub(crate) fn checking(&self) -> bool {
        self.checking
    }

    /// True when this sweep is certified at all, failed or not: then whether a point output is
    /// rounded decides whether a failed check matters ([`RoundingCertificate::holds`]).
    #[inline]
    pub(crate) fn certifying(&self) -> bool {
        self.enabled
    }

    /// The largest crossing error accepted, or infinity when nothing is checked (a crossing is
    /// then computed as it always is: exactly rounded on coarse grids).
    #[inline]
    pub(crate) fn max_error(&self) -> f64 {
        self.max_error
    }

    /// True when edge `e` rises less than the flat edges' limit: such a neighbour is checked
    /// against the flat list, not taken as the nearest edge spanning the point's box.
    #[inline]
    pub(crate) fn is_flat(&self, e: &Edge) -> bool {
        self.is_flat_segment(e.bot, e.top)
    }

    /// [`RoundingCertificate::is_flat`] for the edge from `a` to `b` (horizontal ones too).
    #[inline]
    pub(crate) fn is_flat_segment(&self, a: Point, b: Point) -> bool {
        (b.y - a.y).abs() < self.least_rise * (b.x - a.x).abs()
    }

    /// An event on scanline `p.y`: an input vertex (which `counts` unless all its edges are
    /// flat or horizontal), or where a slide passes an edge (which counts unless the edge is
    /// flat).
    #[inline]
    pub(crate) fn on_scanline(&mut self, p: Point, counts: bool) {
        self.scanline_event(Event { p, half_width: 0.0, counts, edges: None });
    }

    /// A horizontal edge from `a` to `b` on scanline `a.y`.
    #[inline]
    pub(crate) fn horizontal(&mut self, a: Point, b: Point) {
        let (p, half_width) = (Point::new(0.5 * (a.x + b.x), a.y), 0.5 * (b.x - a.x).abs());
        self.scanline_event(Event { p, half_width, counts: true, edges: None });
    }

    #[inline]
    fn scanline_event(&mut self, event: Event) {
        if !self.checking() {
            return;
        }
        if event.p.y != self.row_y {
            // The last scanline's events join the others while within reach of this one.
            if event.p.y - self.row_y <= self.height {
                self.recent.append(&mut self.row);
            } else {
                self.row.clear();
            }
            self.row_y = event.p.y;
        }
        self.apart(event);
        self.row.push(event);
    }

    /// A crossing between scanlines at `p` of the edges named `edges` (each an active edge's
    /// record and top vertex: one segment), off its exact place by at most `r`; it `counts`
    /// unless one of them is flat.
    #[inline]
    pub(crate) fn between_scanlines(&mut self, p: Point, edges: [u64; 2], counts: bool) {
        if !self.checking() {
            return;
        }
        let event = Event { p, half_width: 0.0, counts, edges: Some(edges) };
        self.apart(event);
        if (p.y - self.row_y).abs() <= self.height && self.crowded(&event, &self.row) {
            self.fail_because("events in a box (a crossing near a scanline event)");
        }
        self.recent.push(event);
    }

    /// Fails when `e` comes below the highest event so far by more than the rounding of both,
    /// or lies within the box of an event of another height, dropping those out of reach.
    #[inline]
    fn apart(&mut self, e: Event) {
        if self.max_y < e.p.y - self.height {
            // Every event so far is out of reach of this one, and so of every later one (none
            // may come below it by more than the rounding, which `height` exceeds).
            self.max_y = e.p.y;
            self.recent.clear_unless_empty();
            return;
        }
        if e.p.y < self.max_y - 2.0 * self.moves {
            self.out_of_order = true;
            self.fail_because("out of order");
        }
        self.max_y = self.max_y.max(e.p.y);
        if self.recent.is_empty() {
            return;
        }
        self.apart_from_recent(e);
    }

    /// The part of [`RoundingCertificate::apart`] that looks at the recent events.
    #[inline(never)]
    fn apart_from_recent(&mut self, e: Event) {
        if self.recent.drop_below(e.p.y - self.height) && self.crowded(&e, &self.recent) {
            self.fail_because("events in a box");
        }
    }

    /// True when `e` lies within the box of one of `events` it is compared with
    /// ([`Events::compared_with`]), or those are more than [`COMPARISONS`].
    #[inline]
    fn crowded(&self, e: &Event, events: &Events) -> bool {
        let (counting, others) = events.compared_with(e, self.reach);
        counting.len() + others.len() > COMPARISONS
            || counting.iter().any(|q| self.in_box(e, q))
            || others.iter().any(|q| self.in_box(e, q))
    }

    /// True when events `e` and `q` lie within each other's box, but for two crossings of one
    /// edge ([`Event::shares_edge`]).
    #[inline]
    fn in_box(&self, e: &Event, q: &Event) -> bool {
        (q.p.y - e.p.y).abs() <= self.height
            && (q.p.x - e.p.x).abs() <= self.reach + e.half_width + q.half_width
            && !e.shares_edge(q)
    }

    /// The sweep's decisions may not be those of one input: the certificate fails whatever was
    /// output.
    #[cold]
    pub(crate) fn break_off(&mut self, check: &'static str) {
        if self.enabled {
            self.broken = true;
            self.fail_because(check);
        }
    }

    /// The near-miss distance and how far in x an edge within it may lie, or `None` while no
    /// checks are made (nothing is routed then).
    #[inline]
    pub(crate) fn near_miss_reach(&self) -> Option<(f64, f64)> {
        self.checking.then_some((self.pixel, self.pixel_reach))
    }

    /// How far in x an edge within a near miss of a point may lie from it (infinite while no
    /// checks are made, so every walk looks).
    #[inline]
    pub(crate) fn pixel_reach(&self) -> f64 {
        if self.checking { self.pixel_reach } else { f64::INFINITY }
    }

    /// True when an edge from `a` through `v` to `b` (`a.y < v.y < b.y`) keeps the certificate's
    /// bounds: neither part is flat or rises less than the least rise the event box was made
    /// for, and no flat edge comes within the clearance of `v` (flat edges pass near a point far
    /// from it in the table, where a sweep's neighbours do not show them).
    pub(crate) fn admits_split(&self, a: Point, v: Point, b: Point) -> bool {
        let steep = |p: Point, q: Point| q.y > p.y && (q.x == p.x || q.y - p.y >= self.steep_rise * (q.x - p.x).abs());
        steep(a, v) && steep(v, b) && !self.flat_near(v)
    }

    /// True when some flat edge passes within the clearance of `v` (every flat edge is looked
    /// at: splits are rare).
    fn flat_near(&self, v: Point) -> bool {
        let reach = self.clearance + self.slack(v, 0.0);
        self.flats.iter().take_while(|f| f.a.y <= v.y + reach).any(|&f| {
            f.b.y >= v.y - reach && distance_to_segment(v, f) <= reach + self.slack(v, f.a.x.abs().max(f.b.x.abs()))
        })
    }

    /// A rounded point went into the output.
    #[inline]
    pub(crate) fn rounded_output(&mut self) {
        self.rounded = true;
    }

    /// A check of the sweep's failed (nothing, where checks are not made).
    #[inline]
    pub(crate) fn fail(&mut self, check: &'static str) {
        if self.enabled {
            self.fail_because(check);
        }
    }

    /// Notes the first failed check.
    #[cold]
    fn fail_because(&mut self, check: &'static str) {
        if !self.failed {
            self.failure = Some(check);
        }
        (self.failed, self.checking) = (true, false);
    }

    /// Records whether output point `p` lies farther than the clearance from the line of edge
    /// `k`, which spans its height.
    #[inline]
    pub(crate) fn clear_of(&mut self, p: Point, k: &Edge) {
        let d = k.top - k.bot;
        let off = (p - k.bot).cross(d);
        // Clear by the L1 length, which is at least |d|, in the common case: no square root to
        // wait for (NaN and overflow fall through to the test below).
        if off.abs() >= self.clearance_reach * (d.x.abs() + d.y.abs()) && off != 0.0 {
            return;
        }
        // |off| / |d| is the distance to the line, at most the distance to the segment; the
        // computed values err by a few ulps of the operands' largest coordinate, which the
        // slack in `clearance_reach` covers. Not compared squared: near `MAX_COORDINATE` both
        // squares overflow to infinity, and infinity is at least infinity.
        if !at_least(off.abs(), self.clearance_reach * d.dot(d).sqrt()) || off == 0.0 {
            self.fail_because("a neighbour within the clearance");
        }
    }

    /// True when flat edges may lie near height `p.y`: those not reached yet start above it, so
    /// without flat edges reached or about to be, there is nothing to check.
    #[inline]
    pub(crate) fn flats_near(&self, p: Point) -> bool {
        !self.near_flats.is_empty() || self.flats.get(self.next_flat).is_some_and(|f| f.a.y <= p.y + self.clearance)
    }

    /// Records whether output point `p` lies farther than the clearance from every flat edge
    /// near its height, but those it lies on (exactly) and the crossing pair `pair` it is a
    /// crossing of.
    #[inline]
    pub(crate) fn clear_of_flats(&mut self, p: Point, pair: [Option<Segment>; 2]) {
        while let Some(&f) = self.flats.get(self.next_flat) {
            if f.a.y > p.y + self.clearance {
                break;
            }
            self.near_flats.push(f);
            self.next_flat += 1;
        }
        if self.near_flats.is_empty() {
            return;
        }
        let reach = self.clearance;
        self.near_flats.retain(|f| f.b.y >= p.y - reach);
        if self.near_flats.len() > 16 * COMPARISONS {
            self.fail_because("too many flat edges near a point");
            return;
        }
        for i in 0..self.near_flats.len() {
            let f = self.near_flats[i];
            let (lo, hi) = if f.a.x < f.b.x { (f.a.x, f.b.x) } else { (f.b.x, f.a.x) };
            if p.x < lo - reach || p.x > hi + reach {
                continue;
            }
            if pair.contains(&Some(f)) || pair.contains(&Some(Segment::new(f.b, f.a))) {
                continue;
            }
            let slack = self.slack(p, f.a.x.abs().max(f.a.y.abs()).max(f.b.x.abs()).max(f.b.y.abs()));
            if distance_to_segment(p, f) <= self.clearance + slack && !on_segment(p, f) {
                self.fail_because("a flat edge within the clearance");
                return;
            }
        }
    }

    /// What the computed distances may err by near `p` and coordinates up to `magnitude`.
    #[inline]
    fn slack(&self, p: Point, magnitude: f64) -> f64 {
        2.0 * X_AT_ERROR * magnitude.max(p.x.abs()).max(p.y.abs())
    }
}

/// An event: a crossing of two edges between scanlines, or one on a scanline (an input vertex,
/// where a slide passes an edge, a horizontal edge).
#[derive(Clone, Copy, Debug)]
struct Event {
    /// Where it is: a horizontal edge's middle.
    p: Point,
    /// Half a horizontal edge's length, else 0.
    half_width: f64,
    /// False for events only of flat edges: those are checked against the output points near
    /// them on their own list, and cannot come between a point and an edge that is not flat.
    counts: bool,
    /// The crossing's two edges, for a crossing between scanlines.
    edges: Option<[u64; 2]>,
}

impl Event {
    /// True when both are crossings between scanlines of one edge: neither is then a crossing
    /// of two edges that the other is not on, nor the end of one, so neither can come between
    /// the other and an edge near it (see the module's argument).
    #[inline]
    fn shares_edge(&self, q: &Event) -> bool {
        match (self.edges, q.edges) {
            (Some(a), Some(b)) => a.iter().any(|s| b.contains(s)),
            _ => false,
        }
    }
}

/// Events of the box test, those that count apart from the others: an event that does not
/// count is compared only with those that do, so a pile of crossings of one flat edge is not
/// compared within itself.
#[derive(Debug, Default)]
struct Events {
    counting: EventRun<false>,
    others: EventRun<true>,
}

impl Events {
    fn clear(&mut self) {
        self.counting.clear();
        self.others.clear();
    }

    #[inline]
    fn push(&mut self, e: Event) {
        if e.counts { self.counting.push(e) } else { self.others.push(e) }
    }

    /// Moves every event of `row` here.
    fn append(&mut self, row: &mut Events) {
        self.counting.append(&mut row.counting);
        self.others.append(&mut row.others);
    }

    #[inline]
    fn is_empty(&self) -> bool {
        self.counting.is_empty() && self.others.is_empty()
    }

    #[inline]
    fn clear_unless_empty(&mut self) {
        if !self.is_empty() {
            self.clear();
        }
    }

    /// Drops the events below height `y`; false when none is left.
    #[inline]
    fn drop_below(&mut self, y: f64) -> bool {
        self.counting.drop_below(y);
        self.others.drop_below(y);
        !self.is_empty()
    }

    /// The events `e` is compared with, its box `reach` wide either side of it: those that
    /// count, and where `e` counts the others, if the box meets their extent.
    #[inline]
    fn compared_with(&self, e: &Event, reach: f64) -> (&[Event], &[Event]) {
        let (lo, hi) = (e.p.x - e.half_width - reach, e.p.x + e.half_width + reach);
        let others = if e.counts { self.others.near(lo, hi) } else { &[] };
        (self.counting.near(lo, hi), others)
    }
}

/// Events in order of height (within rounding), oldest first from `first`, and where `EXTENT`,
/// the x extent of every event pushed since the run was last empty (horizontals' half widths
/// included), so a box that misses it meets none of them: a pile of crossings along a flat edge
/// spans the part of the edge they are on, and events elsewhere at its height are not compared
/// with them. (Events that count pile up only where the certificate fails anyway.)
#[derive(Debug)]
struct EventRun<const EXTENT: bool> {
    events: Vec<Event>,
    first: usize,
    lo: f64,
    hi: f64,
}

impl<const EXTENT: bool> Default for EventRun<EXTENT> {
    fn default() -> Self {
        EventRun { events: Vec::new(), first: 0, lo: f64::INFINITY, hi: f64::NEG_INFINITY }
    }
}

impl<const EXTENT: bool> EventRun<EXTENT> {
    fn clear(&mut self) {
        self.events.clear();
        (self.first, self.lo, self.hi) = (0, f64::INFINITY, f64::NEG_INFINITY);
    }

    #[inline]
    fn push(&mut self, e: Event) {
        if EXTENT {
            self.lo = self.lo.min(e.p.x - e.half_width);
            self.hi = self.hi.max(e.p.x + e.half_width);
        }
        self.events.push(e);
    }

    /// Moves every event of `other` here.
    fn append(&mut self, other: &mut Self) {
        for &e in &other.events[other.first..] {
            self.push(e);
        }
        other.clear();
    }

    #[inline]
    fn is_empty(&self) -> bool {
        self.first == self.events.len()
    }

    /// Drops the events below height `y`, and the buffer and extent once none is left.
    #[inline]
    fn drop_below(&mut self, y: f64) {
        while self.first < self.events.len() && self.events[self.first].p.y < y {
            self.first += 1;
        }
        if self.is_empty() {
            self.clear();
        }
    }

    /// The events left, or none where the x range `lo..=hi` misses their extent.
    #[inline]
    fn near(&self, lo: f64, hi: f64) -> &[Event] {
        if EXTENT && (hi < self.lo || lo > self.hi) { &[] } else { &self.events[self.first..] }
    }
}

/// `a >= b`, false where either is NaN (an overflow): every test that uses it then fails safe.
#[inline]
fn at_least(a: f64, b: f64) -> bool {
    a >= b
}

/// The distance from `p` to segment `s`, computed.
fn distance_to_segment(p: Point, s: Segment) -> f64 {
    let d = s.b - s.a;
    let len2 = d.dot(d);
    let t = if len2 > 0.0 { ((p - s.a).dot(d) / len2).clamp(0.0, 1.0) } else { 0.0 };
    let q = Point::new(s.a.x + t * d.x, s.a.y + t * d.y);
    (p - q).dot(p - q).sqrt()
}

#[cfg(test)]
mod tests {
    use clip_core::{BoolOp, FillRule, Ring, WindowKind};
    use clip_oracle::polygon::check_valid_output;
    use clip_testkit::workload::polygon_case;

    use super::*;
    use crate::{Certify, Operands, Sweep, Vatti, swept_operands};

    fn polygon(points: &[(f64, f64)]) -> Polygons {
        Polygons::from(Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect()))
    }

    /// The check that fails for `a op b` (`Ok`: the certificate holds), by both sweeps, which
    /// must agree on whether it holds.
    fn verdict(a: &Polygons, b: &Polygons, op: BoolOp) -> Result<(), &'static str> {
        let run = |sweep| {
            let (a, b) = swept_operands(a, b, sweep, true);
            Vatti::sweep(sweep, &a, &b, op, FillRule::NonZero, false, false, Certify::Yes, |_, _, _, _, v| v)
        };
        let (events, scanbeam) = (run(Sweep::Events), run(Sweep::Scanbeam));
        assert_eq!(
            events.is_ok(),
            scanbeam.is_ok(),
            "the sweeps disagree on {a:?} {op:?} {b:?}: {events:?} {scanbeam:?}"
        );
        events
    }

    fn certified(a: &Polygons, b: &Polygons, op: BoolOp) -> bool {
        verdict(a, b, op).is_ok()
    }

    /// A square [0, 1]² and a triangle crossing its top edge, with its apex `apex`.
    fn square_and_spike(apex: (f64, f64)) -> (Polygons, Polygons) {
        let square = polygon(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let spike = polygon(&[(0.3, 0.5), (0.45, 0.55), apex]);
        (square, spike)
    }

    #[test]
    fn crossings_far_from_everything_hold() {
        let (square, spike) = square_and_spike((0.4, 1.7));
        for op in BoolOp::ALL {
            assert!(certified(&square, &spike, op), "{op:?}");
        }
        // Edges at an angle of 0.02 cross far from everything: the quotient's error bound is
        // past the accepted one, so the crossing is recomputed accurately, and it holds.
        let a = polygon(&[(0.0, 0.0), (1.0, 0.01), (0.5, 1.0)]);
        let b = polygon(&[(0.0, 0.01), (1.0, 0.0), (0.5, -1.0)]);
        for op in BoolOp::ALL {
            assert_eq!(verdict(&a, &b, op), Ok(()), "{op:?}");
        }
    }

    #[test]
    fn a_vertex_a_few_ulps_off_an_edge_fails() {
        // The spike's apex lies 2 ulps above the square's top edge: the two crossings next to it
        // come within the clearance of the apex and of each other.
        let above = 1.0 + 2.0 * f64::EPSILON;
        let (square, spike) = square_and_spike((0.4, above));
        for op in BoolOp::ALL {
            assert!(!certified(&square, &spike, op), "{op:?}");
        }
        // An apex exactly on the edge rounds nothing near it: no crossing is rounded.
        let (square, spike) = square_and_spike((0.4, 1.0));
        assert!(certified(&square, &spike, BoolOp::Union));
    }

    #[test]
    fn a_crossing_next_to_an_edge_it_is_not_on_fails() {
        // Two long edges cross at about (0.5, 0.5); a third passes 1e-14 left of that point.
        let x = polygon(&[(0.0, 0.0), (1.0, 1.0), (1.0, 0.0), (0.0, 1.0)]);
        let third = polygon(&[(0.5 - 1e-14, 0.2), (0.5 - 1e-14, 0.8), (0.2, 0.8)]);
        assert!(!certified(&x, &third, BoolOp::Union));
        // (Not (0.2, 0.8): in binary it lies 6e-17 off the diagonal x + y = 1, a near miss too.)
        let far = polygon(&[(0.45, 0.2), (0.45, 0.8), (0.25, 0.7)]);
        assert_eq!(verdict(&x, &far, BoolOp::Union), Ok(()));
    }

    #[test]
    fn a_vertex_near_an_edge_that_spans_its_scanline_fails() {
        // A triangle's apex 20 ulps left of the square's right side (farther than the sweep's
        // rounding, nearer than the clearance), its other edges crossing the left side: the
        // side is the apex's nearest neighbour in the table.
        let square = polygon(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let triangle = |apex: f64| polygon(&[(apex, 0.5), (-0.5, 0.7), (-0.5, 0.2)]);
        assert_eq!(verdict(&square, &triangle(0.9), BoolOp::Intersection), Ok(()));
        let near = 1.0 - 20.0 * f64::EPSILON;
        assert_eq!(verdict(&square, &triangle(near), BoolOp::Intersection), Err("a neighbour within the clearance"));
    }

    #[test]
    fn a_nearly_horizontal_edge_is_checked_against_the_points_near_it() {
        // The square's top runs from (0, 1) to (1, 1 + 1 ulp): it rises under 1e-15 per unit, so
        // it is checked on its own list. A triangle crosses the square's left side (rounded
        // crossings) and has its apex inside, 0.1 below the top (it holds) or 3 ulps below it,
        // where the top is not yet in the table: only the list sees it.
        let tilted = polygon(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0 + f64::EPSILON), (0.0, 1.0)]);
        let triangle = |apex: f64| polygon(&[(0.4, apex), (-0.5, 0.3), (0.3, 0.2)]);
        assert_eq!(verdict(&tilted, &triangle(0.9), BoolOp::Intersection), Ok(()));
        let near = 1.0 - 3.0 * f64::EPSILON;
        assert_eq!(verdict(&tilted, &triangle(near), BoolOp::Intersection), Err("a flat edge within the clearance"));
    }

    #[test]
    fn where_it_fails_the_output_is_still_valid() {
        let above = 1.0 + 2.0 * f64::EPSILON;
        let (square, spike) = square_and_spike((0.4, above));
        for op in BoolOp::ALL {
            for fill in FillRule::ALL {
                let out = crate::clip_planned(&square, &spike, None, op, fill, crate::route::Plan::WHOLE);
                check_valid_output(&out).unwrap_or_else(|e| panic!("{op:?} {fill:?}: {e}"));
            }
        }
    }

    /// Crossings f64 holds exactly are not rounded: integer operands past the coarse grids
    /// (wind-mills at 10^4 edges: multiples of 10 up to 2,840, eleven binary digits in units of
    /// two) have events in each other's boxes, which fails the checks, yet every crossing they
    /// output is exact, so the certificate holds, and every output coordinate is an integer.
    #[test]
    fn exact_crossings_let_the_certificate_hold_where_its_checks_fail() {
        let case = clip_testkit::workload::polygon_case_sized("wind-mill", 1, 0, 10_000, WindowKind::Any)
            .expect("a polygon workload");
        assert!(!rounding_is_harmless(&case.subject, &case.clip), "not on a coarse grid");
        for op in BoolOp::ALL {
            for sweep in [Sweep::Events, Sweep::Scanbeam] {
                let (a, b) = swept_operands(&case.subject, &case.clip, sweep, true);
                let out = Vatti::sweep_clean(&a, &b, op, FillRule::EvenOdd, sweep, Operands::Float)
                    .unwrap_or_else(|| panic!("{op:?} {sweep:?}: the certificate failed"));
                check_valid_output(&out).unwrap_or_else(|e| panic!("{op:?} {sweep:?}: {e}"));
                assert!(out.points().all(|p| p.x.fract() == 0.0 && p.y.fract() == 0.0), "{op:?} {sweep:?}");
            }
        }
    }

    /// Soundness on the hardest workload: wherever the certificate holds, the output it lets
    /// through has a valid form (it fails on most of these cases, and they fall back).
    #[test]
    fn where_it_holds_on_nearly_coincident_edges_the_output_is_valid() {
        let mut held = 0;
        for index in 0..40 {
            let case = polygon_case("near-coincident", 7, index, WindowKind::Any).expect("a polygon workload");
            for op in BoolOp::ALL {
                for sweep in [Sweep::Events, Sweep::Scanbeam] {
                    let (a, b) = swept_operands(&case.subject, &case.clip, sweep, true);
                    let out = Vatti::sweep_clean(&a, &b, op, FillRule::EvenOdd, sweep, Operands::Float);
                    if let Some(out) = out {
                        held += 1;
                        check_valid_output(&out).unwrap_or_else(|e| panic!("case {index} {op:?} {sweep:?}: {e}"));
                    }
                }
            }
        }
        assert!(held > 0, "the certificate never held");
    }

    /// A certificate for operands reaching 1 in magnitude, enabled: a unit square with its
    /// bottom rising `rise` (a box `2H/rise + 2δ` wide; infinity: the square itself).
    fn certificate_rising(rise: f64) -> RoundingCertificate {
        let mut bounds = crate::bounds::Bounds::default();
        let bottom_right = if rise.is_finite() { rise } else { 0.0 };
        let square = polygon(&[(0.0, 0.0), (1.0, bottom_right), (1.0, 1.0), (0.0, 1.0)]);
        bounds.rebuild(&square, &Polygons::default(), false);
        let mut cert = RoundingCertificate::default();
        cert.reset(true, &bounds);
        cert.rounded_output();
        cert
    }

    /// A certificate whose box is about 1.8e-6 wide (an edge rising 1e-7 per unit of x).
    fn unit_certificate() -> RoundingCertificate {
        certificate_rising(1e-7)
    }

    #[test]
    fn the_box_is_as_wide_as_the_flattest_edge_that_is_not_flat_needs() {
        let p = Point::new(0.5, 0.5);
        for (rise, dx, holds) in [
            (1e-7, 1e-6, false),
            (1e-3, 1e-6, true),
            (1e-3, 1e-10, false),
            (f64::INFINITY, 1e-12, true),
            // A flat bottom (rising under 2.5e-8 per unit here) is on the flat list: the box is
            // as wide as the vertical sides need.
            (1e-9, 1e-12, true),
        ] {
            let mut cert = certificate_rising(rise);
            cert.on_scanline(p, true);
            cert.between_scanlines(Point::new(0.5 + dx, 0.5 + 1e-14), [3, 4], true);
            assert_eq!(cert.verdict().is_ok(), holds, "rise {rise}, {dx} apart");
        }
    }

    #[test]
    fn events_within_a_box_of_each_other_fail_unless_they_cross_one_edge() {
        let (a, b, c, d) = (1, 2, 3, 4);
        let p = Point::new(0.5, 0.5);
        let beside = Point::new(0.5 + 1e-6, 0.5 + 1e-14);
        // Apart in height or in x: holds.
        for q in [Point::new(0.5 + 1e-6, 0.5 + 1e-12), Point::new(0.5 + 1e-4, 0.5 + 1e-14)] {
            let mut cert = unit_certificate();
            cert.between_scanlines(p, [a, b], true);
            cert.between_scanlines(q, [c, d], true);
            assert_eq!(cert.verdict(), Ok(()), "{q:?}");
        }
        let mut cert = unit_certificate();
        cert.between_scanlines(p, [a, b], true);
        cert.between_scanlines(beside, [c, d], true);
        assert_eq!(cert.verdict(), Err("events in a box"));
        // Two crossings of one edge: neither comes between the other and an edge near it.
        let mut cert = unit_certificate();
        cert.between_scanlines(p, [a, b], true);
        cert.between_scanlines(beside, [b, c], true);
        assert_eq!(cert.verdict(), Ok(()));
        // A crossing just above a scanline's vertex, and a vertex just above a crossing.
        let mut cert = unit_certificate();
        cert.on_scanline(p, true);
        cert.between_scanlines(beside, [c, d], true);
        assert_eq!(cert.verdict(), Err("events in a box (a crossing near a scanline event)"));
        let mut cert = unit_certificate();
        cert.between_scanlines(p, [a, b], true);
        cert.on_scanline(beside, true);
        assert_eq!(cert.verdict(), Err("events in a box"));
        // Vertices of one scanline are never compared.
        let mut cert = unit_certificate();
        cert.on_scanline(p, true);
        cert.on_scanline(Point::new(0.5 + 1e-15, 0.5), true);
        assert_eq!(cert.verdict(), Ok(()));
    }

    /// A pile of crossings along one flat edge (which do not count) at one height: compared
    /// neither with each other nor, beyond the comparison limit, with an event far from them.
    #[test]
    fn a_pile_of_crossings_along_a_flat_edge_is_compared_only_near_it() {
        let pile = |cert: &mut RoundingCertificate| {
            for i in 0..4 * COMPARISONS {
                let p = Point::new(0.6 + 1e-4 * i as f64, 0.5 + 1e-17 * i as f64);
                cert.between_scanlines(p, [1, 10 + i as u64], false);
            }
        };
        let mut cert = certificate_rising(1e-3);
        pile(&mut cert);
        assert_eq!(cert.verdict(), Ok(()), "the pile alone");
        cert.between_scanlines(Point::new(0.1, 0.5 + 1e-14), [2, 3], true);
        cert.on_scanline(Point::new(0.2, 0.5 + 2e-14), true);
        assert_eq!(cert.verdict(), Ok(()), "events far from the pile, at its height");
        // Among the pile, past the limit: the certificate gives up.
        let mut cert = certificate_rising(1e-3);
        pile(&mut cert);
        cert.between_scanlines(Point::new(0.61, 0.5 + 1e-14), [2, 3], true);
        assert_eq!(cert.verdict(), Err("events in a box"));
    }

    #[test]
    fn events_out_of_order_fail() {
        let mut cert = unit_certificate();
        cert.on_scanline(Point::new(0.1, 0.5), true);
        cert.between_scanlines(Point::new(0.9, 0.4), [1, 2], true);
        assert_eq!(cert.verdict(), Err("out of order"));
    }

    #[test]
    fn a_failure_counts_only_once_a_rounded_point_is_output() {
        let mut bounds = crate::bounds::Bounds::default();
        bounds.rebuild(&polygon(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]), &Polygons::default(), false);
        let mut cert = RoundingCertificate::default();
        cert.reset(true, &bounds);
        cert.fail("a check");
        assert!(cert.holds(), "nothing rounded was output");
        cert.rounded_output();
        assert_eq!(cert.verdict(), Err("a check"));
        // Events out of their order break the sweep's decisions, not only its points.
        cert.reset(true, &bounds);
        cert.on_scanline(Point::new(0.1, 0.5), true);
        cert.between_scanlines(Point::new(0.9, 0.4), [1, 2], true);
        assert_eq!(cert.verdict(), Err("out of order"), "nothing rounded was output, but out of order");
        // Disabled, nothing is checked.
        cert.reset(false, &bounds);
        cert.fail("a check");
        cert.rounded_output();
        assert_eq!(cert.verdict(), Ok(()));
    }

    #[test]
    fn coarse_grids_need_no_certificate() {
        // In units of 1/4, coordinates up to 64 are integers below 2^9.
        let a = polygon(&[(0.0, 0.0), (64.0, 0.0), (64.0, 64.0)]);
        assert!(rounding_is_harmless(&a, &polygon(&[(0.5, 0.25), (2.0, 3.0), (1.0, 3.0)])));
        assert!(!rounding_is_harmless(&a, &polygon(&[(0.5, 0.125), (2.0, 3.0), (1.0, 3.0)])));
        assert!(!rounding_is_harmless(&a, &polygon(&[(0.1, 0.0), (2.0, 3.0), (1.0, 3.0)])));
        assert!(!rounding_is_harmless(&a, &polygon(&[(1024.0, 0.0), (2.0, 3.0), (1.0, 3.0)])));
    }

    #[test]
    fn axis_parallel_edges_need_no_certificate_at_any_coordinates() {
        let rectilinear = |x: f64, y: f64| polygon(&[(x, y), (x + 0.3, y), (x + 0.3, y + 0.7), (x + 0.1, y + 0.7)]);
        let square = polygon(&[(0.1, 0.2), (1.3, 0.2), (1.3, 1.7), (0.1, 1.7)]);
        assert!(rounding_is_harmless(&square, &polygon(&[(0.7, 0.3), (2.1, 0.3), (2.1, 0.9), (0.7, 0.9)])));
        // One slanted edge (the fourth, back to the start) is enough to need it.
        assert!(!rounding_is_harmless(&square, &rectilinear(0.55, 0.35)));
    }
}
