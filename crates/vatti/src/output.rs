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
    /// The closed rings' points copied out of their chains, ring after ring, each with its
    /// index in `pts` ([`OutputBuilder::rings_into`]'s buffer, kept between sweeps).
    walked: Vec<(Point, u32)>,
}

/// How many chains [`OutputBuilder::rings_into`] walks at once. A ring's points lie far apart
/// in `pts` wherever many rings grow side by side (each scanline feeds each of them), so each
/// step of a walk waits for memory; steps of different walks do not depend on each other, and
/// the processor overlaps them.
const WALKS: usize = 8;

impl OutputBuilder {
    /// Empties the builder, keeping its buffers, with room for `n` points.
    pub(crate) fn reset(&mut self, n: usize) {
        self.pts.clear();
        self.recs.clear();
        self.pts.reserve(n);
    }

    /// Bytes the buffers hold (their capacity).
    pub(crate) fn held_bytes(&self) -> usize {
        self.pts.capacity() * size_of::<OutPt>()
            + self.recs.capacity() * size_of::<OutRec>()
            + self.walked.capacity() * size_of::<(Point, u32)>()
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
    #[inline]
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
    /// points' emission order, into `raw` (emptied first, its buffers kept). The chains are
    /// copied out [`WALKS`] at a time, then read in order.
    pub(crate) fn rings_into(&mut self, raw: &mut RawRings) {
        raw.clear();
        raw.stamps = self.pts.len();
        raw.points.reserve(self.pts.len());
        raw.emitted.reserve(self.pts.len());
        let closed = || self.recs.iter().filter(|r| r.closed && r.left != NONE);
        let total = closed().map(|r| r.len as usize).sum();
        let mut walked = std::mem::take(&mut self.walked);
        walked.clear();
        walked.resize(total, (Point::new(0.0, 0.0), NONE));
        // Each walk: the point it reads next, where that goes in `walked`, and how many are left.
        let mut walks = [(NONE, 0usize, 0u32); WALKS];
        let (mut rings, mut at) = (closed(), 0);
        loop {
            let mut busy = false;
            for (p, to, left) in &mut walks {
                if *left == 0 {
                    let Some(r) = rings.next() else { continue };
                    (*p, *to, *left) = (r.left, at, r.len);
                    at += r.len as usize;
                }
                let here = &self.pts[*p as usize];
                walked[*to] = (here.pt, *p);
                (*p, *to, *left) = (here.next, *to + 1, *left - 1);
                busy = true;
            }
            if !busy {
                break;
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
        self.walked = walked;
    }
}
