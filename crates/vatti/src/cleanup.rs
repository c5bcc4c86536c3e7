//! Output clean-up after the sweep: rings that touch or overlap become simple rings.
//!
//! The sweep's rings already bound the right region with the result on their left, but where
//! the result pinches at a point a ring may visit that point twice, two rings may share an edge
//! in opposite directions (zero-width gaps and slivers between coincident edges), and horizontal
//! output edges may overlap. Here such rings are taken apart into directed edges, split where a
//! vertex lies inside a horizontal edge (inside any edge, when the sweep reported a near miss:
//! see `touches`), opposite edges cancel, and rings are walked again,
//! leaving each vertex by the outgoing edge that bounds the same corner of the region as the
//! incoming one (the first one clockwise from the way back), then split wherever they still
//! visit a vertex twice. So every ring is simple; rings touch only at vertices; outers come out
//! counter-clockwise and holes clockwise. Collinear vertices are dropped last.

use clip_core::predicates::{Orientation, orient};
use clip_core::{Point, Ring, edge_winding};
#[cfg(any(test, debug_assertions))]
use clip_core::{Rect, ring_winding};

use crate::raw_rings::RawRings;
use crate::simplify::simplify_ring;
use crate::touches::Touches;
use crate::turns::Turns;

/// The clean-up's rings, and whether rounding left their form broken (`repair` then joins
/// them): two rings (or two passes of one) running the same way along an edge, where rounded
/// crossings put both sides of a sliver an ulp wide onto one line and their insides overlap; or a
/// rebuilt clockwise ring that no other ring holds, a hole whose outer rounding lost or an outer
/// turned inside out.
#[derive(Debug, Default)]
pub(crate) struct CleanRings {
    pub rings: Vec<Ring>,
    pub broken_form: bool,
}

/// The sweep's rings as conventional output rings. Only rings that share a point with another
/// ring (or with themselves) or have a vertex inside a horizontal edge are rebuilt; the others
/// are already simple and lose only collinear vertices. `touches` is a reused work buffer.
#[cfg(test)]
pub(crate) fn conventional_rings(raw: &RawRings, touches: &mut Touches) -> CleanRings {
    conventional_rings_checked(raw, touches, &mut Turns::default(), true, || true)
}

/// Clockwise rings times rings up to which the held test runs whatever `near_rounding` says.
const HELD_TEST_BUDGET: usize = 1 << 16;

/// [`conventional_rings`], testing whether rebuilt clockwise rings are held when
/// `near_rounding()` (asked only then: it scans the inputs) or the test is cheap ([`HELD_TEST_BUDGET`]): it can be quadratic
/// in the rings, and outputs with thousands of holes far above rounding (scribble unions) took
/// 30 times as long with it.
///
/// With `strict`, edges retraced near rounding also count as broken (see [`SameWay::Retraced`]):
/// for the sweep's own output only, so that the repair's sweeps, judged by the plain form, end.
pub(crate) fn conventional_rings_checked(
    raw: &RawRings,
    touches: &mut Touches,
    turns: &mut Turns,
    strict: bool,
    near_rounding: impl FnOnce() -> bool,
) -> CleanRings {
    touches.find(raw);
    let touches = &*touches;
    let mut out = Vec::with_capacity(raw.len());
    for (i, &t) in touches.touched.iter().enumerate() {
        if !t {
            let s = simplify_ring(raw.ring(i));
            if s.len() >= 3 {
                out.push(Ring::new(s));
            }
        }
    }
    let broken_form = touches.touched.contains(&true)
        && if touches.splits.is_empty() && turns.plan(raw, touches) {
            walk_turns(raw, touches, turns, &mut out, strict, near_rounding)
        } else {
            rebuild(raw, touches, &mut out, strict, near_rounding)
        };
    CleanRings { rings: out, broken_form }
}

/// What [`rebuild`] does with touched rings that `turns` planned (nothing to cancel or split,
/// nothing running the same way): the same rings in the same order, and whether a clockwise one
/// is held by no ring. Debug builds check it against the rebuild.
fn walk_turns(
    raw: &RawRings,
    touches: &Touches,
    turns: &mut Turns,
    out: &mut Vec<Ring>,
    strict: bool,
    near_rounding: impl FnOnce() -> bool,
) -> bool {
    // Asked once at most, for the debug check too.
    let (mut near_rounding, mut near) = (Some(near_rounding), None);
    let mut near_rounding = || *near.get_or_insert_with(|| near_rounding.take().is_some_and(|f| f()));
    #[cfg(debug_assertions)]
    let untouched = out.len();
    let mut clockwise: Vec<usize> = Vec::new();
    turns.walk(raw, touches, &mut |points: &[Point]| push_simplified(points, out, &mut clockwise));
    let broken = any_unheld(out, &clockwise, &mut near_rounding);
    #[cfg(debug_assertions)]
    {
        let mut rebuilt = out[..untouched].to_vec();
        let rebuilt_broken = rebuild(raw, touches, &mut rebuilt, strict, &mut near_rounding);
        assert_eq!((&rebuilt, rebuilt_broken), (&*out, broken), "the planned walk differs from the rebuild");
    }
    #[cfg(not(debug_assertions))]
    let _ = strict;
    broken
}

/// `points` as a ring without repeated or collinear vertices, pushed onto `out` unless that
/// leaves fewer than three; its index goes to `clockwise` unless it runs counter-clockwise, decided
/// exactly where its area is rounding (a clockwise sliver's rounded area can come out positive).
fn push_simplified(points: &[Point], out: &mut Vec<Ring>, clockwise: &mut Vec<usize>) {
    let s = simplify_ring(points);
    if s.len() >= 3 {
        let ring = Ring::new(s);
        if !ring.runs_counter_clockwise() {
            clockwise.push(out.len());
        }
        out.push(ring);
    }
}

/// True when one of the `clockwise` rings of `out` is held by no other ring, tested when that is
/// cheap ([`HELD_TEST_BUDGET`]) or `near_rounding()`.
fn any_unheld(out: &[Ring], clockwise: &[usize], near_rounding: impl FnOnce() -> bool) -> bool {
    let check_holes = !clockwise.is_empty() && (clockwise.len() * out.len() <= HELD_TEST_BUDGET || near_rounding());
    if !check_holes {
        return false;
    }
    let unheld = HeldTest::default().any_unheld(out, clockwise);
    #[cfg(debug_assertions)]
    {
        let boxes: Vec<Rect> = out.iter().map(Ring::bounds).collect();
        assert_eq!(unheld, clockwise.iter().any(|&h| !held(out, &boxes, h)), "the batched held test differs");
    }
    unheld
}

/// Whether holes lie inside an outer, for all holes at once: each hole's first test point
/// ([`test_point`]) goes into a list sorted by y, and one pass over every ring's edges adds each edge's
/// winding to the points level with it. Holes whose point lies on a ring try their next point
/// in the next pass. The same answers as [`held`] hole by hole, which scanned the whole of a
/// large outer ring once per hole (half of a grid union's time with 150 holes).
#[derive(Default)]
struct HeldTest {
    /// `(y, x, slot)` of this pass's points, sorted by y.
    points: Vec<(f64, f64, u32)>,
    /// Per slot: the hole, its test point's index ([`test_point`]), the sum of the windings so
    /// far, and whether the point lies on a ring.
    slots: Vec<HeldSlot>,
}

#[derive(Clone, Copy)]
struct HeldSlot {
    hole: usize,
    candidate: usize,
    winding: i32,
    on_ring: bool,
}

impl HeldTest {
    fn any_unheld(&mut self, rings: &[Ring], holes: &[usize]) -> bool {
        self.slots.clear();
        self.slots.extend(holes.iter().map(|&hole| HeldSlot { hole, candidate: 0, winding: 0, on_ring: false }));
        while !self.slots.is_empty() {
            self.points.clear();
            for (slot, s) in self.slots.iter().enumerate() {
                let p = test_point(&rings[s.hole].points, s.candidate);
                self.points.push((p.y, p.x, slot as u32));
            }
            self.points.sort_unstable_by(|a, b| a.0.total_cmp(&b.0));
            self.pass(rings);
            // Decided holes leave; the others move on to their next point, or are unheld
            // when every point lies on a ring.
            let mut unheld = false;
            self.slots.retain_mut(|s| {
                if !s.on_ring {
                    unheld |= s.winding <= 0;
                    return false;
                }
                s.candidate += 1;
                unheld |= s.candidate == 2 * rings[s.hole].points.len();
                (s.winding, s.on_ring) = (0, false);
                true
            });
            if unheld {
                return true;
            }
        }
        false
    }

    /// Adds every edge's winding to the points level with it (none of its own ring's).
    fn pass(&mut self, rings: &[Ring]) {
        let (Some(&(low, ..)), Some(&(high, ..))) = (self.points.first(), self.points.last()) else { return };
        for (k, ring) in rings.iter().enumerate() {
            let pts = &ring.points;
            let Some(&last) = pts.last() else { continue };
            let mut a = last;
            for &b in pts {
                let (y0, y1) = if a.y <= b.y { (a.y, b.y) } else { (b.y, a.y) };
                if y1 >= low && y0 <= high {
                    let first = self.points.partition_point(|q| q.0 < y0);
                    for &(y, x, slot) in self.points[first..].iter().take_while(|q| q.0 <= y1) {
                        // Edges wholly left of the point neither hold it nor cross its ray.
                        if a.x < x && b.x < x {
                            continue;
                        }
                        let s = &mut self.slots[slot as usize];
                        if s.hole != k && !s.on_ring {
                            match edge_winding(Point::new(x, y), a, b) {
                                Some(w) => s.winding += w,
                                None => s.on_ring = true,
                            }
                        }
                    }
                }
                a = b;
            }
        }
    }
}

/// Test point `i` of a ring: its edges' midpoints, then its vertices. A hole's vertices are
/// where it is pinched to its outer (130 of 153 holes' first vertices in a grid union lay on
/// another ring; in scribble unions, often all of them), its edges' midpoints rarely are.
fn test_point(points: &[Point], i: usize) -> Point {
    let n = points.len();
    if i >= n {
        return points[i - n];
    }
    let (a, b) = (points[i], points[(i + 1) % n]);
    Point::new(a.x + (b.x - a.x) / 2.0, a.y + (b.y - a.y) / 2.0)
}

/// Rebuilds the touched rings (horizontal edges split at the vertices inside them) into simple
/// rings, pushed onto `out` (after the untouched ones). True when two of their edges leave or
/// arrive at one point in the same direction, or a clockwise one is held by no other ring of
/// `out`.
fn rebuild(
    rings: &RawRings,
    touches: &Touches,
    out: &mut Vec<Ring>,
    strict: bool,
    near_rounding: impl FnOnce() -> bool,
) -> bool {
    let Touches { touched, splits, ids, distinct: pts, .. } = touches;
    // Every vertex visit in ring order, as point ids, horizontals split at the vertices inside.
    let inside: usize = splits.iter().map(|s| s.inside.len()).sum();
    let mut visits: Vec<u32> = Vec::with_capacity(rings.points.len() + inside);
    let mut ring_ends: Vec<usize> = Vec::with_capacity(rings.len());
    let mut next_split = splits.iter().peekable();
    for ri in (0..rings.len()).filter(|&ri| touched[ri]) {
        let start = rings.start(ri);
        for i in 0..rings.ring(ri).len() {
            visits.push(ids[start + i]);
            while next_split.next_if(|s| (s.ring, s.edge) < (ri, i)).is_some() {}
            if let Some(s) = next_split.next_if(|s| (s.ring, s.edge) == (ri, i)) {
                visits.extend_from_slice(&s.inside);
            }
        }
        ring_ends.push(visits.len());
    }
    // The directed edges between them.
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(visits.len());
    let mut first = 0;
    for end in &mut ring_ends {
        for k in first..*end {
            let (from, to) = (visits[k], visits[if k + 1 == *end { first } else { k + 1 }]);
            if from != to {
                edges.push((from, to));
            }
        }
        first = *end;
        // From here on, where the ring's edges end in `edges`.
        *end = edges.len();
    }
    drop(visits);
    // Edges by start point (compressed rows, in edge order).
    let mut row = vec![0u32; pts.len() + 1];
    for &(a, _) in &edges {
        row[a as usize + 1] += 1;
    }
    // Points left by more than one edge, found while the counts are at hand.
    let mut shared: Vec<u32> = Vec::with_capacity(pts.len() / 2);
    for v in 0..pts.len() {
        if row[v + 1] > 1 {
            shared.push(v as u32);
        }
        row[v + 1] += row[v];
    }
    let mut outgoing = vec![0u32; edges.len()];
    let mut fill = row.clone();
    for (i, &(a, _)) in edges.iter().enumerate() {
        outgoing[fill[a as usize] as usize] = i as u32;
        fill[a as usize] += 1;
    }
    drop(fill);
    // Opposite edges cancel in pairs (they bound nothing): each edge from the lower id, in edge
    // order, with the first edge back not yet cancelled. Cancelled edges count as used.
    let mut used = vec![false; edges.len()];
    for i in 0..edges.len() {
        let (a, b) = edges[i];
        if a > b {
            continue;
        }
        let back = &outgoing[row[b as usize] as usize..row[b as usize + 1] as usize];
        if let Some(&j) = back.iter().find(|&&j| edges[j as usize].1 == a && !used[j as usize]) {
            used[i] = true;
            used[j as usize] = true;
        }
    }
    let same_way = has_same_way_edges(pts, &shared, &row, &outgoing, &edges, &ring_ends, &used);
    let mut slot = vec![usize::MAX; pts.len()];
    let mut walk: Vec<u32> = Vec::new();
    let mut stack: Vec<u32> = Vec::new();
    let mut clockwise: Vec<usize> = Vec::new();
    for start in 0..edges.len() {
        if used[start] {
            continue;
        }
        walk.clear();
        let mut e = start;
        // Each step uses one edge, so the walk ends within the edge count.
        for _ in 0..edges.len() {
            used[e] = true;
            let (from, to) = edges[e];
            walk.push(from);
            let leaving = &outgoing[row[to as usize] as usize..row[to as usize + 1] as usize];
            let candidates = leaving.iter().map(|&c| c as usize).filter(|&c| !used[c] || c == start);
            match first_clockwise(pts, from, to, candidates, &edges) {
                Some(next) if next != start => e = next,
                _ => break,
            }
        }
        split_repeats(&walk, &mut slot, &mut stack, &mut |ring: &[u32]| {
            let points: Vec<Point> = ring.iter().map(|&i| pts[i as usize]).collect();
            push_simplified(&points, out, &mut clockwise);
        });
    }
    // Asked once at most: it scans the inputs.
    let (mut near_rounding, mut near) = (Some(near_rounding), None);
    let mut near_rounding = || *near.get_or_insert_with(|| near_rounding.take().is_some_and(|f| f()));
    // Retraced edges are a valid form where nothing is rounded, but near rounding the walk over
    // them can leave rings crossing at a shared point (a fuzz input's xor): the repair decides.
    if same_way == SameWay::Remaining || (strict && same_way == SameWay::Retraced && near_rounding()) {
        return true;
    }
    any_unheld(out, &clockwise, near_rounding)
}

/// True when a point of `rings[hole]` off every other ring (an edge's midpoint, else a vertex:
/// [`test_point`]) has a winding number of 1 or more in them: the hole lies inside an outer.
/// False when every such point lies on another ring (the repair's sweep then decides). Exact
/// for the point tested. The reference for [`HeldTest`], which asks the same for all holes at
/// once. `boxes` are the rings' bounds.
#[cfg(any(test, debug_assertions))]
fn held(rings: &[Ring], boxes: &[Rect], hole: usize) -> bool {
    let points = &rings[hole].points;
    'point: for p in (0..2 * points.len()).map(|i| test_point(points, i)) {
        let mut winding = 0;
        for (k, r) in rings.iter().enumerate() {
            if k == hole || !boxes[k].contains(p) {
                continue;
            }
            match ring_winding(p, r) {
                Some(w) => winding += w,
                None => continue 'point,
            }
        }
        return winding > 0;
    }
    false
}

/// Edges in the same direction at one point, as [`has_same_way_edges`] finds them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum SameWay {
    None,
    /// Only where an edge back cancelled one of them: two edges one way and one back along a
    /// stretch bound it once (a hole retracing its outer's edge, common in grid unions).
    Retraced,
    /// Two left after opposite edges cancelled: the insides overlap.
    Remaining,
}

/// Whether two edges leave one point, or arrive at one point, in the same direction
/// ([`SameWay`]; `cancelled` are the edges opposite edges cancelled): they overlap along the
/// shorter one, running the same way (two rings' insides overlap there, or a hole pokes out of
/// its outer). Ends are compared exactly, so this also catches overlaps of slanted edges that
/// were not split. `shared` are the points left by
/// two edges or more, `outgoing[row[v]..row[v + 1]]` the edges leaving point `v`, and
/// `ring_ends[r]` where ring `r`'s edges end in `edges`: an edge is arrived at by the one before
/// it in its ring. Kept out of line: `rebuild`'s walk is the hot part.
#[inline(never)]
fn has_same_way_edges(
    pts: &[Point],
    shared: &[u32],
    row: &[u32],
    outgoing: &[u32],
    edges: &[(u32, u32)],
    ring_ends: &[usize],
    cancelled: &[bool],
) -> SameWay {
    // Which edges start a ring, one bit each, and one past the last edge.
    let mut ring_start = vec![0u64; edges.len() / 64 + 1];
    let mut first = 0;
    for &end in ring_ends {
        if end > first {
            ring_start[first / 64] |= 1 << (first % 64);
        }
        first = end;
    }
    ring_start[edges.len() / 64] |= 1 << (edges.len() % 64);
    // The edge arriving where edge `i` leaves: the one before it in its ring.
    let arriving = |i: usize| {
        if ring_start[i / 64] & (1 << (i % 64)) == 0 {
            return i - 1;
        }
        // A ring's first edge is arrived at by its last: the edge before the next ring's start.
        let (mut word, mut bits, mut at) = (i / 64, ring_start[i / 64] >> (i % 64) >> 1, i + 1);
        while bits == 0 {
            word += 1;
            (bits, at) = (ring_start[word], word * 64);
        }
        at + bits.trailing_zeros() as usize - 1
    };
    let mut found = SameWay::None;
    for &v in shared {
        let leaving = &outgoing[row[v as usize] as usize..row[v as usize + 1] as usize];
        let pv = pts[v as usize];
        for (k, &i) in leaving.iter().enumerate() {
            let (i, before_i) = (i as usize, arriving(i as usize));
            for &j in &leaving[k + 1..] {
                let (j, before_j) = (j as usize, arriving(j as usize));
                for (a, b, to_a, to_b) in
                    [(i, j, edges[i].1, edges[j].1), (before_i, before_j, edges[before_i].0, edges[before_j].0)]
                {
                    if same_way(pts, pv, to_a, to_b) {
                        if !cancelled[a] && !cancelled[b] {
                            return SameWay::Remaining;
                        }
                        found = SameWay::Retraced;
                    }
                }
            }
        }
    }
    found
}

/// True when points `a` and `b` (ids in `pts`, neither at `v`) lie on one ray from `v`. Exact.
#[inline(always)]
fn same_way(pts: &[Point], v: Point, a: u32, b: u32) -> bool {
    a == b || sector(v, pts[a as usize], pts[b as usize]) == 3
}

/// Of the edges leaving `v`, the first met turning clockwise from the direction back to `u`.
fn first_clockwise(
    pts: &[Point],
    u: u32,
    v: u32,
    candidates: impl Iterator<Item = usize>,
    edges: &[(u32, u32)],
) -> Option<usize> {
    let (pu, pv) = (pts[u as usize], pts[v as usize]);
    let mut best: Option<(usize, Point)> = None;
    for c in candidates {
        let w = pts[edges[c].1 as usize];
        best = match best {
            None => Some((c, w)),
            Some((b, bw)) => {
                if clockwise_before(pv, pu, w, bw) {
                    Some((c, w))
                } else {
                    Some((b, bw))
                }
            }
        };
    }
    best.map(|(c, _)| c)
}

/// Sector of direction `v -> w` measured clockwise from `v -> r`: 0 for (0, pi), 1 at pi,
/// 2 for (pi, 2pi), 3 when it points back along `v -> r` (a full turn).
fn sector(v: Point, r: Point, w: Point) -> u8 {
    match orient(v, r, w) {
        Orientation::Clockwise => 0,
        Orientation::CounterClockwise => 2,
        Orientation::Collinear => {
            // Collinear through v: same direction when on the same side of v (exact compares).
            let same = if r.x != v.x { (w.x > v.x) == (r.x > v.x) } else { (w.y > v.y) == (r.y > v.y) };
            if same { 3 } else { 1 }
        }
    }
}

/// True when `v -> w1` comes strictly before `v -> w2` turning clockwise from `v -> r`. Exact.
fn clockwise_before(v: Point, r: Point, w1: Point, w2: Point) -> bool {
    let (s1, s2) = (sector(v, r, w1), sector(v, r, w2));
    if s1 != s2 {
        return s1 < s2;
    }
    if s1 == 0 || s1 == 2 { orient(v, w1, w2) == Orientation::Clockwise } else { false }
}

/// Splits a closed walk at every vertex it visits twice, handing each simple loop to `emit`.
/// `slot` is scratch space indexed by vertex id, all `usize::MAX` on entry and exit; `stack` is
/// a reused buffer.
pub(crate) fn split_repeats(walk: &[u32], slot: &mut [usize], stack: &mut Vec<u32>, emit: &mut impl FnMut(&[u32])) {
    stack.clear();
    for &v in walk {
        let at = slot[v as usize];
        if at != usize::MAX {
            emit(&stack[at..]);
            for &w in &stack[at + 1..] {
                slot[w as usize] = usize::MAX;
            }
            stack.truncate(at + 1);
        } else {
            slot[v as usize] = stack.len();
            stack.push(v);
        }
    }
    emit(stack);
    for &w in stack.iter() {
        slot[w as usize] = usize::MAX;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn conventional_rings(rings: Vec<Vec<Point>>) -> Vec<Ring> {
        super::conventional_rings(&RawRings::from_rings(rings), &mut Touches::default()).rings
    }

    fn ring(points: &[(f64, f64)]) -> Vec<Point> {
        points.iter().map(|&(x, y)| Point::new(x, y)).collect()
    }

    fn areas(rings: &[Ring]) -> Vec<f64> {
        let mut a: Vec<f64> = rings.iter().map(Ring::signed_area).collect();
        a.sort_by(f64::total_cmp);
        a
    }

    #[test]
    fn rings_sharing_an_edge_merge_into_one() {
        let left = ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let right = ring(&[(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)]);
        let out = conventional_rings(vec![left, right]);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].len(), 4, "collinear vertices dropped: {:?}", out[0]);
        assert_eq!(out[0].signed_area(), 2.0);
    }

    #[test]
    fn a_ring_visiting_a_point_twice_splits_there() {
        // A bow tie of two counter-clockwise triangles meeting at (1, 1).
        let bow = ring(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (2.0, 2.0), (1.0, 1.0), (0.0, 2.0)]);
        let out = conventional_rings(vec![bow]);
        assert_eq!(areas(&out), vec![1.0, 1.0]);
    }

    #[test]
    fn horizontal_edges_split_where_the_other_ring_has_vertices() {
        // [0,2]x[0,1] above [1,3]x[-1,0]: they share (1,0)-(2,0), each end inside the other's edge.
        let top = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)]);
        let bottom = ring(&[(1.0, -1.0), (3.0, -1.0), (3.0, 0.0), (1.0, 0.0)]);
        let out = conventional_rings(vec![top, bottom]);
        assert_eq!(out.len(), 1);
        assert_eq!(out[0].len(), 8, "{:?}", out[0]);
        assert_eq!(out[0].signed_area(), 4.0);
    }

    #[test]
    fn rings_running_the_same_way_along_an_edge_are_reported() {
        // Both triangles lie left of (0,0) -> (2,0): their insides overlap there.
        let big = ring(&[(0.0, 0.0), (2.0, 0.0), (1.0, 2.0)]);
        let small = ring(&[(0.0, 0.0), (2.0, 0.0), (1.0, 1.0)]);
        let clean = super::conventional_rings(&RawRings::from_rings(vec![big, small]), &mut Touches::default());
        assert!(clean.broken_form);
        // Run opposite ways, the shared edge bounds nothing and the rings merge.
        let left = ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let right = ring(&[(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)]);
        let clean = super::conventional_rings(&RawRings::from_rings(vec![left, right]), &mut Touches::default());
        assert!(!clean.broken_form);
    }

    #[test]
    fn rings_leaving_or_arriving_at_a_point_the_same_way_are_reported() {
        // A square and a triangle inside it, both leaving (2,0) upwards, to different ends:
        // the square's (2,2) and the triangle's (2,1). Vertical edges are not split.
        let square = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
        let leaving = ring(&[(2.0, 0.0), (2.0, 1.0), (1.5, 0.5)]);
        let clean =
            super::conventional_rings(&RawRings::from_rings(vec![square.clone(), leaving]), &mut Touches::default());
        assert!(clean.broken_form);
        // A clockwise triangle arriving at (2,2) along the square's right edge from (2,1): a
        // hole poking out of its outer.
        let arriving = ring(&[(2.0, 1.0), (2.0, 2.0), (2.5, 1.5)]);
        let clean =
            super::conventional_rings(&RawRings::from_rings(vec![square.clone(), arriving]), &mut Touches::default());
        assert!(clean.broken_form);
        // Touching at (0,0) in other directions is a valid form.
        let beside = ring(&[(0.0, 0.0), (-1.0, 0.0), (-1.0, -1.0)]);
        let clean = super::conventional_rings(&RawRings::from_rings(vec![square, beside]), &mut Touches::default());
        assert!(!clean.broken_form);
    }

    #[test]
    fn clockwise_rings_held_by_no_ring_are_reported() {
        // A clockwise triangle touching a square at its corner, outside it: an outer turned
        // inside out.
        let square = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
        let outside = ring(&[(2.0, 2.0), (3.0, 4.0), (4.0, 3.0)]);
        let clean =
            super::conventional_rings(&RawRings::from_rings(vec![square.clone(), outside]), &mut Touches::default());
        assert!(clean.broken_form);
        // The same triangle inside the square, touching it at that corner: a hole.
        let inside = ring(&[(2.0, 2.0), (1.0, 0.5), (0.5, 1.0)]);
        let clean = super::conventional_rings(&RawRings::from_rings(vec![square, inside]), &mut Touches::default());
        assert!(!clean.broken_form);
    }

    #[test]
    fn holes_are_tested_all_at_once_at_points_off_the_other_rings() {
        let rings: Vec<Ring> = [
            ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]),
            // Pinched to the outer at every vertex: held, told by its edges' midpoints.
            ring(&[(2.0, 0.0), (0.0, 2.0), (2.0, 4.0), (4.0, 2.0)]),
            // Its first edge runs along the outer's: held, told by its second edge's midpoint.
            ring(&[(2.0, 0.0), (1.0, 0.0), (1.0, 1.0), (2.0, 1.0)]),
            // Outside everything.
            ring(&[(10.0, 10.0), (10.0, 11.0), (11.0, 11.0), (11.0, 10.0)]),
            // The outer's first triangle, reversed, over a triangle: every point lies on it.
            ring(&[(5.0, 0.0), (6.0, 0.0), (5.0, 1.0)]),
            ring(&[(5.0, 0.0), (5.0, 1.0), (6.0, 0.0)]),
        ]
        .into_iter()
        .map(Ring::new)
        .collect();
        let boxes: Vec<Rect> = rings.iter().map(Ring::bounds).collect();
        let mut test = HeldTest::default();
        for (holes, unheld) in [(&[1, 2][..], false), (&[1, 3], true), (&[3], true), (&[5], true), (&[2, 5], true)] {
            assert_eq!(test.any_unheld(&rings, holes), unheld, "holes {holes:?}");
            assert_eq!(holes.iter().any(|&h| !held(&rings, &boxes, h)), unheld, "holes {holes:?} one by one");
        }
    }

    #[test]
    fn a_hole_retracing_its_outers_edge_is_reported_only_near_rounding_and_strict() {
        // The outer runs up x = 4 through (4,1), (4,2), (4,3); the hole runs down it from (4,3) to
        // (4,1) and back up from (4,2) to (4,3): along (4,2)-(4,3) two edges go up, one down.
        let outer = ring(&[(0.0, 0.0), (4.0, 0.0), (4.0, 1.0), (4.0, 2.0), (4.0, 3.0), (4.0, 4.0), (0.0, 4.0)]);
        let hole =
            ring(&[(4.0, 3.0), (4.0, 2.0), (4.0, 1.0), (3.0, 1.5), (4.0, 2.0), (4.0, 3.0), (3.0, 3.0), (3.5, 3.5)]);
        let raw = RawRings::from_rings(vec![outer, hole]);
        let clean = |strict: bool, near: bool| {
            super::conventional_rings_checked(&raw, &mut Touches::default(), &mut Turns::default(), strict, || near)
        };
        let plain = clean(false, true);
        assert!(!plain.broken_form);
        assert_eq!(areas(&plain.rings), vec![-0.25, 15.5]);
        assert!(!clean(true, false).broken_form);
        assert!(clean(true, true).broken_form);
    }

    #[test]
    fn after_a_near_miss_slanted_edges_split_and_opposite_overlaps_cancel() {
        // One ring runs up y = x from (0,0) to (4,4) and later down it from (3,3) to (1,1): no
        // point repeats and no horizontal edge holds a vertex, so only the sweep's near miss
        // (rounded edges through exact points) has the clean-up look at slanted edges.
        let points = ring(&[(0.0, 0.0), (4.0, 4.0), (1.0, 4.0), (3.0, 3.0), (1.0, 1.0), (0.0, 2.0)]);
        let mut raw = RawRings::from_rings(vec![points]);
        let clean = super::conventional_rings(&raw, &mut Touches::default());
        assert_eq!(clean.rings.len(), 1, "untouched without a near miss");
        raw.near_miss = true;
        let clean = super::conventional_rings(&raw, &mut Touches::default());
        assert!(!clean.broken_form);
        assert_eq!(areas(&clean.rings), vec![1.0, 1.5]);
    }

    #[test]
    fn untouched_rings_only_lose_collinear_vertices() {
        let square = ring(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
        let hole = ring(&[(0.5, 0.5), (0.5, 1.5), (1.5, 1.5), (1.5, 0.5)]);
        let out = conventional_rings(vec![square, hole]);
        assert_eq!(areas(&out), vec![-1.0, 4.0]);
        assert_eq!(out.iter().map(Ring::len).collect::<Vec<_>>(), vec![4, 4]);
    }
}
