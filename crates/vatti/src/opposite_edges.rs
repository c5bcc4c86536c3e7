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
/// confirmed bit for bit); the rings are rebuilt only when some pair cancels.
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
    let mut any = false;
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
                let reverse = by_edge.find(joined(hb, ha), |(j, k)| !gone[j] && keys[j] == b && keys[k] == a);
                if let Some((j, _)) = reverse {
                    gone[e] = true;
                    gone[j] = true;
                    any = true;
                } else {
                    by_edge.insert(joined(ha, hb), e, f);
                }
            }
            (a, ha) = (b, hb);
        }
    }
    if !any {
        return Cow::Borrowed(p);
    }
    Edges::of(p, keys).rings_without(gone).map_or(Cow::Borrowed(p), |rings| Cow::Owned(Polygons::new(rings)))
}

/// An operand's vertices in one array, each with its key, its hash and the vertex after it on
/// its ring: edge `e` runs from vertex `e` to vertex `next[e]`.
struct Edges {
    points: Vec<Point>,
    keys: Vec<PointKey>,
    hashes: Vec<u64>,
    next: Vec<u32>,
}

impl Edges {
    /// `keys` are `p`'s vertices' keys, numbered across its rings.
    fn of(p: &Polygons, keys: Vec<PointKey>) -> Edges {
        let mut points = Vec::with_capacity(keys.len());
        let mut next = Vec::with_capacity(keys.len());
        for ring in &p.rings {
            let first = points.len();
            points.extend_from_slice(&ring.points);
            next.extend((first + 1..points.len()).map(|i| i as u32));
            if !ring.points.is_empty() {
                next.push(first as u32);
            }
        }
        let hashes = keys.iter().map(|&k| point_hash(k)).collect();
        Edges { points, keys, hashes, next }
    }

    /// The edges not `gone` (as many leaving each point as arriving) closed into rings, each walk
    /// following its input ring where it can; `None` if a walk gets stuck (it cannot where the
    /// counts balance).
    fn rings_without(&self, mut used: Vec<bool>) -> Option<Vec<Ring>> {
        let n = self.points.len();
        for (e, u) in used.iter_mut().enumerate() {
            *u |= self.keys[e] == self.keys[self.next[e] as usize];
        }
        let mut by_start = ProbeTable::new(used.iter().filter(|g| !**g).count());
        for e in (0..n).filter(|&e| !used[e]) {
            by_start.insert(self.hashes[e], e, e);
        }
        let mut rings = Vec::new();
        // One walk buffer for every ring, each ring then copied out at its length: a vector per
        // ring grown point by point is reallocated about log2(length) times.
        let mut points = Vec::with_capacity(n);
        for first in 0..n {
            if used[first] {
                continue;
            }
            let start = self.keys[first];
            points.clear();
            let mut at = first;
            loop {
                used[at] = true;
                points.push(self.points[at]);
                let end = self.next[at] as usize;
                let end_key = self.keys[end];
                if end_key == start {
                    break;
                }
                at = if used[end] {
                    by_start.find(self.hashes[end], |(j, _)| !used[j] && self.keys[j] == end_key)?.0
                } else {
                    end
                };
            }
            rings.push(Ring::new(points.as_slice().to_vec()));
        }
        Some(rings)
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

/// The hash of the edge from a point hashed `ha` to one hashed `hb`: the way it runs changes it.
fn joined(ha: u64, hb: u64) -> u64 {
    hb ^ ha.rotate_left(17)
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

    fn insert(&mut self, hash: u64, i: usize, j: usize) {
        let mask = self.slots.len() - 1;
        let mut s = (hash >> self.shift) as usize;
        while self.slots[s].1 != Self::EMPTY {
            s = (s + 1) & mask;
        }
        self.slots[s] = (hash, i as u32, j as u32);
    }

    /// The first pair inserted with `hash` that `is` accepts.
    fn find(&self, hash: u64, mut is: impl FnMut((usize, usize)) -> bool) -> Option<(usize, usize)> {
        let mask = self.slots.len() - 1;
        let mut s = (hash >> self.shift) as usize;
        loop {
            let (h, i, j) = self.slots[s];
            if i == Self::EMPTY {
                return None;
            }
            let pair = (i as usize, j as usize);
            if h == hash && is(pair) {
                return Some(pair);
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
