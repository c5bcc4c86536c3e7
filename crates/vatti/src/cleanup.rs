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

use std::collections::HashMap;
use std::collections::hash_map::Entry;
use std::hash::{BuildHasherDefault, Hasher};

use clip_core::predicates::{Orientation, orient};
use clip_core::{Point, Ring};

use crate::simplify::simplify_ring;

/// Exact key of a point (`-0.0` and `0.0` alike).
#[inline]
fn key(p: Point) -> (u64, u64) {
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

/// A fast multiplicative hash for exact point keys (the keys are not attacker-controlled).
#[derive(Default)]
struct KeyHasher(u64);

impl Hasher for KeyHasher {
    #[inline]
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(u64::from(b));
        }
    }

    #[inline]
    fn write_u64(&mut self, v: u64) {
        self.0 = (self.0.rotate_left(5) ^ v).wrapping_mul(0x517c_c1b7_2722_0a95);
    }

    #[inline]
    fn write_u32(&mut self, v: u32) {
        self.write_u64(u64::from(v));
    }

    #[inline]
    fn write_usize(&mut self, v: usize) {
        self.write_u64(v as u64);
    }

    #[inline]
    fn finish(&self) -> u64 {
        self.0
    }
}

type FastMap<K, V> = HashMap<K, V, BuildHasherDefault<KeyHasher>>;

/// The sweep's rings as conventional output rings. Only rings that share a point with another
/// ring (or with themselves) or have a vertex inside a horizontal edge are rebuilt; the others
/// are already simple and lose only collinear vertices.
pub(crate) fn conventional_rings(raw: Vec<Vec<Point>>) -> Vec<Ring> {
    let raw: Vec<Vec<Point>> = raw.into_iter().map(without_repeats).filter(|r| r.len() >= 3).collect();
    let touched = touched_rings(&raw);
    let mut out = Vec::with_capacity(raw.len());
    let mut rebuild_set = Vec::new();
    for (r, t) in raw.into_iter().zip(touched) {
        if t {
            rebuild_set.push(r);
        } else {
            let s = simplify_ring(&r);
            if s.len() >= 3 {
                out.push(Ring::new(s));
            }
        }
    }
    if !rebuild_set.is_empty() {
        out.extend(rebuild(&rebuild_set));
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

/// For each ring: does it share a point with another ring or itself, or have a vertex inside a
/// horizontal edge (or own a horizontal edge with another ring's vertex inside)?
fn touched_rings(rings: &[Vec<Point>]) -> Vec<bool> {
    let mut touched = vec![false; rings.len()];
    let total: usize = rings.iter().map(Vec::len).sum();
    let mut first: FastMap<(u64, u64), usize> = FastMap::with_capacity_and_hasher(total, Default::default());
    for (i, r) in rings.iter().enumerate() {
        for &p in r {
            match first.entry(key(p)) {
                Entry::Occupied(e) => {
                    touched[i] = true;
                    touched[*e.get()] = true;
                }
                Entry::Vacant(e) => {
                    e.insert(i);
                }
            }
        }
    }
    for (edge_ring, vertex_rings) in horizontal_contacts(rings) {
        touched[edge_ring] = true;
        for v in vertex_rings {
            touched[v] = true;
        }
    }
    touched
}

/// Rings with a horizontal edge that has vertices strictly inside it, with those vertices' rings.
fn horizontal_contacts(rings: &[Vec<Point>]) -> Vec<(usize, Vec<usize>)> {
    let has_horizontal = rings.iter().any(|r| (0..r.len()).any(|i| r[i].y == r[(i + 1) % r.len()].y));
    if !has_horizontal {
        return Vec::new();
    }
    let by_y = vertices_by_y(rings);
    let mut contacts = Vec::new();
    for (ri, r) in rings.iter().enumerate() {
        let n = r.len();
        for i in 0..n {
            let (a, b) = (r[i], r[(i + 1) % n]);
            if a.y != b.y {
                continue;
            }
            let inside: Vec<usize> = inside_horizontal(&by_y, a, b).map(|&(_, _, rj)| rj).collect();
            if !inside.is_empty() {
                contacts.push((ri, inside));
            }
        }
    }
    contacts
}

/// Every vertex as `(y, x, ring)`, sorted by y then x.
fn vertices_by_y(rings: &[Vec<Point>]) -> Vec<(f64, f64, usize)> {
    let mut v: Vec<(f64, f64, usize)> =
        rings.iter().enumerate().flat_map(|(i, r)| r.iter().map(move |p| (p.y, p.x, i))).collect();
    v.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    v
}

/// The vertices strictly inside the horizontal edge `a`-`b`.
fn inside_horizontal(by_y: &[(f64, f64, usize)], a: Point, b: Point) -> impl Iterator<Item = &(f64, f64, usize)> {
    let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
    let start = by_y.partition_point(|&(y, x, _)| y < a.y || (y == a.y && x <= lo));
    by_y[start..].iter().take_while(move |&&(y, x, _)| y == a.y && x < hi)
}

/// For every horizontal edge `(ring, index)` with vertices strictly inside it, those vertices'
/// x values in the edge's direction.
fn horizontal_splits(rings: &[Vec<Point>]) -> FastMap<(usize, usize), Vec<f64>> {
    let by_y = vertices_by_y(rings);
    let mut splits = FastMap::default();
    for (ri, r) in rings.iter().enumerate() {
        let n = r.len();
        for i in 0..n {
            let (a, b) = (r[i], r[(i + 1) % n]);
            if a.y != b.y || a.x == b.x {
                continue;
            }
            let mut xs: Vec<f64> = inside_horizontal(&by_y, a, b).map(|&(_, x, _)| x).collect();
            if xs.is_empty() {
                continue;
            }
            xs.dedup();
            if a.x > b.x {
                xs.reverse();
            }
            splits.insert((ri, i), xs);
        }
    }
    splits
}

fn rebuild(rings: &[Vec<Point>]) -> Vec<Ring> {
    let splits = horizontal_splits(rings);
    // Points by id, and the directed edges between them.
    let mut ids: FastMap<(u64, u64), u32> = FastMap::default();
    let mut pts: Vec<Point> = Vec::new();
    let mut id_of = |p: Point, pts: &mut Vec<Point>| {
        *ids.entry(key(p)).or_insert_with(|| {
            pts.push(p);
            pts.len() as u32 - 1
        })
    };
    let mut edges: Vec<(u32, u32)> = Vec::new();
    for (ri, r) in rings.iter().enumerate() {
        let n = r.len();
        for i in 0..n {
            let (a, b) = (r[i], r[(i + 1) % n]);
            let mut from = id_of(a, &mut pts);
            if let Some(xs) = splits.get(&(ri, i)) {
                for &x in xs {
                    let mid = id_of(Point::new(x, a.y), &mut pts);
                    edges.push((from, mid));
                    from = mid;
                }
            }
            let to = id_of(b, &mut pts);
            if from != to {
                edges.push((from, to));
            }
        }
    }
    // Opposite edges cancel: they bound nothing.
    let mut live = vec![true; edges.len()];
    let mut open: FastMap<(u32, u32), Vec<usize>> = FastMap::default();
    for (i, &(a, b)) in edges.iter().enumerate() {
        if let Some(j) = open.get_mut(&(b, a)).and_then(Vec::pop) {
            live[i] = false;
            live[j] = false;
        } else {
            open.entry((a, b)).or_default().push(i);
        }
    }
    let mut outgoing: Vec<Vec<usize>> = vec![Vec::new(); pts.len()];
    for (i, &(a, _)) in edges.iter().enumerate() {
        if live[i] {
            outgoing[a as usize].push(i);
        }
    }
    let mut used = vec![false; edges.len()];
    let mut result = Vec::new();
    let mut slot = vec![usize::MAX; pts.len()];
    for start in 0..edges.len() {
        if !live[start] || used[start] {
            continue;
        }
        let mut walk: Vec<u32> = Vec::new();
        let mut e = start;
        // Each step uses one edge, so the walk ends within the edge count.
        for _ in 0..edges.len() {
            used[e] = true;
            let (from, to) = edges[e];
            walk.push(from);
            let candidates = outgoing[to as usize].iter().copied().filter(|&c| !used[c] || c == start);
            match first_clockwise(&pts, from, to, candidates, &edges) {
                Some(next) if next != start => e = next,
                _ => break,
            }
        }
        split_repeats(&walk, &mut slot, &mut |ring: &[u32]| {
            let points: Vec<Point> = ring.iter().map(|&i| pts[i as usize]).collect();
            let s = simplify_ring(&points);
            if s.len() >= 3 {
                result.push(Ring::new(s));
            }
        });
    }
    result
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
