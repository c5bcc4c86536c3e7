//! The clean-up's walk of touching rings, turned only at the points they share.
//!
//! Most touching rings need nothing cancelled or split: holes touching their outers at vertices
//! (holes unions), lobes pinched at a point (scribble). For them the rebuild (`rebuild`: directed
//! edges sorted into rows by start point, opposite edges cancelled, every vertex walked through
//! its row) reduces to choosing, at each shared point, the way out for each way in; elsewhere a
//! ring's next edge is the only one. This does that choice with the rebuild's rule (the first
//! edge clockwise from the way back) over the few visits of each shared point, and walks the
//! same rings in the same order, or declines, so that the rebuild runs, when the rebuild would
//! find more to do: an edge run both ways (it cancels), two edges leaving or arriving at a point
//! the same way (a broken form it reports), or ways in that share a way out.

use std::cmp::Ordering;

use clip_core::Point;

use super::directions::counter_clockwise_from_east;
use super::simple_loops::split_repeats;
use super::touches::Touches;
use crate::raw_rings::RawRings;

/// Where the walk turns, for the touched rings of one output; the buffers are kept between
/// clips.
#[derive(Debug, Default)]
pub(crate) struct Turns {
    /// Per visit, the visit whose edge the walk leaves by after arriving there.
    pick: Vec<u32>,
    /// Per visit, whether its edge was walked; the walk's point ids; split scratch.
    used: Vec<bool>,
    walk: Vec<u32>,
    stack: Vec<u32>,
    slot: Vec<usize>,
    points: Vec<Point>,
    /// The ways in and out of one shared point.
    ways: Vec<Way>,
}

/// A way in to a shared point (from the point before it in its ring) or out of it (to the
/// point after), of one visit.
#[derive(Clone, Copy, Debug)]
struct Way {
    to: Point,
    visit: u32,
    out: bool,
}

/// Sorts `ways` counter-clockwise by direction from `v`; false (order unspecified) when two
/// share a direction. An insertion sort for the common two to eight ways, whose comparisons
/// meet every pair that ends adjacent, so equal directions are seen where they are compared.
fn sorted_apart(ways: &mut [Way], v: Point) -> bool {
    if ways.len() > 16 {
        ways.sort_unstable_by(|a, b| counter_clockwise_from_east(v, a.to, b.to));
        return ways.windows(2).all(|w| counter_clockwise_from_east(v, w[0].to, w[1].to) != Ordering::Equal);
    }
    for i in 1..ways.len() {
        let mut j = i;
        while j > 0 {
            match counter_clockwise_from_east(v, ways[j - 1].to, ways[j].to) {
                Ordering::Less => break,
                Ordering::Equal => return false,
                Ordering::Greater => ways.swap(j - 1, j),
            }
            j -= 1;
        }
    }
    true
}

impl Turns {
    /// Chooses the turns at the shared points of the rings marked in `rings` (touched rings whose
    /// horizontal edges need no split, sharing no point with the others). False, with nothing
    /// chosen, when the rebuild must run instead.
    pub(crate) fn plan(&mut self, raw: &RawRings, touches: &Touches, rings: &[bool]) -> bool {
        let Touches { ids, distinct: pts, shared, shared_ends, .. } = touches;
        self.pick.clear();
        self.pick.extend(0..raw.points.len() as u32);
        let mut ways = std::mem::take(&mut self.ways);
        let mut from = 0;
        for &end in shared_ends {
            let visits = &shared[from..end as usize];
            from = end as usize;
            // A point's visits are all of marked rings or none.
            if !rings[touches.ring_of(visits[0] as usize)] {
                continue;
            }
            let pv = pts[ids[visits[0] as usize] as usize];
            // The ways in and out of every visit of the point, counter-clockwise by direction.
            ways.clear();
            for &m in visits {
                let (prev, next) = touches.around(raw, m as usize);
                ways.push(Way { to: pts[ids[prev] as usize], visit: m, out: false });
                ways.push(Way { to: pts[ids[next] as usize], visit: m, out: true });
            }
            // Two ways in one direction: edges leaving or arriving the same way (the rebuild
            // reports it) or an edge run both ways (it cancels), or a way out back along a way
            // in (rare; left to the rebuild). Else each way in turns to the first way out
            // clockwise from it (the rebuild's rule), and those are one to one when ways in and
            // out alternate around the point.
            // (Neighbours around the circle without `%`: a division per way cost a sixth of this.)
            let n = ways.len();
            if !sorted_apart(&mut ways, pv)
                || ways.windows(2).any(|w| w[0].out == w[1].out)
                || ways[0].out == ways[n - 1].out
            {
                self.ways = ways;
                return false;
            }
            let mut before = ways[n - 1];
            for &way in ways.iter() {
                if !way.out {
                    self.pick[way.visit as usize] = before.visit;
                }
                before = way;
            }
        }
        self.ways = ways;
        true
    }

    /// The closed walks through the rings marked in `rings` (those [`Turns::plan`] planned) along
    /// the planned turns, in the rebuild's order (each from the first edge not yet walked), each
    /// split at the points it visits twice and handed to `emit` as points.
    pub(crate) fn walk(&mut self, raw: &RawRings, touches: &Touches, rings: &[bool], emit: &mut impl FnMut(&[Point])) {
        let Touches { ids, distinct: pts, .. } = touches;
        self.used.clear();
        self.used.resize(raw.points.len(), false);
        self.slot.clear();
        self.slot.resize(pts.len(), usize::MAX);
        let points = &mut self.points;
        for ri in (0..raw.len()).filter(|&ri| rings[ri]) {
            for start in raw.start(ri)..raw.ends[ri] {
                if self.used[start] {
                    continue;
                }
                self.walk.clear();
                let mut e = start;
                // Each step walks one edge, so the walk ends within the edge count.
                for _ in 0..raw.points.len() {
                    self.used[e] = true;
                    self.walk.push(ids[e]);
                    e = self.pick[touches.around(raw, e).1] as usize;
                    if e == start || self.used[e] {
                        break;
                    }
                }
                split_repeats(&self.walk, &mut self.slot, &mut self.stack, &mut |ring: &[u32]| {
                    points.clear();
                    points.extend(ring.iter().map(|&i| pts[i as usize]));
                    emit(points);
                });
            }
        }
    }

    /// Bytes the buffers hold (their capacity).
    pub(crate) fn held_bytes(&self) -> usize {
        use std::mem::size_of;
        4 * (self.pick.capacity() + self.walk.capacity() + self.stack.capacity())
            + self.used.capacity()
            + self.slot.capacity() * size_of::<usize>()
            + self.points.capacity() * size_of::<Point>()
            + self.ways.capacity() * size_of::<Way>()
    }
}
