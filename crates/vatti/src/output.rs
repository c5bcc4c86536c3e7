//! Output polygons built from both ends as the sweep goes (the paper's polygon nodes with their
//! L and R ends): AddLocalMin, AddLeft, AddRight, AddLocalMax and AppendPolygon.
//!
//! Each open polygon is a list of points from its *left* end (fed by the edge that has the result
//! on its right) to its *right* end, in the order that has the result on its left
//! (counter-clockwise outers, clockwise holes). Each point links only to the next: a point added
//! at the left end links to the old left end, one added at the right end is linked from the old
//! right end. So an addition writes only the end it grows from, which the repeat test has just
//! read, and the other end's point, often cold where the two ends are fed far apart, is not
//! touched. A closed ring runs from its left end to its right end and back.

use clip_core::Point;

use crate::bounds::NONE;
use crate::raw_rings::RawRings;

#[derive(Clone, Copy, Debug)]
struct OutPt {
    pt: Point,
    /// The point after this one towards the right end, `NONE` at the right end.
    next: u32,
}

/// An output polygon (the paper's polygon node).
#[derive(Clone, Copy, Debug)]
pub(crate) struct OutRec {
    /// The point at the left end (the paper's L).
    left: u32,
    /// The point at the right end (the paper's R).
    right: u32,
    /// Edge feeding the left end, `NONE` once closed.
    pub left_edge: u32,
    /// Edge feeding the right end, `NONE` once closed.
    pub right_edge: u32,
    /// True once the ring is closed and its points final.
    closed: bool,
    /// How many points the chain from `left` to `right` holds.
    len: u32,
}

/// All output polygons of one sweep.
#[derive(Debug, Default)]
pub(crate) struct OutputBuilder {
    pts: Vec<OutPt>,
    recs: Vec<OutRec>,
}

/// How many chains [`OutputBuilder::rings_into`] walks at once, from [`WALKS_FROM`] points. A
/// ring's points lie far apart in `pts` wherever many rings grow side by side (each scanline
/// feeds each of them), so where `pts` is larger than the processor's caches each step of a walk
/// waits for memory; steps of different walks do not depend on each other, and the processor
/// overlaps them.
const WALKS: usize = 8;

/// The fewest points (24 bytes each: 768 KiB, about a core's second-level cache) from which
/// [`OutputBuilder::rings_into`] walks chains [`WALKS`] at a time; below, one at a time costs
/// fewer instructions and its steps find the points in cache.
const WALKS_FROM: usize = 1 << 15;

impl OutputBuilder {
    /// Empties the builder, keeping its buffers, with room for `n` points.
    pub(crate) fn reset(&mut self, n: usize) {
        self.pts.clear();
        self.recs.clear();
        self.pts.reserve(n);
    }

    /// Bytes the buffers hold (their capacity).
    pub(crate) fn held_bytes(&self) -> usize {
        self.pts.capacity() * size_of::<OutPt>() + self.recs.capacity() * size_of::<OutRec>()
    }

    /// AddLocalMin: a new polygon holding `p`, fed by `left_edge` and `right_edge`.
    pub(crate) fn add_local_min(&mut self, left_edge: u32, right_edge: u32, p: Point) -> u32 {
        let pt = self.pts.len() as u32;
        self.pts.push(OutPt { pt: p, next: NONE });
        let rec = self.recs.len() as u32;
        self.recs.push(OutRec { left: pt, right: pt, left_edge, right_edge, closed: false, len: 1 });
        rec
    }

    #[inline]
    pub(crate) fn rec(&self, rec: u32) -> &OutRec {
        &self.recs[rec as usize]
    }

    #[inline]
    pub(crate) fn rec_mut(&mut self, rec: u32) -> &mut OutRec {
        &mut self.recs[rec as usize]
    }

    /// AddLeft / AddRight: appends `p` at the left or right end (nothing if it repeats the end).
    /// Always inlined: it runs at nearly every output point, and its callers fix `at_left`.
    #[inline(always)]
    pub(crate) fn add(&mut self, rec: u32, at_left: bool, p: Point) {
        let r = &mut self.recs[rec as usize];
        let (left, right) = (r.left, r.right);
        let end = if at_left { left } else { right };
        if self.pts[end as usize].pt == p {
            return;
        }
        let id = self.pts.len() as u32;
        r.len += 1;
        if at_left {
            r.left = id;
            self.pts.push(OutPt { pt: p, next: left });
        } else {
            r.right = id;
            self.pts[right as usize].next = id;
            self.pts.push(OutPt { pt: p, next: NONE });
        }
    }

    /// The two ends of one polygon met: it is a closed ring.
    pub(crate) fn close(&mut self, rec: u32) {
        let r = &mut self.recs[rec as usize];
        r.closed = true;
        r.left_edge = NONE;
        r.right_edge = NONE;
    }

    /// AppendPolygon: the right end of `x` met the left end of `y` (a local maximum of two
    /// different polygons). `y`'s chain is appended after `x`'s; `x` keeps its left edge and takes
    /// `y`'s right edge, which the caller re-points to `x`. `y` is left empty.
    pub(crate) fn append(&mut self, x: u32, y: u32) {
        let (rx, ry) = (self.recs[x as usize], self.recs[y as usize]);
        self.pts[rx.right as usize].next = ry.left;
        let r = &mut self.recs[x as usize];
        r.right = ry.right;
        r.right_edge = ry.right_edge;
        r.len += ry.len;
        let e = &mut self.recs[y as usize];
        e.left_edge = NONE;
        e.right_edge = NONE;
        e.left = NONE;
        e.right = NONE;
        e.len = 0;
    }

    /// Every closed ring, each in `next` order (the result on its left), stamped with the
    /// points' emission order, into `raw` (emptied first, its buffers kept).
    pub(crate) fn rings_into(&self, raw: &mut RawRings) {
        raw.clear();
        raw.stamps = self.pts.len();
        raw.points.reserve(self.pts.len());
        raw.emitted.reserve(self.pts.len());
        if self.pts.len() >= WALKS_FROM { self.walk_apart(raw) } else { self.walk_one_by_one(raw) }
    }

    /// [`OutputBuilder::rings_into`] of few points: each chain walked in turn.
    fn walk_one_by_one(&self, raw: &mut RawRings) {
        for r in self.recs.iter().filter(|r| r.closed && r.left != NONE) {
            let (start, mut p) = (raw.points.len(), r.left);
            for _ in 0..r.len {
                let here = &self.pts[p as usize];
                raw.push_point(start, here.pt, p);
                p = here.next;
            }
            raw.end_ring(start);
        }
    }

    /// [`OutputBuilder::rings_into`] of many points: the chains are copied out [`WALKS`] at a
    /// time into one buffer, then read from it in order. The buffer is not kept: held between
    /// sweeps it would add to the peak of every later step (a tenth at 10^6 output points).
    fn walk_apart(&self, raw: &mut RawRings) {
        let closed = || self.recs.iter().filter(|r| r.closed && r.left != NONE);
        let total = closed().map(|r| r.len as usize).sum();
        let mut walked = vec![(Point::new(0.0, 0.0), NONE); total];
        // Each walk: the point it reads next, where that goes in `walked`, and how many are left.
        // Walks `..busy` are under way; one that ends takes the next ring, or the last walk's
        // place when there is none.
        let mut walks = [(NONE, 0usize, 0u32); WALKS];
        let (mut rings, mut at, mut busy) = (closed(), 0, 0);
        loop {
            while busy < WALKS {
                let Some(r) = rings.next() else { break };
                walks[busy] = (r.left, at, r.len);
                at += r.len as usize;
                busy += 1;
            }
            if busy == 0 {
                break;
            }
            let mut w = 0;
            while w < busy {
                let (p, to, left) = &mut walks[w];
                let here = &self.pts[*p as usize];
                walked[*to] = (here.pt, *p);
                (*p, *to, *left) = (here.next, *to + 1, *left - 1);
                if *left == 0 {
                    busy -= 1;
                    walks[w] = walks[busy];
                } else {
                    w += 1;
                }
            }
        }
        let mut from = 0;
        for r in closed() {
            debug_assert_eq!(walked[from + r.len as usize - 1].1, r.right, "a chain's length is off");
            let start = raw.points.len();
            for &(pt, stamp) in &walked[from..from + r.len as usize] {
                raw.push_point(start, pt, stamp);
            }
            from += r.len as usize;
            raw.end_ring(start);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chains_walked_apart_give_the_rings_walked_one_by_one() {
        // Many polygons grown at both ends side by side (their points interleaved in `pts`),
        // some joined end to end, some left open; a point repeating an end is not added.
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = |n: u64| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state % n
        };
        let mut out = OutputBuilder::default();
        out.reset(0);
        let mut open: Vec<u32> = Vec::new();
        for step in 0..20_000u32 {
            let p = Point::new(f64::from(step % 97), f64::from(step));
            if open.is_empty() || next(10) == 0 {
                open.push(out.add_local_min(0, 0, p));
                continue;
            }
            let k = next(open.len() as u64) as usize;
            match next(40) {
                0 if open.len() > 1 => {
                    let y = open.swap_remove((k + 1) % open.len());
                    let x = open[k % open.len()];
                    out.append(x, y);
                }
                1 => out.close(open.swap_remove(k)),
                2 => out.add(open[k], true, out.pts[out.rec(open[k]).left as usize].pt),
                r => out.add(open[k], r % 2 == 0, p),
            }
        }
        for &r in &open[..open.len() / 2] {
            out.close(r);
        }
        let (mut apart, mut one_by_one) = (RawRings::default(), RawRings::default());
        out.walk_apart(&mut apart);
        out.walk_one_by_one(&mut one_by_one);
        assert!(apart.len() > 100, "{} rings", apart.len());
        assert_eq!(apart.points, one_by_one.points);
        assert_eq!(apart.ends, one_by_one.ends);
        assert_eq!(apart.emitted, one_by_one.emitted);
    }
}
