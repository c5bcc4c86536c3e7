//! Near misses routed as the event sweep meets them: an edge that passes within a pixel (four
//! ulps of the largest coordinate) of a vertex it does not end at is split at that vertex, so
//! the two meet exactly there, as GEOS's snapping noder and this crate's vertex snapping
//! (`clip_core::snap_edges_to_vertices`) route such edges before a sweep. Layers that share
//! borders, each rounded on its own (map layers, tiles cut from them), hold vertices a fraction
//! of an ulp off the neighbour's edge they were on; swept as they are, the rounding certificate
//! fails there and the operands are swept again after a search for near pairs over all edges.
//! Routed here, the certified sweep holds where the only trouble was such near misses. It is the
//! first retry where the certificate fails (`Vatti::sweep_polygons`), not the first sweep: the
//! walks cost every certified sweep a few percent, and most hold without them.
//!
//! Why the output is still the exact arrangement of one input, the routed one: an edge is split
//! at `v` only while nothing it decided above its bottom depends on its line there
//! (`Edge::tainted`: no crossing taken or queued, no vertex met within a pixel). Routing moves
//! its swept part by under a pixel, within the thin triangle of its bottom, `v` and its old line
//! at `v`'s height. A vertex that the move takes across the edge lies in that triangle, so within
//! a pixel of the old line; every vertex event walks the table beside its vertex over every
//! non-flat edge within a pixel (`RoundingCertificate::near_miss_reach`), which either routes the
//! edge there or taints it. An edge that crosses the routed edge and not the old one leaves the
//! triangle through its side at `v`'s height, between the old line and `v`: the walk passes it
//! before the edge to route, and the edge is not routed unless that one is too. Flat edges pass
//! near a point far from it in the table: no edge is split near one
//! (`RoundingCertificate::admits_split`), and they are never split. A crossing put off because
//! one edge's top is a near miss of the other must be routed at that top, or the certificate
//! breaks.
//!
//! Property used: a vertex within a pixel of an edge of another ring, or of its own ring's far
//! edge. Exact inputs (integer grids, shared borders that match) have none, and the walks cost
//! a comparison or two per vertex.

use clip_core::Point;
use clip_core::predicates::{Orientation, orient};

use crate::bounds::NONE;
use crate::sweep::SweepLine;

/// Where a vertex lies from an edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Miss {
    /// Farther than a pixel from its line.
    Apart,
    /// On it exactly (the edge spans the vertex's height).
    Through,
    /// Within a pixel of its line and off it: `splittable` when strictly between its ends in
    /// height and farther than a pixel from both (else a split would make an edge without length
    /// or a horizontal one).
    Near { splittable: bool },
}

/// Where vertex `v` lies from the edge `a`-`b` (`a` below `b`) that spans its height, at the
/// distance `pixel`. Floating point: which vertices count as near is a choice; the split, once
/// made, is exact.
fn miss(a: Point, b: Point, v: Point, pixel: f64) -> Miss {
    let (d, w) = (b - a, v - a);
    // |d| lies between its largest coordinate `m` and `m·√2`: decided by those where they
    // decide it, else by `hypot`. Never squared: squares of coordinates near `MAX_COORDINATE`
    // overflow, and infinity is not greater than infinity (a cross product of coordinates up to
    // `MAX_COORDINATE` is finite).
    let (off, m) = (w.cross(d).abs(), d.x.abs().max(d.y.abs()));
    if off > 1.5 * pixel * m || (off > pixel * m && off > pixel * d.x.hypot(d.y)) {
        return Miss::Apart;
    }
    if orient(a, b, v) == Orientation::Collinear {
        return Miss::Through;
    }
    let far = |q: Point| (v.x - q.x).hypot(v.y - q.y) > pixel;
    Miss::Near { splittable: a.y < v.y && v.y < b.y && far(a) && far(b) }
}

/// An edge beside a vertex, as the walk leaves it.
enum Beside {
    /// Split at the vertex.
    Routed,
    /// Through the vertex exactly (not at an end): tainted.
    Through,
    /// Anything else: farther than a near miss, or near and not routable (tainted).
    Apart,
}

/// Edges looked at on each side of a vertex before routing stops for the rest of the sweep
/// (more edges within reach of one point than this: a pile-up routing would not untangle).
const WALK: usize = 8;

impl SweepLine<'_> {
    /// Routes the edges beside vertex `v` on the current scanline that pass within a pixel of
    /// it, walking the table from `from` (an edge at `v`) to its left and to its right: each is
    /// split at `v` if it can be, else tainted. `settle_now`: order a split edge among the
    /// edges through `v` at once (else it joins the scanline's settle list).
    #[inline(always)]
    pub(crate) fn route_near_misses(&mut self, v: Point, from: u32, settle_now: bool) {
        if !self.route || from == NONE {
            return;
        }
        // Most vertices have no edge within reach: their nearest neighbours' boxes show it.
        if self.may_reach(v, from, false) || self.may_reach(v, from, true) {
            self.walk_beside(v, from, settle_now);
        } else if !self.deferred.is_empty() {
            self.check_put_off(v);
        }
    }

    /// False when the nearest edge beside `v` on one side, past `v`'s own edges, lies farther
    /// than the walk's reach from it in x on the scanline, or there is none: by its box where
    /// that shows it (most neighbours), else by its x there.
    #[inline(always)]
    fn may_reach(&mut self, v: Point, from: u32, rightwards: bool) -> bool {
        let reach = self.cert.pixel_reach();
        let mut k = from;
        loop {
            k = if rightwards { self.ael.next(k) } else { self.ael.prev(k) };
            if k == NONE {
                return false;
            }
            let e = self.ael.get(k);
            let (lo, hi) = if e.bot.x < e.top.x { (e.bot.x, e.top.x) } else { (e.top.x, e.bot.x) };
            if (if rightwards { lo - v.x } else { v.x - hi }) > reach {
                return false;
            }
            if !(e.moving || e.bot == v || e.top == v) {
                return (self.ael.x_on(k, v.y) - v.x).abs() <= reach;
            }
        }
    }

    /// [`SweepLine::route_near_misses`] while routing.
    fn walk_beside(&mut self, v: Point, from: u32, settle_now: bool) {
        let Some((pixel, reach)) = self.cert.near_miss_reach() else {
            self.stop_routing();
            return;
        };
        for rightwards in [false, true] {
            let mut k = from;
            let mut looked = 0;
            // An edge between `v` and one routed through it would be crossed by the routed one
            // (it lies across the routed edge's thin triangle): past an edge not routed and not
            // through `v`, none is routed on this side.
            let mut blocked = false;
            loop {
                k = if rightwards { self.ael.next(k) } else { self.ael.prev(k) };
                if k == NONE {
                    break;
                }
                let e = self.ael.get(k);
                if e.bot == v || e.top == v {
                    continue;
                }
                if e.moving {
                    blocked = true;
                    continue;
                }
                // The table is in order of x on the scanline: past the first edge beyond reach,
                // every edge is. Its box tells most of them without computing its x there.
                let (lo, hi) = if e.bot.x < e.top.x { (e.bot.x, e.top.x) } else { (e.top.x, e.bot.x) };
                if (if rightwards { lo - v.x } else { v.x - hi }) > reach || (self.ael.x_on(k, v.y) - v.x).abs() > reach
                {
                    break;
                }
                looked += 1;
                if looked > WALK {
                    self.stop_routing();
                    return;
                }
                match self.route_edge(k, v, pixel, !blocked) {
                    Beside::Routed => self.routed.push(k),
                    Beside::Through => {}
                    Beside::Apart => blocked = true,
                }
            }
        }
        // Their output only once every edge through `v` is routed: a point is checked against
        // the edges beside it, and two coincident edges are routed one after the other.
        for i in 0..self.routed.len() {
            let k = self.routed[i];
            if self.ael.get(k).outrec != NONE {
                self.add_point(k, v);
            }
            if settle_now {
                self.settle(k);
            } else {
                self.settle_later(k);
            }
        }
        self.routed.clear();
        self.check_put_off(v);
    }

    /// Splits active edge `k` at vertex `v` (on the current scanline) if `v` is a near miss of
    /// it, `split` allows it and it can be routed; taints it if `v` lies within a pixel of its
    /// line otherwise.
    fn route_edge(&mut self, k: u32, v: Point, pixel: f64, split: bool) -> Beside {
        let e = self.ael.get(k);
        let (a, b) = (e.bot, e.top);
        let routable = match miss(a, b, v, pixel) {
            Miss::Apart => return Beside::Apart,
            Miss::Through => {
                self.ael.get_mut(k).tainted = true;
                return Beside::Through;
            }
            Miss::Near { splittable } => splittable && split && !e.tainted && self.cert.admits_split(a, v, b),
        };
        if !routable {
            self.ael.get_mut(k).tainted = true;
            return Beside::Apart;
        }
        let e = self.ael.get_mut(k);
        e.set_ends(v, b);
        e.curr_x = v.x;
        e.curr_y = v.y;
        e.next_y = f64::NAN;
        self.ael.segment_changed(k);
        self.deferred.retain(|&(id, p)| !(id == k && p == v));
        Beside::Routed
    }

    /// In `test_pair`, for adjacent edges `l` and `r` that cross before either top: true (and
    /// the crossing put off) when the top of one, above scanline `y`, is a near miss of the
    /// other, which can be routed through it when the sweep reaches that top. Then they meet
    /// there and cross nowhere.
    pub(crate) fn put_off_near_top(&mut self, l: u32, r: u32, y: f64) -> bool {
        let Some((pixel, _)) = self.cert.near_miss_reach() else { return false };
        let (el, er) = (self.ael.get(l), self.ael.get(r));
        for (edge, e, t) in [(l, el, er.top), (r, er, el.top)] {
            let (a, b) = (e.bot, e.top);
            if t.y > y
                && !e.tainted
                && miss(a, b, t, pixel) == (Miss::Near { splittable: true })
                && self.cert.admits_split(a, t, b)
            {
                self.deferred.push((edge, t));
                return true;
            }
        }
        false
    }

    /// At vertex `v`, every crossing put off for it must have been routed: else the sweep kept
    /// two edges in an order no input has.
    fn check_put_off(&mut self, v: Point) {
        if self.deferred.iter().any(|&(_, p)| p == v) {
            self.deferred.retain(|&(_, p)| p != v);
            self.cert.break_off("a near miss put off and not routed");
        }
    }

    /// No more routing in this sweep; a crossing put off and not routed yet never will be.
    fn stop_routing(&mut self) {
        self.route = false;
        if !self.deferred.is_empty() {
            self.deferred.clear();
            self.cert.break_off("a near miss put off and not routed");
        }
    }
}

#[cfg(test)]
mod tests {
    use clip_core::{BoolOp, FillRule, Point, PolygonClipper, Polygons, Rect, Ring, WindowKind};
    use clip_oracle::polygon::{OutputRules, REGION_TOLERANCE, check_polygon_result, check_valid_output};
    use clip_testkit::workload::polygon_case;

    use crate::{FixedSweep, Operands, Sweep, Vatti, swept_operands};

    fn polygon(points: &[(f64, f64)]) -> Polygons {
        Polygons::from(Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect()))
    }

    /// Whether `a op b`, swept certified by `sweep` (the event sweep routing), is certified,
    /// and its output when it is.
    fn swept(sweep: Sweep, a: &Polygons, b: &Polygons, op: BoolOp) -> Option<Polygons> {
        let (a, b) = swept_operands(a, b, sweep, true);
        let operands = if sweep == Sweep::Events { Operands::FloatRouted } else { Operands::Float };
        Vatti::sweep_clean(&a, &b, op, FillRule::NonZero, sweep, operands)
    }

    /// A triangle's vertex an ulp beside a square's edge (its edges stay outside) and an ulp
    /// inside it (its edges cross the square's edge a fraction of an ulp from the vertex: the
    /// crossing below it is put off until the vertex). The event sweep routes the square's edge
    /// through the vertex and its certificate holds; the paper's sweep, which does not route,
    /// fails where the vertex is output, and falls back. Either way the output passes the
    /// oracle.
    #[test]
    fn a_vertex_an_ulp_off_an_edge_is_routed_through_it() {
        let square = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0).to_ring());
        // A second triangle across the square's top: crossings f64 rounds, so that a failed
        // check matters (with nothing rounded, the exact output needs no certificate).
        let across = Ring::new([(0.3, 0.9), (0.71, 1.33), (0.17, 1.1)].map(|(x, y)| Point::new(x, y)).to_vec());
        for off in [f64::EPSILON, -f64::EPSILON / 2.0] {
            let mut triangle = polygon(&[(1.0 + off, 0.5), (2.0, 0.0), (2.0, 1.0)]);
            triangle.rings.push(across.clone());
            let mut fell_back = 0;
            for op in BoolOp::ALL {
                let routed = swept(Sweep::Events, &square, &triangle, op)
                    .unwrap_or_else(|| panic!("{off:e} {op:?}: the event sweep's certificate failed"));
                check_valid_output(&routed).unwrap_or_else(|e| panic!("{off:e} {op:?}: {e}"));
                fell_back += usize::from(swept(Sweep::Scanbeam, &square, &triangle, op).is_none());
                let rules = OutputRules::conventional(REGION_TOLERANCE);
                for sweep in [Sweep::Events, Sweep::Scanbeam] {
                    let out =
                        FixedSweep(sweep).clip(&square, &triangle, op, FillRule::NonZero).expect("valid operands");
                    check_polygon_result(&square, &triangle, op, FillRule::NonZero, &out, &rules)
                        .unwrap_or_else(|e| panic!("{off:e} {op:?} {sweep:?}: {e}"));
                }
            }
            assert!(fell_back > 0, "{off:e}: the paper's sweep was certified on every operation");
        }
    }

    /// Soundness where near misses abound: wherever the event sweep's certificate holds with
    /// its routing, the output is valid, and it holds on more cases than the paper's sweep.
    #[test]
    fn routed_near_misses_leave_valid_output_on_nearly_coincident_edges() {
        let (mut events, mut scanbeam) = (0, 0);
        for index in 0..40 {
            let case = polygon_case("near-coincident", 11, index, WindowKind::Any).expect("a polygon workload");
            for op in BoolOp::ALL {
                if let Some(out) = swept(Sweep::Events, &case.subject, &case.clip, op) {
                    events += 1;
                    check_valid_output(&out).unwrap_or_else(|e| panic!("case {index} {op:?}: {e}"));
                }
                scanbeam += usize::from(swept(Sweep::Scanbeam, &case.subject, &case.clip, op).is_some());
            }
        }
        assert!(events > scanbeam, "routing certified {events} clips, the paper's sweep {scanbeam}");
    }
}
