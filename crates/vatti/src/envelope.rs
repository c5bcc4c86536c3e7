//! The envelope pre-filter (after GEOS's overlay): ring stretches that cannot reach a box are
//! replaced by short paths around it, so they never enter the sweep, while every winding number
//! inside the box stays what it was.
//!
//! A stretch of edges whose bounding box misses the closed box `E` is replaced by the path
//! `p -> clamp(p) -> along the border of E -> clamp(q) -> q` (`p`, `q` its ends, `clamp` the
//! nearest point of `E`: exact, and the segment to it stays outside E's interior). The loop of old
//! stretch and reversed new path avoids E's interior, so it winds the same number of times around
//! every point of it; that number (from Sunday's crossing rule, exact) is added back as loops of
//! E's border. Nothing is rounded: every new vertex copies an input coordinate.

use std::borrow::Cow;

use clip_core::predicates::{Orientation, orient};
use clip_core::{BoolOp, FillRule, MAX_COORDINATE, MIN_COORDINATE, Point, Polygons, Rect, Ring};

use crate::edge_blocks::{EdgeBlocks, EdgeRun};

/// A stretch of a ring, in walk order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Stretch {
    /// Edge `i` (vertex `i` to vertex `i + 1`) may reach the box: it stays.
    Kept(usize),
    /// Edges `first..end` all miss the box; `crossings` is their signed count of crossings of
    /// the ray from the box's centre to the right (Sunday's rule).
    Missed { first: usize, end: usize, crossings: i32 },
}

/// A box to cut to, with a point strictly inside it (the winding reference).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Envelope {
    b: Rect,
    c: Point,
}

impl Envelope {
    /// The envelope of box `b`, or `None` when `b` has no interior point to measure windings at
    /// (empty, zero width or height, or too thin for its midpoint to fall strictly inside).
    pub(crate) fn new(b: Rect) -> Option<Envelope> {
        let c = Point::new(b.min.x + 0.5 * (b.max.x - b.min.x), b.min.y + 0.5 * (b.max.y - b.min.y));
        (c.x > b.min.x && c.x < b.max.x && c.y > b.min.y && c.y < b.max.y).then_some(Envelope { b, c })
    }

    /// The box.
    #[inline]
    pub(crate) fn rect(&self) -> Rect {
        self.b
    }

    /// The point strictly inside the box that windings are measured at.
    #[inline]
    pub(crate) fn center(&self) -> Point {
        self.c
    }

    /// True when box `r` has no point in common with the closed box.
    #[inline]
    fn misses(&self, r: &Rect) -> bool {
        r.max.x < self.b.min.x || r.min.x > self.b.max.x || r.max.y < self.b.min.y || r.min.y > self.b.max.y
    }

    #[inline]
    fn edge_misses(&self, a: Point, b: Point) -> bool {
        self.misses(&Rect::from_points(a, b))
    }

    /// Signed crossings of the rightward ray from the centre by a path from `s` to `e` whose
    /// bounding box (left edge `min_x`) misses the box. Such a path reaches the ray's height only
    /// left or right of the box; on the right its crossings telescope to where it starts and ends.
    #[inline]
    fn missed_crossings(&self, s: Point, e: Point, min_x: f64) -> i32 {
        if min_x > self.c.x { i32::from(e.y > self.c.y) - i32::from(s.y > self.c.y) } else { 0 }
    }

    /// Appends `stretch`, merging it into a directly preceding missed stretch.
    #[inline]
    fn push(out: &mut Vec<Stretch>, stretch: Stretch) {
        if let (Some(Stretch::Missed { end, crossings, .. }), Stretch::Missed { first, end: e, crossings: c }) =
            (out.last_mut(), stretch)
            && *end == first
        {
            *end = e;
            *crossings += c;
            return;
        }
        out.push(stretch);
    }

    /// Edge `i` of ring `pts`, kept or missed.
    #[inline]
    pub(crate) fn push_edge(&self, pts: &[Point], i: usize, out: &mut Vec<Stretch>) {
        let (a, b) = (pts[i], pts[(i + 1) % pts.len()]);
        if self.edge_misses(a, b) {
            Envelope::push(
                out,
                Stretch::Missed { first: i, end: i + 1, crossings: self.missed_crossings(a, b, a.x.min(b.x)) },
            );
        } else {
            out.push(Stretch::Kept(i));
        }
    }

    /// The stretches of ring `pts` as [`Envelope::push_edge`] gives them edge by edge (missed
    /// stretches merged), found through the ring's edge `blocks` without visiting every edge.
    pub(crate) fn push_blocks(&self, pts: &[Point], blocks: &EdgeBlocks, out: &mut Vec<Stretch>) {
        let n = pts.len();
        blocks.walk(n, &|b| self.misses(b), &mut |run| match run {
            EdgeRun::Missed { first, end, bounds } => {
                let crossings = self.missed_crossings(pts[first], pts[end % n], bounds.min.x);
                Envelope::push(out, Stretch::Missed { first, end, crossings });
            }
            EdgeRun::Near(e) => self.push_edge(pts, e, out),
        });
    }

    /// True when some edge of the ring misses the box.
    fn misses_some_edge(&self, pts: &[Point]) -> bool {
        let n = pts.len();
        (0..n).any(|i| self.edge_misses(pts[i], pts[(i + 1) % n]))
    }

    /// The nearest point of the box to `p`: on its border when `p` is outside.
    #[inline]
    fn clamp(&self, p: Point) -> Point {
        Point::new(p.x.clamp(self.b.min.x, self.b.max.x), p.y.clamp(self.b.min.y, self.b.max.y))
    }

    /// The corner where side `k` starts, sides counter-clockwise from the bottom.
    fn corner(&self, k: u8) -> Point {
        let (lo, hi) = (self.b.min, self.b.max);
        [lo, Point::new(hi.x, lo.y), hi, Point::new(lo.x, hi.y)][usize::from(k)]
    }

    /// Side (0 bottom, 1 right, 2 top, 3 left; a corner belongs to the side it starts) and
    /// position along it, increasing counter-clockwise, of a point on the border.
    fn place(&self, p: Point) -> (u8, f64) {
        let (lo, hi) = (self.b.min, self.b.max);
        if p.y == lo.y && p.x < hi.x {
            (0, p.x)
        } else if p.x == hi.x && p.y < hi.y {
            (1, p.y)
        } else if p.y == hi.y && p.x > lo.x {
            (2, -p.x)
        } else {
            (3, -p.y)
        }
    }

    /// The corners passed going along the border from `from` to `to` the way that passes fewer
    /// (counter-clockwise on a tie). A path the other way round would wind once more around the
    /// box, which the caller's border loops take back: either keeps every winding inside it, but
    /// a ring whose missed stretches each went all the way round (a comb's gaps walked right to
    /// left, below a box over its teeth) gave the sweep a full border of edges per stretch, all
    /// on the same four lines.
    fn nearer_corners_between(&self, from: Point, to: Point, out: &mut Vec<Point>) {
        let start = out.len();
        self.corners_between(from, to, out);
        if out.len() - start <= 2 {
            return;
        }
        out.truncate(start);
        // Clockwise: the corners passed counter-clockwise from `to` back to `from`, reversed,
        // or none on one side.
        self.corners_between(to, from, out);
        out[start..].reverse();
    }

    /// The corners passed going counter-clockwise along the border from `from` to `to`.
    pub(crate) fn corners_between(&self, from: Point, to: Point, out: &mut Vec<Point>) {
        let ((mut k, kp), (sq, kq)) = (self.place(from), self.place(to));
        if k == sq && kq >= kp {
            return;
        }
        loop {
            k = (k + 1) % 4;
            out.push(self.corner(k));
            if k == sq {
                break;
            }
        }
    }

    /// The ring with its missed stretches replaced by paths around the box, into `out`; returns
    /// how many times the replaced loops wound around the box (to be added back).
    fn rebuild_ring(&self, pts: &[Point], stretches: &[Stretch], out: &mut Vec<Point>, path: &mut Vec<Point>) -> i32 {
        let Some(start) = stretches.iter().position(|s| matches!(s, Stretch::Kept(_))) else {
            // Nothing reaches the box: the whole ring is one loop around it (or not).
            return stretches
                .iter()
                .map(|s| if let Stretch::Missed { crossings, .. } = s { *crossings } else { 0 })
                .sum();
        };
        let n = pts.len();
        let mut wound = 0;
        let mut run: Option<(usize, usize, i32)> = None;
        let k = stretches.len();
        for j in 0..=k {
            let s = stretches[(start + j) % k];
            match s {
                Stretch::Missed { first, end, crossings } => {
                    run = Some(match run {
                        Some((f, _, c)) => (f, end, c + crossings),
                        None => (first, end, crossings),
                    });
                }
                Stretch::Kept(i) => {
                    if let Some((first, end, crossings)) = run.take() {
                        wound += self.replace(pts[first], pts[end % n], crossings, out, path);
                    }
                    if j < k {
                        out.push(pts[i]);
                    }
                }
            }
        }
        wound
    }

    /// Emits `p`, then the path around the box to `q` (`q` itself comes with the next kept
    /// edge); returns the winding of the old stretch (`crossings`) with the new path reversed.
    fn replace(&self, p: Point, q: Point, crossings: i32, out: &mut Vec<Point>, path: &mut Vec<Point>) -> i32 {
        let (pc, qc) = (self.clamp(p), self.clamp(q));
        path.clear();
        path.extend([p, pc]);
        self.nearer_corners_between(pc, qc, path);
        path.push(qc);
        out.extend_from_slice(path);
        path.push(q);
        // The closing loop: q back along the path to p.
        let back: i32 = path.windows(2).map(|w| sunday(w[1], w[0], self.c)).sum();
        crossings + back
    }

    /// `count` loops of the border, counter-clockwise when positive.
    pub(crate) fn border_loops(&self, count: i32, rings: &mut Vec<Ring>) {
        let ccw: Vec<Point> = (0..4).map(|k| self.corner(k)).collect();
        let ring = if count > 0 { Ring::new(ccw) } else { Ring::new(ccw).reversed() };
        rings.extend(std::iter::repeat_n(ring, count.unsigned_abs() as usize));
    }
}

/// Sunday's signed crossing of edge `a -> b` with the rightward ray from `c` (exact).
#[inline]
pub(crate) fn sunday(a: Point, b: Point, c: Point) -> i32 {
    if a.y <= c.y {
        i32::from(b.y > c.y && orient(a, b, c) == Orientation::CounterClockwise)
    } else if b.y <= c.y && orient(a, b, c) == Orientation::Clockwise {
        -1
    } else {
        0
    }
}

/// `polygons` cut to box `b`: the same winding number at every point strictly inside `b`, with
/// the edges that miss `b` gone. `None` when nothing would change (or `b` has no interior).
/// `blocks`, one per ring, find the edges that reach `b` without visiting each.
pub(crate) fn cut(polygons: &Polygons, b: Rect, blocks: Option<&[EdgeBlocks]>) -> Option<Polygons> {
    let env = Envelope::new(b)?;
    if blocks.is_none() && !polygons.rings.iter().any(|r| env.misses_some_edge(&r.points)) {
        return None;
    }
    let mut stretches = Vec::with_capacity(polygons.rings.iter().map(|r| r.points.len()).sum());
    let mut ends = Vec::with_capacity(polygons.rings.len());
    for (k, ring) in polygons.rings.iter().enumerate() {
        match blocks {
            Some(blocks) => env.push_blocks(&ring.points, &blocks[k], &mut stretches),
            None => (0..ring.points.len()).for_each(|i| env.push_edge(&ring.points, i, &mut stretches)),
        }
        ends.push(stretches.len());
    }
    if stretches.iter().all(|s| matches!(s, Stretch::Kept(_))) {
        return None;
    }
    let (mut rings, mut path, mut wound, mut from) = (Vec::new(), Vec::new(), 0, 0);
    for (ring, &to) in polygons.rings.iter().zip(&ends) {
        let own = &stretches[from..to];
        from = to;
        if own.iter().all(|s| matches!(s, Stretch::Kept(_))) {
            rings.push(ring.clone());
            continue;
        }
        let mut pts = Vec::with_capacity(ring.points.len() + 4);
        wound += env.rebuild_ring(&ring.points, own, &mut pts, &mut path);
        if !pts.is_empty() {
            rings.push(Ring { points: pts });
        }
    }
    env.border_loops(wound, &mut rings);
    Some(Polygons::new(rings))
}

/// Box `b` grown by an eighth of its extent on every side, so paths along its border run
/// clear of the operand whose box it is (on that operand's edges, rounded crossings a few ulps
/// off them would make slivers in the output); `None` when the grown corners leave the valid
/// coordinate range.
pub(crate) fn grown(b: Rect) -> Option<Rect> {
    let m = 0.125 * b.extent();
    let g = Rect::new(b.min.x - m, b.min.y - m, b.max.x + m, b.max.y + m);
    let valid = |v: f64| v.abs() <= MAX_COORDINATE && (v == 0.0 || v.abs() >= MIN_COORDINATE);
    [g.min.x, g.min.y, g.max.x, g.max.y].into_iter().all(valid).then_some(g)
}

/// The operands with what cannot reach the result's box cut away: for ∩ the subject to the
/// clip's (grown) box, then the clip to the cut subject's; for − the clip to the subject's box
/// (the subject is zero outside it). ∪ and ⊕ keep everything (outside the other operand's box the
/// result is an operand itself, which still needs the sweep to come out as simple rings).
/// When no clip edge reaches the box, the clip is all or nothing over the subject, and the
/// subject alone is swept (as its union with nothing) or nothing is. `clip_blocks` are the clip's
/// edge blocks when it was prepared.
pub(crate) fn prefilter<'a>(
    subject: &'a Polygons,
    clip: &'a Polygons,
    clip_bounds: Rect,
    clip_blocks: Option<&[EdgeBlocks]>,
    op: BoolOp,
    fill: FillRule,
) -> (Cow<'a, Polygons>, Cow<'a, Polygons>, BoolOp) {
    let owned = |cut: Option<Polygons>, whole: &'a Polygons| cut.map_or(Cow::Borrowed(whole), Cow::Owned);
    let cut_to = |p: &Polygons, b: Rect, blocks| {
        grown(b).and_then(|g| cut(p, g, blocks).map(|c| (uniform_winding(&c, g).map(|w| fill.is_inside(w)), c)))
    };
    let nothing = || Cow::Owned(Polygons::default());
    match op {
        BoolOp::Intersection => {
            let a = match cut_to(subject, clip_bounds, None) {
                Some((Some(true), _)) => return (Cow::Borrowed(clip), nothing(), BoolOp::Union),
                Some((Some(false), _)) => return (nothing(), nothing(), BoolOp::Union),
                other => owned(other.map(|c| c.1), subject),
            };
            match cut_to(clip, a.bounds(), clip_blocks) {
                Some((Some(true), _)) => (a, nothing(), BoolOp::Union),
                Some((Some(false), _)) => (nothing(), nothing(), BoolOp::Union),
                other => (a, owned(other.map(|c| c.1), clip), op),
            }
        }
        BoolOp::Difference => match cut_to(clip, subject.bounds(), clip_blocks) {
            Some((Some(true), _)) => (nothing(), nothing(), BoolOp::Union),
            Some((Some(false), _)) => (Cow::Borrowed(subject), nothing(), BoolOp::Union),
            other => (Cow::Borrowed(subject), owned(other.map(|c| c.1), clip), op),
        },
        BoolOp::Union | BoolOp::Xor => (Cow::Borrowed(subject), Cow::Borrowed(clip), op),
    }
}

/// The winding number over the whole of box `g` when `cut` (an operand cut to `g`) is nothing
/// but loops of its border.
fn uniform_winding(cut: &Polygons, g: Rect) -> Option<i32> {
    let corner = |p: &Point| (p.x == g.min.x || p.x == g.max.x) && (p.y == g.min.y || p.y == g.max.y);
    let loops = cut.rings.iter().all(|r| r.points.len() == 4 && r.points.iter().all(corner));
    loops.then(|| cut.rings.iter().map(|r| if r.signed_area() > 0.0 { 1 } else { -1 }).sum())
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::winding_number;

    fn ring(pts: &[(f64, f64)]) -> Ring {
        Ring::new(pts.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    /// Windings agree at a lattice of points strictly inside the box (none on an edge).
    fn same_inside(a: &Polygons, b: &Polygons, r: Rect) {
        for i in 1..40 {
            for j in 1..40 {
                let p = Point::new(
                    r.min.x + (r.max.x - r.min.x) * (f64::from(i) + 0.37) / 40.0,
                    r.min.y + (r.max.y - r.min.y) * (f64::from(j) + 0.61) / 40.0,
                );
                if p.x < r.max.x && p.y < r.max.y {
                    assert_eq!(winding_number(p, a), winding_number(p, b), "at {p:?}");
                }
            }
        }
    }

    #[test]
    fn a_spiral_around_the_box_keeps_its_two_windings() {
        // A ring winding twice around the box [4,6]², far from it, then one edge through it.
        let spiral = Polygons::from(ring(&[
            (0.0, 0.0),
            (10.0, 0.0),
            (10.0, 10.0),
            (1.0, 10.0),
            (1.0, 1.0),
            (9.0, 1.0),
            (9.0, 9.0),
            (2.0, 9.0),
            (5.0, 5.5),
            (2.0, 2.0),
            (0.0, 2.0),
        ]));
        let b = Rect::new(4.0, 4.0, 6.0, 6.0);
        let cut = cut(&spiral, b, None).expect("most edges miss the box");
        assert!(cut.vertex_count() < 20);
        same_inside(&spiral, &cut, b);
    }

    #[test]
    fn a_ring_that_misses_the_box_becomes_border_loops_or_nothing() {
        let around = Polygons::from(ring(&[(0.0, 0.0), (10.0, 0.0), (10.0, 10.0), (0.0, 10.0)]));
        let b = Rect::new(4.0, 4.0, 6.0, 6.0);
        let cut_around = cut(&around, b, None).unwrap();
        assert_eq!(cut_around.rings.len(), 1);
        assert_eq!(cut_around.signed_area(), 4.0);
        let beside = Polygons::from(ring(&[(20.0, 0.0), (30.0, 0.0), (30.0, 10.0)]));
        assert!(cut(&beside, b, None).unwrap().rings.is_empty());
        // All edges touch: nothing to do.
        let inside = Polygons::from(ring(&[(4.0, 4.0), (7.0, 5.0), (5.0, 7.0)]));
        assert!(cut(&inside, b, None).is_none());
        // No interior: no filtering.
        assert!(cut(&around, Rect::new(4.0, 4.0, 4.0, 6.0), None).is_none());
    }

    #[test]
    fn blocks_find_the_same_stretches_as_the_edge_walk() {
        let pts: Vec<Point> = (0..500)
            .map(|i| {
                let a = f64::from(i) * std::f64::consts::TAU / 500.0;
                let r = if i % 2 == 0 { 10.0 } else { 3.0 + f64::from(i % 7) };
                Point::new(r * a.cos(), r * a.sin())
            })
            .collect();
        for b in [Rect::new(-1.0, -1.0, 1.0, 1.0), Rect::new(2.0, -1.0, 9.0, 4.0), Rect::new(-20.0, 5.0, 20.0, 6.0)] {
            let env = Envelope::new(b).unwrap();
            let mut walked = Vec::new();
            (0..pts.len()).for_each(|i| env.push_edge(&pts, i, &mut walked));
            let mut blocked = Vec::new();
            env.push_blocks(&pts, &EdgeBlocks::new(&pts), &mut blocked);
            assert_eq!(walked, blocked);
        }
    }
}
