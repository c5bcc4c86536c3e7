//! Splicing for ∪ and ⊕ (and − of a big subject): an operand in conventional form is swept only
//! inside the other operand's grown box, and its chains outside that box, which the result keeps
//! unchanged, are joined back to the swept rings.
//!
//! Let `E` be the near operand's box grown, `F` the far operand in conventional form (simple
//! rings, windings 0 or 1, as the sweep outputs them). Outside `E` the near operand winds zero,
//! so there the result is `F` itself (`F ∪ 0`, `F ⊕ 0`, `F − 0`) and its boundary is `F`'s. Inside
//! `E` the result is that of the local sweep of the near operand with `F` cut to `E` (`F`'s edges
//! clipped at `E`'s border, joined along it, loops of the border added so every winding number
//! inside `E` is `F`'s). The result's boundary is the local result's without its edges along the
//! border, plus `F`'s chains outside `E`, joined where `F` crosses the border. Each crossing is
//! found exactly (orientation tests with `E`'s corners); its point is rounded but never output:
//! the edge it lies on is restored. Anything degenerate (a vertex on the border, an edge through a
//! corner, two crossings at one point, a local result that does not meet the border as `F` does)
//! gives `None`, and the caller sweeps everything.

use std::collections::HashMap;

use clip_core::predicates::{Orientation, on_segment, orient, segment_intersection};
use clip_core::{
    BoolOp, CellIndex, FillRule, MIN_COORDINATE, Point, Polygons, Rect, Ring, Segment, SegmentIntersection,
};

use crate::edge_blocks::EdgeBlocks;
use crate::envelope::{Envelope, Stretch, grown, sunday};

/// An operand in conventional form (outers counter-clockwise, holes clockwise, nothing crossing),
/// with edge blocks over its rings when it was prepared.
#[derive(Clone, Copy)]
pub(crate) struct Far<'a> {
    pub(crate) rings: &'a Polygons,
    pub(crate) blocks: Option<&'a [EdgeBlocks]>,
}

/// Where a point is against the open box: strictly inside, strictly outside, or on its border.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Place {
    Inside,
    Outside,
    Border,
}

/// The far operand's boundary outside the box from one exit to the next entry: vertices
/// `first..first + count` (cyclic) of ring `ring`, leaving the box at `exit`, entering at `entry`.
struct Chain {
    ring: usize,
    first: usize,
    count: usize,
    exit: Point,
    entry: Point,
    /// Signed crossings of the centre's ray by `exit`, the vertices, `entry`.
    crossings: i32,
}

/// A stretch of a swept ring strictly inside the box, between the entry of chain `after` (which
/// it follows) and the exit of chain `next`; `from..to` index its vertices in the run buffer,
/// the two crossing points left out.
#[derive(Clone, Copy)]
struct Run {
    from: usize,
    to: usize,
    next: usize,
    source: usize,
}

/// `near op far` (∪ or ⊕ for either role, − when the far operand is the subject), or `None`
/// when the splice does not apply and everything must be swept. `far_is_subject` gives the
/// roles; `near` must be valid. `sweep(a, b, op)` is the clean sweep of `a op b`.
pub(crate) fn splice(
    near: &Polygons,
    far: Far<'_>,
    far_is_subject: bool,
    op: BoolOp,
    fill: FillRule,
    sweep: impl FnOnce(&Polygons, &Polygons, BoolOp) -> Polygons,
) -> Option<Polygons> {
    let passes = match op {
        BoolOp::Union | BoolOp::Xor => true,
        BoolOp::Difference => far_is_subject,
        BoolOp::Intersection => false,
    };
    if !passes || near.rings.is_empty() {
        return None;
    }
    let env = Envelope::new(grown(near.bounds())?)?;
    let cut = Cut::new(far, &env)?;
    if cut.chains.is_empty() && cut.far_rings.is_empty() {
        return None;
    }
    // The local far operand reads as windings 0 and 1; under negative fill those must be -1.
    let mut local = Polygons::new(cut.local);
    if fill == FillRule::Negative {
        local.rings.iter_mut().for_each(|r| *r = r.reversed());
    }
    let swept = if far_is_subject { sweep(&local, near, op) } else { sweep(near, &local, op) };
    join(&env, far.rings, &cut.chains, &cut.far_rings, cut.far_winding, &swept)
}

/// The far operand cut to the box: the local rings to sweep, the chains outside to splice back,
/// the rings wholly outside and their winding around the box.
struct Cut {
    local: Vec<Ring>,
    chains: Vec<Chain>,
    far_rings: Vec<usize>,
    far_winding: i32,
}

impl Cut {
    fn new(far: Far<'_>, env: &Envelope) -> Option<Cut> {
        let mut cut = Cut { local: Vec::new(), chains: Vec::new(), far_rings: Vec::new(), far_winding: 0 };
        let (mut stretches, mut wound, mut path) = (Vec::new(), 0, Vec::new());
        for (k, ring) in far.rings.rings.iter().enumerate() {
            stretches.clear();
            let pts = &ring.points;
            match far.blocks {
                Some(blocks) => env.push_blocks(pts, &blocks[k], &mut stretches),
                None => (0..pts.len()).for_each(|i| env.push_edge(pts, i, &mut stretches)),
            }
            wound += cut.ring(k, pts, &stretches, env, &mut path)?;
        }
        env.border_loops(wound, &mut cut.local);
        Some(cut)
    }

    /// Ring `k` against the box; returns the winding around the box of the loops its outside
    /// chains make with the border paths that replace them, or of the whole ring when it stays
    /// outside.
    fn ring(
        &mut self,
        k: usize,
        pts: &[Point],
        stretches: &[Stretch],
        env: &Envelope,
        path: &mut Vec<Point>,
    ) -> Option<i32> {
        let n = pts.len();
        let b = env.rect();
        let c = env.center();
        let mut local: Vec<Point> = Vec::new();
        // Crossings of the ray from the centre since the last exit (or the ring's start).
        let mut acc = 0;
        // The last exit: its edge, point and chain acc; the first entry's edge, point and the acc before it.
        let mut exit: Option<(usize, Point)> = None;
        let mut head: Option<(usize, Point, i32)> = None;
        let mut wound = 0;
        let mut inside = place(pts[0], &b);
        if inside == Place::Border {
            return None;
        }
        let first_chain = self.chains.len();
        for s in stretches {
            match *s {
                Stretch::Missed { crossings, .. } => {
                    if inside != Place::Outside {
                        return None;
                    }
                    acc += crossings;
                }
                Stretch::Kept(i) => {
                    let (u, w) = (pts[i], pts[(i + 1) % n]);
                    let end = place(w, &b);
                    if end == Place::Border {
                        return None;
                    }
                    let (entry, leave) = crossings(u, w, &b)?;
                    // A crossing exactly in line with the next inside edge would let the local
                    // sweep drop the vertex between them, which the whole sweep keeps.
                    let in_line = |a: Point, m: Point, c: Point| orient(a, m, c) == Orientation::Collinear;
                    if entry.is_some_and(|y| end == Place::Inside && in_line(y, w, pts[(i + 2) % n]))
                        || leave.is_some_and(|x| inside == Place::Inside && in_line(pts[(i + n - 1) % n], u, x))
                    {
                        return None;
                    }
                    match (inside, end, entry, leave) {
                        (Place::Inside, Place::Inside, None, None) => local.push(w),
                        (Place::Outside, Place::Outside, None, None) => acc += sunday(u, w, c),
                        (Place::Inside, Place::Outside, None, Some(x)) => {
                            local.push(x);
                            exit = Some((i, x));
                            acc = sunday(x, w, c);
                        }
                        (Place::Outside, _, Some(y), x) if (end == Place::Inside) == x.is_none() => {
                            acc += sunday(u, y, c);
                            match exit.take() {
                                Some((j, xp)) => {
                                    wound += self.chain(k, n, (j, xp), (i, y), acc, env, &mut local, path);
                                }
                                None => head = Some((i, y, acc)),
                            }
                            local.push(y);
                            if let Some(x) = x {
                                local.push(x);
                                exit = Some((i, x));
                                acc = sunday(x, w, c);
                            } else {
                                local.push(w);
                            }
                        }
                        _ => return None,
                    }
                    inside = end;
                }
            }
        }
        match (exit, head) {
            (Some(from), Some((i, y, before))) => {
                wound += self.chain(k, n, from, (i, y), acc + before, env, &mut local, path);
            }
            (None, None) if inside == Place::Outside => {
                self.far_rings.push(k);
                self.far_winding += acc;
                return Some(acc);
            }
            (None, None) => {}
            _ => return None,
        }
        if first_chain == self.chains.len() {
            // Wholly inside: swept as it is.
            self.local.push(Ring { points: pts.to_vec() });
        } else {
            // An entry and exit on one side with nothing between encloses nothing.
            if local.len() >= 3 {
                self.local.push(Ring { points: local });
            }
        }
        Some(wound)
    }

    /// Records the chain from the exit on edge `j` at `x` to the entry on edge `i` at `y`, whose
    /// own crossings of the centre's ray are `crossings`, and puts the border path from `x` to `y`
    /// in its place; returns the winding of the chain with that path reversed.
    #[allow(clippy::too_many_arguments)]
    fn chain(
        &mut self,
        k: usize,
        n: usize,
        (j, x): (usize, Point),
        (i, y): (usize, Point),
        crossings: i32,
        env: &Envelope,
        local: &mut Vec<Point>,
        path: &mut Vec<Point>,
    ) -> i32 {
        let count = match (i + n - j) % n {
            0 => n,
            d => d,
        };
        self.chains.push(Chain { ring: k, first: (j + 1) % n, count, exit: x, entry: y, crossings });
        path.clear();
        path.push(x);
        env.corners_between(x, y, path);
        path.push(y);
        local.extend_from_slice(&path[1..path.len() - 1]);
        let back: i32 = path.windows(2).map(|w| sunday(w[1], w[0], env.center())).sum();
        crossings + back
    }
}

fn place(p: Point, b: &Rect) -> Place {
    if p.x > b.min.x && p.x < b.max.x && p.y > b.min.y && p.y < b.max.y {
        Place::Inside
    } else if p.x < b.min.x || p.x > b.max.x || p.y < b.min.y || p.y > b.max.y {
        Place::Outside
    } else {
        Place::Border
    }
}

/// The sides of the box, counter-clockwise from the bottom: the corner each starts at and ends at.
fn sides(b: &Rect) -> [(Point, Point); 4] {
    let (lo, hi) = (b.min, b.max);
    let (br, tl) = (Point::new(hi.x, lo.y), Point::new(lo.x, hi.y));
    [(lo, br), (br, hi), (hi, tl), (tl, lo)]
}

/// Where segment `u w` (neither end on the border) enters and leaves the open box, or `None`
/// when it passes through a corner or a rounded crossing lands on one.
fn crossings(u: Point, w: Point, b: &Rect) -> Option<(Option<Point>, Option<Point>)> {
    let (mut entry, mut leave) = (None, None);
    for (k, (s, e)) in sides(b).into_iter().enumerate() {
        // Signed distance beyond the side's line (positive outside) of each end.
        let beyond = |p: Point| match k {
            0 => b.min.y - p.y,
            1 => p.x - b.max.x,
            2 => p.y - b.max.y,
            _ => b.min.x - p.x,
        };
        let (du, dw) = (beyond(u), beyond(w));
        if du == 0.0 || dw == 0.0 || (du > 0.0) == (dw > 0.0) {
            continue;
        }
        let (os, oe) = (orient(u, w, s), orient(u, w, e));
        if os == Orientation::Collinear || oe == Orientation::Collinear {
            return None;
        }
        if os == oe {
            continue;
        }
        let at = side_crossing(u, w, k, b)?;
        let slot = if du > 0.0 { &mut entry } else { &mut leave };
        if slot.replace(at).is_some() {
            return None;
        }
    }
    Some((entry, leave))
}

/// The crossing of segment `u w` with side `k`'s line, rounded, strictly between its corners.
fn side_crossing(u: Point, w: Point, k: usize, b: &Rect) -> Option<Point> {
    let (p, q) = if (u.x, u.y) <= (w.x, w.y) { (u, w) } else { (w, u) };
    let at = if k % 2 == 1 {
        let x = if k == 1 { b.max.x } else { b.min.x };
        let y = p.y + (x - p.x) / (q.x - p.x) * (q.y - p.y);
        Point::new(x, y.clamp(p.y.min(q.y), p.y.max(q.y)))
    } else {
        let y = if k == 0 { b.min.y } else { b.max.y };
        let x = p.x + (y - p.y) / (q.y - p.y) * (q.x - p.x);
        Point::new(x.clamp(p.x.min(q.x), p.x.max(q.x)), y)
    };
    let valid = |v: f64| v == 0.0 || v.abs() >= MIN_COORDINATE;
    let strictly = if k % 2 == 1 { at.y > b.min.y && at.y < b.max.y } else { at.x > b.min.x && at.x < b.max.x };
    (strictly && valid(at.x) && valid(at.y)).then_some(at)
}

/// Bit `k` set when `p` lies on side `k` of the box (corners on two sides).
fn on_sides(p: Point, b: &Rect) -> u8 {
    let in_x = p.x >= b.min.x && p.x <= b.max.x;
    let in_y = p.y >= b.min.y && p.y <= b.max.y;
    u8::from(in_x && p.y == b.min.y)
        | u8::from(in_y && p.x == b.max.x) << 1
        | u8::from(in_x && p.y == b.max.y) << 2
        | u8::from(in_y && p.x == b.min.x) << 3
}

fn key(p: Point) -> (u64, u64) {
    (p.x.to_bits(), p.y.to_bits())
}

/// The result from the local sweep's rings and the far chains, or `None` when the swept rings do
/// not meet the border as the far operand does.
fn join(
    env: &Envelope,
    far: &Polygons,
    chains: &[Chain],
    far_rings: &[usize],
    far_winding: i32,
    swept: &Polygons,
) -> Option<Polygons> {
    let b = env.rect();
    let c = env.center();
    let entries: HashMap<(u64, u64), usize> = chains.iter().enumerate().map(|(i, ch)| (key(ch.entry), i)).collect();
    let exits: HashMap<(u64, u64), usize> = chains.iter().enumerate().map(|(i, ch)| (key(ch.exit), i)).collect();
    let shared = chains.iter().any(|ch| entries.contains_key(&key(ch.exit)));
    if entries.len() != chains.len() || exits.len() != chains.len() || shared {
        return None;
    }
    let mut out: Vec<Ring> = Vec::new();
    let mut verts: Vec<Point> = Vec::new();
    // run_after[chain] = the run that starts at that chain's entry.
    let mut run_after: Vec<Option<Run>> = vec![None; chains.len()];
    let mut border_winding = 0;
    for (source, ring) in swept.rings.iter().enumerate() {
        let pts = &ring.points;
        let n = pts.len();
        let masks: Vec<u8> = pts.iter().map(|&p| on_sides(p, &b)).collect();
        if masks.iter().all(|&m| m == 0) {
            out.push(ring.clone());
            continue;
        }
        let along = |i: usize| masks[i] & masks[(i + 1) % n] != 0;
        // A ring along the border alone is the far operand covering the whole border: its
        // chains (none) and rings outside account for it. One meeting the border at a point
        // and nowhere along it is not what the far operand makes.
        if !(0..n).any(along) {
            return None;
        }
        for i in (0..n).filter(|&i| along(i)) {
            border_winding += sunday(pts[i], pts[(i + 1) % n], c);
        }
        for start in (0..n).filter(|&i| along((i + n - 1) % n) && !along(i)) {
            let after = *entries.get(&key(pts[start]))?;
            let from = verts.len();
            let mut i = (start + 1) % n;
            while !along(i) {
                if masks[i] != 0 {
                    return None;
                }
                verts.push(pts[i]);
                i = (i + 1) % n;
            }
            let next = *exits.get(&key(pts[i]))?;
            if run_after[after].replace(Run { from, to: verts.len(), next, source }).is_some() {
                return None;
            }
        }
    }
    let chain_winding: i32 = chains.iter().map(|ch| ch.crossings).sum();
    if chain_winding + far_winding != border_winding {
        return None;
    }
    let inside = InsideEdges::of(swept, &b);
    let mut done = vec![false; chains.len()];
    let (mut sources, mut far_sources, mut runs) = (Vec::new(), Vec::new(), Vec::new());
    for first in 0..chains.len() {
        if done[first] {
            continue;
        }
        let (mut ring, mut k) = (Vec::new(), first);
        sources.clear();
        far_sources.clear();
        runs.clear();
        loop {
            if std::mem::replace(&mut done[k], true) {
                return None;
            }
            let ch = &chains[k];
            let pts = &far.rings[ch.ring].points;
            let n = pts.len();
            ring.extend((0..ch.count).map(|d| pts[(ch.first + d) % n]));
            far_sources.push(ch.ring);
            let run = run_after[k]?;
            runs.push((ring.len(), ring.len() + run.to - run.from));
            ring.extend_from_slice(&verts[run.from..run.to]);
            sources.push(run.source);
            k = run.next;
            if k == first {
                break;
            }
        }
        // Rings that touched (swept ones inside the box, far ones outside) and are now joined
        // would visit the point twice: the plain sweep splits them there.
        let joined = |v: &mut Vec<usize>| {
            v.sort_unstable();
            v.dedup();
            v.len() > 1
        };
        let (a, b) = (joined(&mut sources), joined(&mut far_sources));
        if ring.len() < 3 || ((a || b) && (visits_twice(&ring) || on_own_edge(&ring, &runs))) {
            return None;
        }
        if joins_cross(&ring, &runs, &inside) {
            return None;
        }
        out.push(Ring { points: ring });
    }
    out.extend(far_rings.iter().map(|&k| far.rings[k].clone()));
    Some(Polygons::new(out))
}

/// The swept rings' edges with neither end on the box's border, in a cell index: what stays of
/// the local result inside the box.
struct InsideEdges {
    edges: Vec<Segment>,
    boxes: Vec<Rect>,
    index: Option<CellIndex>,
}

impl InsideEdges {
    fn of(swept: &Polygons, b: &Rect) -> InsideEdges {
        let edges: Vec<Segment> = swept.edges().filter(|e| on_sides(e.a, b) == 0 && on_sides(e.b, b) == 0).collect();
        let boxes: Vec<Rect> = edges.iter().map(Segment::bounds).collect();
        let index = CellIndex::new(&boxes);
        InsideEdges { edges, boxes, index }
    }
}

/// True when an edge joining a far chain to a run (it crosses the border: the far operand's own
/// edge, restored) crosses or overlaps an edge the local sweep left inside the box. The sweep cut
/// that far edge at a rounded point of the border, so crossings it computed along it can lie an
/// ulp or so off the restored edge, on the wrong side of it.
fn joins_cross(ring: &[Point], runs: &[(usize, usize)], inside: &InsideEdges) -> bool {
    let Some(index) = &inside.index else { return false };
    let n = ring.len();
    runs.iter().flat_map(|&(from, to)| [(from + n - 1) % n, (to + n - 1) % n]).any(|i| {
        let join = Segment::new(ring[i], ring[(i + 1) % n]);
        let mut crossed = false;
        index.for_each_meeting(&inside.boxes, &join.bounds(), |k| {
            crossed |= matches!(
                segment_intersection(join, inside.edges[k]),
                SegmentIntersection::Crossing(_) | SegmentIntersection::Overlap(_)
            );
        });
        crossed
    })
}

/// True when a vertex of the ring's `runs` (index ranges of the local sweep's vertices) lies inside
/// one of the ring's edges at a run (the runs' own and the two joining each to its chains):
/// swept rings may touch at a vertex of one inside an edge of the other, and joined into one
/// ring they would visit that point twice. Only run edges can hold a run vertex: the chains lie
/// outside the box. Pairs come from a cell index over those edges' boxes.
fn on_own_edge(ring: &[Point], runs: &[(usize, usize)]) -> bool {
    let n = ring.len();
    let starts: Vec<usize> = runs.iter().flat_map(|&(from, to)| (from..=to).map(move |i| (i + n - 1) % n)).collect();
    let edge = |i: usize| Segment::new(ring[i], ring[(i + 1) % n]);
    let boxes: Vec<Rect> = starts.iter().map(|&i| edge(i).bounds()).collect();
    let Some(index) = CellIndex::new(&boxes) else { return false };
    runs.iter().flat_map(|&(from, to)| from..to).any(|v| {
        let p = ring[v];
        let mut inside = false;
        index.for_each_meeting(&boxes, &Rect::new(p.x, p.y, p.x, p.y), |k| {
            let i = starts[k];
            let e = edge(i);
            inside |= i != v && (i + 1) % n != v && p != e.a && p != e.b && on_segment(p, e);
        });
        inside
    })
}

/// True when the ring has a vertex twice.
fn visits_twice(ring: &[Point]) -> bool {
    let mut keys: Vec<(u64, u64)> = ring.iter().map(|&p| key(p)).collect();
    keys.sort_unstable();
    keys.windows(2).any(|w| w[0] == w[1])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Route, Vatti};
    use clip_core::WindowKind;
    use clip_oracle::polygon::{REGION_TOLERANCE, same_region, tolerance};
    use clip_testkit::workload::polygon_case;

    /// From `grid` case 13087 of seed 1 (20000 cases), union, even-odd: the local sweep's two
    /// rings touch where a vertex of one lies inside an edge of the other, at (2, 2); the far
    /// chains joined them into one ring that visited (2, 2) twice. Now the plain sweep runs.
    #[test]
    fn rings_touching_inside_an_edge_are_not_joined_into_one() {
        let r = |p: &[(f64, f64)]| Ring::new(p.iter().map(|&(x, y)| Point::new(x, y)).collect());
        let subject = Polygons::new(vec![r(&[(2., 0.), (3., 4.), (2., 4.)])]);
        let clip = Polygons::new(vec![
            r(&[(0., 2.), (5., 2.), (2., 4.), (2., 5.)]),
            r(&[(2., 5.), (2., 4.), (1., 3.), (2., 2.), (6., 2.)]),
        ]);
        let fill = FillRule::EvenOdd;
        let far = Vatti::prepare(&clip, fill).unwrap().resolved().rings.clone();
        let sweep =
            |a: &Polygons, b: &Polygons, op| Vatti.clip_along(Route::Whole, None, None, a, b, op, fill).unwrap();
        let far = Far { rings: &far, blocks: None };
        assert!(splice(&subject, far, false, BoolOp::Union, fill, sweep).is_none());
        let prepared = Vatti::prepare(&clip, fill).unwrap();
        for op in [BoolOp::Union, BoolOp::Xor] {
            let out = prepared.clip(&subject, op).unwrap();
            clip_oracle::polygon::check_valid_output(&out).unwrap_or_else(|e| panic!("{op:?}: {e:?}"));
        }
    }

    #[test]
    fn many_subjects_unions_and_xors_splice_and_match_the_plain_sweep() {
        let mut spliced = 0;
        for index in 0..40 {
            let case = polygon_case("many-subjects", 3, index, WindowKind::Any).unwrap();
            for fill in FillRule::ALL {
                let far = Vatti::prepare(&case.clip, fill).unwrap().resolved().rings.clone();
                let blocks: Vec<EdgeBlocks> = far.rings.iter().map(|r| EdgeBlocks::new(&r.points)).collect();
                for op in [BoolOp::Union, BoolOp::Xor] {
                    let far = Far { rings: &far, blocks: Some(&blocks) };
                    let sweep = |a: &Polygons, b: &Polygons, op| {
                        Vatti.clip_along(Route::Whole, None, None, a, b, op, fill).unwrap()
                    };
                    let Some(out) = splice(&case.subject, far, false, op, fill, sweep) else {
                        continue;
                    };
                    spliced += 1;
                    let plain =
                        Vatti.clip_along(Route::Whole, None, None, &case.subject, &case.clip, op, fill).unwrap();
                    let tol = tolerance(&case.subject, &case.clip, REGION_TOLERANCE);
                    let same = same_region((&out, FillRule::NonZero), (&plain, FillRule::NonZero), tol);
                    assert!(same.is_ok(), "case {index} {op:?} {fill:?}: {:?}", same.unwrap_err());
                }
            }
        }
        // Under positive and negative fill one of the two orientations leaves the clip empty.
        assert!(spliced >= 200, "spliced only {spliced} of 320");
    }
}
