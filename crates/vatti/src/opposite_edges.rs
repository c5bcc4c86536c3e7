//! Exactly coincident edges of one operand running opposite ways, dropped before the event sweep.
//!
//! Such a pair separates equal winding numbers: crossing it, one edge adds what the other takes
//! away. So the operand's region is the same without both, under every fill rule, and so is
//! every result. Layers that tile the plane (the countries of a map, a grid of tiles) run every
//! shared border once each way; swept as they are, each border is two edges in the sweep and two
//! output chains that the clean-up joins again. What remains still has as many edges leaving
//! each point as arriving at it, so it closes into rings again.
//!
//! Property used: two edges of one operand with the same two end points, bit for bit, in an
//! operand of several rings. Edges that only overlap in part, or that belong to different
//! operands, are swept as they are.

use std::borrow::Cow;

use clip_core::{Point, Polygons, Ring};

/// `p` without its pairs of opposite coincident edges, as rings; borrowed when it has none.
/// One pass over the edges pairs each with an earlier reverse not yet paired (looked up by hash,
/// confirmed bit for bit); the rings are rebuilt only when some pair cancels, by splicing each
/// pair out of the rings' cyclic edge lists in the order the pairs were found.
pub(crate) fn cancel_opposite_edges(p: &Polygons) -> Cow<'_, Polygons> {
    let n: usize = p.rings.iter().map(|r| r.points.len()).sum();
    // One ring rarely runs back along its own edge, and cancelling is only a saving.
    if p.rings.len() < 2 || n >= ProbeTable::EMPTY as usize {
        return Cow::Borrowed(p);
    }
    // Vertices numbered across the rings; edge `e` runs from vertex `e` to the next on its ring.
    let mut keys: Vec<PointKey> = Vec::with_capacity(n);
    let mut gone = vec![false; n];
    let mut by_edge = ProbeTable::new(n);
    let mut pairs: Vec<(u32, u32)> = Vec::new();
    for ring in &p.rings {
        let first = keys.len();
        keys.extend(ring.points.iter().map(|&q| key(q)));
        let Some(&first_key) = keys.get(first) else { continue };
        let first_hash = point_hash(first_key);
        let (mut a, mut ha) = (first_key, first_hash);
        for e in first..keys.len() {
            let f = if e + 1 == keys.len() { first } else { e + 1 };
            let b = keys[f];
            let hb = if f == first { first_hash } else { point_hash(b) };
            if a != b {
                // Its reverse, else the edge goes in where the search for one ended.
                let is_reverse = |(j, k): (usize, usize)| !gone[j] && keys[j] == b && keys[k] == a;
                if let Some((j, _)) = by_edge.find_or_insert(unordered(ha, hb), e, f, is_reverse) {
                    gone[e] = true;
                    gone[j] = true;
                    pairs.push((j as u32, e as u32));
                }
            }
            (a, ha) = (b, hb);
        }
    }
    if pairs.is_empty() {
        return Cow::Borrowed(p);
    }
    Cow::Owned(Polygons::new(EdgeCycles::of(p).without(&pairs).rings(p, &keys, gone)))
}

/// An operand's edges as cyclic lists, one per ring to begin with: edge `e` runs from vertex `e`
/// (numbered across the rings) to the start of `next[e]`.
struct EdgeCycles {
    next: Vec<u32>,
    prev: Vec<u32>,
}

impl EdgeCycles {
    fn of(p: &Polygons) -> EdgeCycles {
        let n: usize = p.rings.iter().map(|r| r.points.len()).sum();
        let (mut next, mut prev) = (Vec::with_capacity(n), Vec::with_capacity(n));
        for ring in &p.rings {
            let (first, len) = (next.len() as u32, ring.points.len() as u32);
            next.extend((1..=len).map(|i| first + i % len));
            prev.extend((0..len).map(|i| first + (i + len - 1) % len));
        }
        EdgeCycles { next, prev }
    }

    /// Without each pair `(j, e)` of opposite edges (`e` from `a` to `b`, `j` from `b` to `a`):
    /// the edge before `e`, which ends at `a`, goes on with the edge after `j`, which starts
    /// there, and the edge before `j` with the edge after `e`, at `b`. Every edge left still
    /// ends where the next on its list starts, so the lists stay rings. Where the two are
    /// consecutive (a spike) the links written to them are never read again.
    fn without(mut self, pairs: &[(u32, u32)]) -> EdgeCycles {
        for &(j, e) in pairs {
            let (pe, se, pj, sj) =
                (self.prev[e as usize], self.next[e as usize], self.prev[j as usize], self.next[j as usize]);
            self.next[pe as usize] = sj;
            self.prev[sj as usize] = pe;
            self.next[pj as usize] = se;
            self.prev[se as usize] = pj;
        }
        self
    }

    /// The rings left: each list's start points, from its lowest-numbered edge, without the
    /// edges that cancelled (`gone`) and those without length. The points come from `p`, whose
    /// vertices `keys` are, numbered as the edges.
    fn rings(&self, p: &Polygons, keys: &[PointKey], gone: Vec<bool>) -> Vec<Ring> {
        let points: Vec<Point> = p.rings.iter().flat_map(|r| r.points.iter().copied()).collect();
        let n = points.len();
        let mut seen = gone;
        let mut rings = Vec::new();
        let mut walk = Vec::new();
        for first in 0..n {
            if seen[first] {
                continue;
            }
            walk.clear();
            let mut e = first;
            while !seen[e] {
                seen[e] = true;
                let next = self.next[e] as usize;
                if keys[e] != keys[next] {
                    walk.push(points[e]);
                }
                e = next;
            }
            if !walk.is_empty() {
                rings.push(Ring::new(walk.as_slice().to_vec()));
            }
        }
        rings
    }
}

/// A point's bits, with −0 read as 0.
type PointKey = (u64, u64);

fn key(p: Point) -> PointKey {
    ((p.x + 0.0).to_bits(), (p.y + 0.0).to_bits())
}

/// FxHash's multiply-rotate step over the words: the keys are not chosen by an adversary who
/// could gain from collisions, and a keyed hash costs several times more per edge.
fn mix(words: [u64; 2]) -> u64 {
    words.iter().fold(0u64, |h, &w| (h.rotate_left(5) ^ w).wrapping_mul(0x517c_c1b7_2722_0a95))
}

fn point_hash((x, y): PointKey) -> u64 {
    mix([x, y])
}

/// The hash of the edge between points hashed `ha` and `hb`, whichever way it runs: an edge and
/// its reverse are looked for on one probe sequence, so one cache miss an edge looks for the
/// reverse and stores the edge where the table outgrows the cache (a large map's).
fn unordered(ha: u64, hb: u64) -> u64 {
    ha.wrapping_add(hb)
}

/// Pairs of vertex numbers by hash, open addressing with linear probing: no allocation per key,
/// and the full hash kept beside each pair so a probe compares keys only on equal hashes.
struct ProbeTable {
    slots: Vec<(u64, u32, u32)>,
    shift: u32,
}

impl ProbeTable {
    const EMPTY: u32 = u32::MAX;

    /// A table for `n` entries, at most half full.
    fn new(n: usize) -> ProbeTable {
        let bits = (2 * n.max(1)).next_power_of_two().trailing_zeros().max(1);
        ProbeTable { slots: vec![(0, Self::EMPTY, 0); 1 << bits], shift: 64 - bits }
    }

    /// The first pair inserted with `hash` that `is` accepts; else `None`, and `(i, j)` is
    /// inserted with `hash`.
    fn find_or_insert(
        &mut self,
        hash: u64,
        i: usize,
        j: usize,
        mut is: impl FnMut((usize, usize)) -> bool,
    ) -> Option<(usize, usize)> {
        let mask = self.slots.len() - 1;
        let mut s = (hash >> self.shift) as usize;
        loop {
            let (h, a, b) = self.slots[s];
            if a == Self::EMPTY {
                self.slots[s] = (hash, i as u32, j as u32);
                return None;
            }
            if h == hash && is((a as usize, b as usize)) {
                return Some((a as usize, b as usize));
            }
            s = (s + 1) & mask;
        }
    }
}

#[cfg(test)]
mod tests {
    use clip_core::{BoolOp, FillRule, Rect};
    use clip_oracle::polygon::region_area;

    use super::*;

    fn square(x: f64, y: f64) -> Ring {
        Rect::new(x, y, x + 1.0, y + 1.0).to_ring()
    }

    /// `a` and `b` cover the same region under every fill rule.
    fn assert_same_region(a: &Polygons, b: &Polygons) {
        for fill in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative] {
            let layers = [(a, fill), (b, fill)];
            assert_eq!(region_area(&layers, |inside| inside[0] != inside[1]), 0.0, "{fill:?}");
        }
    }

    #[test]
    fn tiles_sharing_edges_become_their_outline() {
        let tiles =
            Polygons::new((0..3).flat_map(|i| (0..2).map(move |j| square(f64::from(i), f64::from(j)))).collect());
        let outline = cancel_opposite_edges(&tiles);
        assert!(matches!(outline, Cow::Owned(_)));
        // 3 x 2 unit squares: the 7 inner edges cancel, 10 outer unit edges remain.
        assert_eq!(outline.rings.iter().map(|r| r.points.len()).sum::<usize>(), 10);
        assert_same_region(&tiles, &outline);
    }

    #[test]
    fn edges_run_the_same_way_or_in_part_stay() {
        // Two squares stacked on one another: coincident, but the same way.
        let twice = Polygons::new(vec![square(0.0, 0.0), square(0.0, 0.0)]);
        assert!(matches!(cancel_opposite_edges(&twice), Cow::Borrowed(_)));
        // Neighbours of different heights share only part of an edge.
        let part = Polygons::new(vec![square(0.0, 0.0), Rect::new(1.0, 0.0, 2.0, 2.0).to_ring()]);
        assert!(matches!(cancel_opposite_edges(&part), Cow::Borrowed(_)));
    }

    #[test]
    fn an_edge_twice_against_its_reverse_once_keeps_one_copy() {
        // Tile (1, 0) stacked twice beside its neighbours: each shared border runs twice one way
        // and once the other, so one copy stays, and the region is unchanged under every rule.
        let mut rings: Vec<Ring> = (0..3).map(|i| square(f64::from(i), 0.0)).collect();
        rings.push(square(1.0, 0.0));
        let tiles = Polygons::new(rings);
        let outline = cancel_opposite_edges(&tiles);
        assert!(matches!(outline, Cow::Owned(_)));
        // 16 edges, 2 pairs cancelled.
        assert_eq!(outline.rings.iter().map(|r| r.points.len()).sum::<usize>(), 12);
        assert_same_region(&tiles, &outline);
    }

    #[test]
    fn random_tilings_with_spikes_and_repeats_keep_their_region() {
        // Unit squares on a 4 x 3 grid, each absent, once, reversed, twice or with a vertex
        // repeated; rings with a spike (an edge out and back, which cancels within its ring) and
        // rings through a shared corner: cancellations chain through rings in every order. The
        // region stays under every rule, the edges left are fewer, and no rebuilt ring repeats a
        // point (keeps an edge without length).
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move |m: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % m
        };
        for _ in 0..300 {
            let mut rings = Vec::new();
            for i in 0..4 {
                for j in 0..3 {
                    let sq = square(f64::from(i), f64::from(j));
                    match next(6) {
                        0 => {}
                        1 => rings.push(sq.reversed()),
                        2 => rings.extend([sq.clone(), sq]),
                        // A repeated vertex: an edge without length.
                        3 => rings.push(Ring::new([&sq.points[..1], &sq.points[..]].concat())),
                        _ => rings.push(sq),
                    }
                }
            }
            if next(2) == 0 {
                let (x, y) = (next(4) as f64, next(3) as f64);
                let p = |dx: f64, dy: f64| Point::new(x + dx, y + dy);
                rings.push(Ring::new(vec![
                    p(0.0, 0.0),
                    p(1.0, 0.0),
                    p(1.0, 1.0),
                    p(1.0, 2.0),
                    p(1.0, 1.0),
                    p(0.0, 1.0),
                ]));
            }
            let tiles = Polygons::new(rings);
            let out = cancel_opposite_edges(&tiles);
            assert_same_region(&tiles, &out);
            let count = |p: &Polygons| p.rings.iter().map(|r| r.points.len()).sum::<usize>();
            assert!(count(&out) <= count(&tiles));
            // Rebuilt rings (the input comes back as it is where nothing cancels).
            let rebuilt = if let Cow::Owned(rings) = &out { &rings.rings[..] } else { &[] };
            for r in rebuilt {
                let n = r.points.len();
                assert!((0..n).all(|k| r.points[k] != r.points[(k + 1) % n]), "{r:?}");
            }
        }
    }

    #[test]
    fn a_square_and_its_reverse_cancel_to_nothing() {
        let both = Polygons::new(vec![square(0.0, 0.0), square(0.0, 0.0).reversed()]);
        assert!(cancel_opposite_edges(&both).rings.is_empty());
    }

    #[test]
    fn results_are_the_same_with_and_without_the_cancelled_edges() {
        use crate::Sweep;
        // A 4 x 4 grid of tiles against a diamond across it, every operation and fill rule.
        let tiles =
            Polygons::new((0..4).flat_map(|i| (0..4).map(move |j| square(f64::from(i), f64::from(j)))).collect());
        let diamond = Polygons::from(Ring::new(vec![
            Point::new(2.0, -0.5),
            Point::new(4.5, 2.0),
            Point::new(2.0, 4.5),
            Point::new(-0.5, 2.0),
        ]));
        for fill in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative] {
            for op in BoolOp::ALL {
                let events = crate::Vatti::sweep_polygons(&tiles, &diamond, op, fill, Sweep::Events);
                let scanbeam = crate::Vatti::sweep_polygons(&tiles, &diamond, op, fill, Sweep::Scanbeam);
                let layers = [(&events, FillRule::NonZero), (&scanbeam, FillRule::NonZero)];
                assert_eq!(region_area(&layers, |inside| inside[0] != inside[1]), 0.0, "{op:?} {fill:?}");
                assert_eq!(events.rings.len(), scanbeam.rings.len(), "{op:?} {fill:?}");
            }
        }
    }
}
