//! Horizontal edges (the paper's Extensions): vertex classes ignore them, and an edge reaching
//! one slides along the scanline to its far end, crossing the edges on the way.

use clip_core::Point;
use clip_core::predicates::Orientation;
use clip_core::predicates::orient;

use crate::bounds::NONE;
use crate::sweep::{Slide, SweepLine};

impl SweepLine<'_> {
    /// Slides `s.edge` along the scanline `y` from `s.from_x` to `s.to_x`, crossing every edge
    /// met on the way (each crossing at the other edge's x on the scanline). At the far end it
    /// passes edges through that point that head left of it (moving right) or right of it
    /// (moving left), decided exactly. Each step moves one place in one direction, so at most
    /// the table's length steps are taken.
    pub(crate) fn slide(&mut self, s: Slide, y: f64) {
        let (mut lo, mut hi) = (s.from_x.min(s.to_x), s.from_x.max(s.to_x));
        let rightwards = s.to_x > s.from_x;
        let end = Point::new(s.to_x, y);
        let top = self.ael.get(s.edge).top;
        for _ in 0..self.ael.len() {
            let k = if rightwards { self.ael.next(s.edge) } else { self.ael.prev(s.edge) };
            if k == NONE {
                break;
            }
            match self.passes(k, end, top, rightwards) {
                Passing::Passes => {}
                Passing::Stops => break,
                Passing::Along => {
                    let (l, r) = if rightwards { (s.edge, k) } else { (k, s.edge) };
                    self.order_coincident(l, r, end);
                    break;
                }
            }
            let xk = self.ael.x_on(k, y);
            // k's x on the scanline is computed unless the crossing is exact (see `passed_at`):
            // other edges through the exact crossing lie within rounding of a rounded one, and
            // take it too.
            let (p, rounded) = self.ael.get(k).passed_at(xk, y, lo, hi, [s.from_x, s.to_x]);
            self.certify_passed(k, xk, p);
            self.rounded_crossing = rounded;
            self.crossing_pair = (s.edge, k);
            let left = if rightwards { s.edge } else { k };
            self.taint(k);
            self.cross(left, p);
            self.ael.recheck(self.ael.prev(left));
            self.rounded_crossing = false;
            self.crossing_pair = (NONE, NONE);
            // The crossings come in order along the horizontal even where two edges' rounded x
            // on the scanline are an ulp out of their order.
            if rightwards {
                lo = p.x;
            } else {
                hi = p.x;
            }
        }
        let e = self.ael.get_mut(s.edge);
        e.curr_x = s.to_x;
        e.curr_y = y;
    }

    /// Whether an edge sliding towards `end` (and heading to `top` from there) must pass `k`.
    /// k's x on the scanline is computed, off by up to a few ulps of its ends' magnitude, which
    /// far from `end` can be a long way: within that of `end` its side is decided exactly, as
    /// the edges entering the table are placed (a fuzz input's edge from x = -2.9 came out 9e-17
    /// right of a horizontal's end it passes 3e-16 left of, and the crossing was missed). The x
    /// of an edge ending here or sliding is an exact input coordinate.
    fn passes(&mut self, k: u32, end: Point, top: Point, rightwards: bool) -> Passing {
        let x = self.ael.x_on(k, end.y);
        let e = self.ael.get(k);
        let exact_x = e.ends_by(end.y) || e.moving;
        if x != end.x && (exact_x || e.clearly_off(x, end)) {
            return Passing::when((x < end.x) == rightwards);
        }
        if exact_x {
            return Passing::Stops;
        }
        match e.side_of(end) {
            // `end` right of k: k is left of the end point.
            Orientation::Clockwise => Passing::when(rightwards),
            Orientation::CounterClockwise => Passing::when(!rightwards),
            Orientation::Collinear => match orient(end, top, e.top) {
                Orientation::Collinear => Passing::Along,
                turn => Passing::when(
                    turn == if rightwards { Orientation::CounterClockwise } else { Orientation::Clockwise },
                ),
            },
        }
    }
}

/// What a sliding edge does at an active edge it meets.
enum Passing {
    Passes,
    Stops,
    /// It stops: the edge goes on from the slide's end along the line the sliding edge takes.
    Along,
}

impl Passing {
    fn when(passes: bool) -> Passing {
        if passes { Passing::Passes } else { Passing::Stops }
    }
}
