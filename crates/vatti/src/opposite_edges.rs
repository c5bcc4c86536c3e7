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
/// When nothing cancels (the common case) this is one pass over the vertices
/// ([`has_opposite_pair`]); the rings are rebuilt only when something does.
pub(crate) fn cancel_opposite_edges(p: &Polygons) -> Cow<'_, Polygons> {
    // One ring rarely runs back along its own edge, and cancelling is only a saving.
    if p.rings.len() < 2 || !has_opposite_pair(p) {
        return Cow::Borrowed(p);
    }
    let edges: Vec<(Point, Point)> = p
        .rings
        .iter()
        .flat_map(|r| {
            let n = r.points.len();
            (0..n).map(move |i| (r.points[i], r.points[(i + 1) % n]))
        })
        .filter(|(a, b)| key(*a) != key(*b))
        .collect();
    let mut by_edge = ProbeTable::new(edges.len());
    for (i, (a, b)) in edges.iter().enumerate() {
        by_edge.insert(edge_hash(*a, *b), i);
    }
    // Each edge cancels with one reverse edge not yet cancelled, in the input's order.
    let mut cancelled = vec![false; edges.len()];
    let mut any = false;
    for (i, &(a, b)) in edges.iter().enumerate() {
        if cancelled[i] {
            continue;
        }
        let (ka, kb) = (key(a), key(b));
        let reverse = by_edge
            .candidates(edge_hash(b, a))
            .find(|&j| !cancelled[j] && key(edges[j].0) == kb && key(edges[j].1) == ka);
        if let Some(j) = reverse {
            cancelled[i] = true;
            cancelled[j] = true;
            any = true;
        }
    }
    if !any {
        return Cow::Borrowed(p);
    }
    let kept: Vec<(Point, Point)> = edges.iter().zip(&cancelled).filter(|(_, c)| !**c).map(|(e, _)| *e).collect();
    rings_of(&kept).map_or(Cow::Borrowed(p), |rings| Cow::Owned(Polygons::new(rings)))
}

/// Whether some edge of `p` may meet its reverse: one pass, each edge looking up its reverse's
/// hash among the edges before it (both hashes from the end points' hashes), then inserting its
/// own. Only hashes are kept, so a collision of 64-bit hashes says yes where the answer is no,
/// which [`cancel_opposite_edges`] then finds exactly.
fn has_opposite_pair(p: &Polygons) -> bool {
    let n: usize = p.rings.iter().map(|r| r.points.len()).sum();
    let bits = (2 * n.max(1)).next_power_of_two().trailing_zeros().max(1);
    let (mask, shift) = ((1usize << bits) - 1, 64 - bits);
    // 0 marks an empty slot; a hash of 0 is stored as 1.
    let mut slots = vec![0u64; 1 << bits];
    for ring in &p.rings {
        let Some(&last) = ring.points.last() else { continue };
        let (mut a, mut ha) = (key(last), point_hash(last));
        for &q in &ring.points {
            let (b, hb) = (key(q), point_hash(q));
            if a != b {
                let reverse = joined(hb, ha).max(1);
                let mut s = (reverse >> shift) as usize;
                while slots[s] != 0 {
                    if slots[s] == reverse {
                        return true;
                    }
                    s = (s + 1) & mask;
                }
                let forward = joined(ha, hb).max(1);
                let mut s = (forward >> shift) as usize;
                while slots[s] != 0 {
                    s = (s + 1) & mask;
                }
                slots[s] = forward;
            }
            (a, ha) = (b, hb);
        }
    }
    false
}

/// Closes `edges` (as many leaving each point as arriving) into rings, following the input's
/// order where it can; `None` if a walk gets stuck (it cannot where the counts balance).
fn rings_of(edges: &[(Point, Point)]) -> Option<Vec<Ring>> {
    let mut by_start = ProbeTable::new(edges.len());
    for (i, (a, _)) in edges.iter().enumerate() {
        by_start.insert(point_hash(*a), i);
    }
    let mut used = vec![false; edges.len()];
    let mut rings = Vec::new();
    for first in 0..edges.len() {
        if used[first] {
            continue;
        }
        let start = key(edges[first].0);
        let mut points = Vec::new();
        let mut at = first;
        loop {
            used[at] = true;
            points.push(edges[at].0);
            let end = edges[at].1;
            if key(end) == start {
                break;
            }
            at = match edges.get(at + 1) {
                Some((a, _)) if !used[at + 1] && key(*a) == key(end) => at + 1,
                _ => by_start.candidates(point_hash(end)).find(|&j| !used[j] && key(edges[j].0) == key(end))?,
            };
        }
        rings.push(Ring::new(points));
    }
    Some(rings)
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

/// The edge from `a` to `b`: the way it runs changes the hash.
fn edge_hash(a: Point, b: Point) -> u64 {
    joined(point_hash(a), point_hash(b))
}

/// The hash of the edge from a point hashed `ha` to one hashed `hb`.
fn joined(ha: u64, hb: u64) -> u64 {
    hb ^ ha.rotate_left(17)
}

fn point_hash(a: Point) -> u64 {
    let (ax, ay) = key(a);
    mix([ax, ay])
}

/// Indices by hash, open addressing with linear probing: no allocation per key.
struct ProbeTable {
    slots: Vec<u32>,
    shift: u32,
}

impl ProbeTable {
    const EMPTY: u32 = u32::MAX;

    /// A table for `n` entries, at most half full.
    fn new(n: usize) -> ProbeTable {
        let bits = (2 * n.max(1)).next_power_of_two().trailing_zeros().max(1);
        ProbeTable { slots: vec![Self::EMPTY; 1 << bits], shift: 64 - bits }
    }

    fn insert(&mut self, hash: u64, index: usize) {
        let mask = self.slots.len() - 1;
        let mut s = (hash >> self.shift) as usize;
        while self.slots[s] != Self::EMPTY {
            s = (s + 1) & mask;
        }
        self.slots[s] = index as u32;
    }

    /// The indices inserted with `hash`, and others that share its probe run.
    fn candidates(&self, hash: u64) -> impl Iterator<Item = usize> + '_ {
        let mask = self.slots.len() - 1;
        let first = (hash >> self.shift) as usize;
        (0..self.slots.len())
            .map(move |k| self.slots[(first + k) & mask])
            .take_while(|&i| i != Self::EMPTY)
            .map(|i| i as usize)
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

    #[test]
    fn tiles_sharing_edges_become_their_outline() {
        let tiles =
            Polygons::new((0..3).flat_map(|i| (0..2).map(move |j| square(f64::from(i), f64::from(j)))).collect());
        let outline = cancel_opposite_edges(&tiles);
        assert!(matches!(outline, Cow::Owned(_)));
        // 3 x 2 unit squares: the 7 inner edges cancel, 10 outer unit edges remain.
        assert_eq!(outline.rings.iter().map(|r| r.points.len()).sum::<usize>(), 10);
        for fill in [FillRule::EvenOdd, FillRule::NonZero, FillRule::Positive, FillRule::Negative] {
            let layers = [(&tiles, fill), (&*outline, fill)];
            assert_eq!(region_area(&layers, |inside| inside[0] != inside[1]), 0.0, "{fill:?}");
        }
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
