//! Output clean-up after the sweep: rings that touch or overlap become simple rings.
//!
//! The sweep's rings already bound the right region with the result on their left, but where
//! the result pinches at a point a ring may visit that point twice, two rings may share an edge
//! in opposite directions (zero-width gaps and slivers between coincident edges), and horizontal
//! output edges may overlap. Here such rings are taken apart into directed edges, split where a
//! vertex lies inside a horizontal edge, opposite edges cancel, and rings are walked again,
//! leaving each vertex by the outgoing edge that bounds the same corner of the region as the
//! incoming one (the first one clockwise from the way back), then split wherever they still
//! visit a vertex twice. So every ring is simple; rings touch only at vertices; outers come out
//! counter-clockwise and holes clockwise. Collinear vertices are dropped last.

use clip_core::predicates::{Orientation, orient};
use clip_core::{Point, Ring};

use crate::simplify::simplify_ring;

/// Exact key of a point (`-0.0` and `0.0` alike), ordered so equal points sort together.
#[inline]
fn key(p: Point) -> (u64, u64) {
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

/// The sweep's rings as conventional output rings. Only rings that share a point with another
/// ring (or with themselves) or have a vertex inside a horizontal edge are rebuilt; the others
/// are already simple and lose only collinear vertices.
pub(crate) fn conventional_rings(raw: Vec<Vec<Point>>) -> Vec<Ring> {
    let raw: Vec<Vec<Point>> = raw.into_iter().map(without_repeats).filter(|r| r.len() >= 3).collect();
    let mut touched = shared_points(&raw);
    let splits = split_horizontals(&raw, &mut touched);
    let mut out = Vec::with_capacity(raw.len());
    for (r, &t) in raw.iter().zip(&touched) {
        if !t {
            let s = simplify_ring(r);
            if s.len() >= 3 {
                out.push(Ring::new(s));
            }
        }
    }
    if touched.contains(&true) {
        rebuild(&raw, &touched, &splits, &mut out);
    }
    out
}

/// The ring without consecutive repeated points (the closing pair included).
fn without_repeats(mut r: Vec<Point>) -> Vec<Point> {
    r.dedup();
    while r.len() > 1 && r.first() == r.last() {
        r.pop();
    }
    r
}

/// For each ring: does it share a point with another ring or visit one twice? By sorting the
/// exact keys, which for the few hundred points of a typical result beats hashing them.
fn shared_points(rings: &[Vec<Point>]) -> Vec<bool> {
    let mut touched = vec![false; rings.len()];
    let mut keyed: Vec<((u64, u64), u32)> =
        rings.iter().enumerate().flat_map(|(i, r)| r.iter().map(move |&p| (key(p), i as u32))).collect();
    keyed.sort_unstable_by_key(|&(k, _)| k);
    for run in keyed.chunk_by(|a, b| a.0 == b.0) {
        if run.len() > 1 {
            for &(_, i) in run {
                touched[i as usize] = true;
            }
        }
    }
    touched
}

/// A horizontal edge (`ring`, `edge`: the edge from vertex `edge` to the next) with vertices
/// strictly inside it, at these x values in the edge's direction.
struct SplitEdge {
    ring: usize,
    edge: usize,
    xs: Vec<f64>,
}

/// Every horizontal edge with vertices strictly inside it, in ring and edge order; its ring and
/// the vertices' rings are marked touched.
fn split_horizontals(rings: &[Vec<Point>], touched: &mut [bool]) -> Vec<SplitEdge> {
    let has_horizontal = rings.iter().any(|r| (0..r.len()).any(|i| r[i].y == r[(i + 1) % r.len()].y));
    if !has_horizontal {
        return Vec::new();
    }
    let by_y = vertices_by_y(rings);
    let mut splits = Vec::new();
    for (ri, r) in rings.iter().enumerate() {
        let n = r.len();
        for i in 0..n {
            let (a, b) = (r[i], r[(i + 1) % n]);
            if a.y != b.y {
                continue;
            }
            let mut xs = Vec::new();
            for &(_, x, rj) in inside_horizontal(&by_y, a, b) {
                touched[rj] = true;
                xs.push(x);
            }
            if xs.is_empty() {
                continue;
            }
            touched[ri] = true;
            xs.dedup();
            if a.x > b.x {
                xs.reverse();
            }
            splits.push(SplitEdge { ring: ri, edge: i, xs });
        }
    }
    splits
}

/// Every vertex as `(y, x, ring)`, sorted by y then x.
fn vertices_by_y(rings: &[Vec<Point>]) -> Vec<(f64, f64, usize)> {
    let mut v: Vec<(f64, f64, usize)> =
        rings.iter().enumerate().flat_map(|(i, r)| r.iter().map(move |p| (p.y, p.x, i))).collect();
    v.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    v
}

/// The vertices strictly inside the horizontal edge `a`-`b`.
fn inside_horizontal(by_y: &[(f64, f64, usize)], a: Point, b: Point) -> impl Iterator<Item = &(f64, f64, usize)> {
    let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
    let start = by_y.partition_point(|&(y, x, _)| y < a.y || (y == a.y && x <= lo));
    by_y[start..].iter().take_while(move |&&(y, x, _)| y == a.y && x < hi)
}

/// Rebuilds the touched rings (`splits` as found by [`split_horizontals`]) into simple rings,
/// pushed onto `out`.
fn rebuild(rings: &[Vec<Point>], touched: &[bool], splits: &[SplitEdge], out: &mut Vec<Ring>) {
    // Every vertex visit in ring order, horizontals split at the vertices inside them.
    let mut visits: Vec<Point> = Vec::new();
    let mut ring_ends: Vec<usize> = Vec::new();
    let mut next_split = splits.iter().peekable();
    for (ri, r) in rings.iter().enumerate().filter(|&(ri, _)| touched[ri]) {
        for (i, &p) in r.iter().enumerate() {
            visits.push(p);
            while next_split.next_if(|s| (s.ring, s.edge) < (ri, i)).is_some() {}
            if let Some(s) = next_split.next_if(|s| (s.ring, s.edge) == (ri, i)) {
                visits.extend(s.xs.iter().map(|&x| Point::new(x, p.y)));
            }
        }
        ring_ends.push(visits.len());
    }
    // Point ids: equal points, found by sorting their keys, share one.
    let mut keyed: Vec<((u64, u64), u32)> = visits.iter().enumerate().map(|(i, &p)| (key(p), i as u32)).collect();
    keyed.sort_unstable();
    let mut id = vec![0u32; visits.len()];
    let mut pts: Vec<Point> = Vec::new();
    for run in keyed.chunk_by(|a, b| a.0 == b.0) {
        for &(_, v) in run {
            id[v as usize] = pts.len() as u32;
        }
        pts.push(visits[run[0].1 as usize]);
    }
    // The directed edges between them.
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(visits.len());
    let mut first = 0;
    for &end in &ring_ends {
        for k in first..end {
            let (from, to) = (id[k], id[if k + 1 == end { first } else { k + 1 }]);
            if from != to {
                edges.push((from, to));
            }
        }
        first = end;
    }
    // Opposite edges cancel in pairs: they bound nothing.
    let mut live = vec![true; edges.len()];
    let mut undirected: Vec<(u32, u32, u32)> =
        edges.iter().enumerate().map(|(i, &(a, b))| (a.min(b), a.max(b), i as u32)).collect();
    undirected.sort_unstable();
    for run in undirected.chunk_by(|a, b| (a.0, a.1) == (b.0, b.1)) {
        if run.len() < 2 {
            continue;
        }
        let upwards = run.iter().filter(|u| edges[u.2 as usize].0 == u.0);
        let downwards = run.iter().filter(|u| edges[u.2 as usize].0 != u.0);
        for (u, d) in upwards.zip(downwards) {
            live[u.2 as usize] = false;
            live[d.2 as usize] = false;
        }
    }
    // Live edges by start point (compressed rows, in edge order).
    let mut row = vec![0u32; pts.len() + 1];
    for (i, &(a, _)) in edges.iter().enumerate() {
        if live[i] {
            row[a as usize + 1] += 1;
        }
    }
    for v in 0..pts.len() {
        row[v + 1] += row[v];
    }
    let mut outgoing = vec![0u32; row[pts.len()] as usize];
    let mut fill = row.clone();
    for (i, &(a, _)) in edges.iter().enumerate() {
        if live[i] {
            outgoing[fill[a as usize] as usize] = i as u32;
            fill[a as usize] += 1;
        }
    }
    let mut used = vec![false; edges.len()];
    let mut slot = vec![usize::MAX; pts.len()];
    let mut walk: Vec<u32> = Vec::new();
    for start in 0..edges.len() {
        if !live[start] || used[start] {
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
            match first_clockwise(&pts, from, to, candidates, &edges) {
                Some(next) if next != start => e = next,
                _ => break,
            }
        }
        split_repeats(&walk, &mut slot, &mut |ring: &[u32]| {
            let points: Vec<Point> = ring.iter().map(|&i| pts[i as usize]).collect();
            let s = simplify_ring(&points);
            if s.len() >= 3 {
                out.push(Ring::new(s));
            }
        });
    }
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
/// `slot` is scratch space indexed by vertex id, all `usize::MAX` on entry and exit.
fn split_repeats(walk: &[u32], slot: &mut [usize], emit: &mut impl FnMut(&[u32])) {
    let mut stack: Vec<u32> = Vec::with_capacity(walk.len());
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
    emit(&stack);
    for &w in &stack {
        slot[w as usize] = usize::MAX;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
    fn untouched_rings_only_lose_collinear_vertices() {
        let square = ring(&[(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0)]);
        let hole = ring(&[(0.5, 0.5), (0.5, 1.5), (1.5, 1.5), (1.5, 0.5)]);
        let out = conventional_rings(vec![square, hole]);
        assert_eq!(areas(&out), vec![-1.0, 4.0]);
        assert_eq!(out.iter().map(Ring::len).collect::<Vec<_>>(), vec![4, 4]);
    }
}
