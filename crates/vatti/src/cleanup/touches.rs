//! Which output rings touch (share a point with another ring or visit one twice, or have a
//! vertex inside a horizontal edge), and an id per distinct output point, found from the order
//! the sweep emitted the points.
//!
//! The sweep emits points scanline by scanline, so where the emission order is non-decreasing
//! in y, equal points are emitted within one run of equal y, and so are a horizontal edge's ends
//! and every vertex inside it: only those short runs are compared, with no global sort. Where
//! crossings at nearly one height were taken out of y order, every point is sorted instead.
//!
//! Slanted edges are not split: a vertex on a slanted output edge is on its input edge (the
//! output has the exact arrangement's form, `rounding_certificate`), and the sweep put it into
//! the edge's chain.

use clip_core::Point;

use crate::bounds::NONE;
use crate::raw_rings::RawRings;
use crate::scanbeam::height_key;
use crate::small_sort::insertion_sorted_by;

/// A horizontal edge (`ring`, `edge`: the edge from the ring's vertex `edge` to the next) with
/// vertices strictly inside it: their point ids in the edge's direction, at `inside` in
/// [`Touches::split_points`] (one buffer for all, not an allocation per edge).
#[derive(Debug, PartialEq)]
pub(crate) struct SplitEdge {
    pub ring: usize,
    pub edge: usize,
    pub inside: std::ops::Range<usize>,
}

/// The rings to rebuild, the horizontal edges to split (in ring and edge order), and the
/// distinct points: `ids[k]` is point `k`'s index in `distinct`. The value is reused between
/// clips (its buffers kept).
#[derive(Debug, Default)]
pub(crate) struct Touches {
    pub touched: Vec<bool>,
    pub splits: Vec<SplitEdge>,
    /// The split edges' inside points (see [`SplitEdge`]).
    pub split_points: Vec<u32>,
    /// The rings of the vertices inside split edges, once per vertex.
    inside_rings: Vec<u32>,
    pub ids: Vec<u32>,
    /// The distinct points, ordered by y then x: both passes number them in that order.
    pub distinct: Vec<Point>,
    /// The points visited more than once, each as a run of its visits (point indices) in
    /// `shared`, run `i` ending at `shared_ends[i]`.
    pub shared: Vec<u32>,
    pub shared_ends: Vec<u32>,
    /// Work buffers: point index by emission stamp, ring of every point, and one run of equal
    /// y by x.
    slot: Vec<u32>,
    ring: Vec<u32>,
    run: Vec<(f64, u32)>,
    /// Every point as (y, x, index) by y then x, for [`split_edges`].
    sorted: Vec<(f64, f64, u32)>,
}

impl Touches {
    /// Finds them from the emission order, or by sorting every point when that order is not
    /// monotone in y; whatever this value held before is replaced.
    pub(crate) fn find(&mut self, raw: &RawRings) {
        if !self.by_emission_order(raw) {
            self.by_sorting(raw);
        }
    }

    /// Every point into `sorted` as (y, x, index), by its distinct point's id, so by y then x
    /// ([`Touches::distinct`]): a counting sort on the ids, which are dense.
    fn points_by_id(&mut self, raw: &RawRings) {
        let mut starts = vec![0u32; self.distinct.len() + 1];
        for &id in &self.ids {
            starts[id as usize + 1] += 1;
        }
        for i in 1..starts.len() {
            starts[i] += starts[i - 1];
        }
        self.sorted.clear();
        self.sorted.resize(raw.points.len(), (0.0, 0.0, 0));
        for (k, &id) in self.ids.iter().enumerate() {
            let p = self.distinct[id as usize];
            self.sorted[starts[id as usize] as usize] = (p.y, p.x, k as u32);
            starts[id as usize] += 1;
        }
        debug_assert!(
            self.sorted.windows(2).all(|w| w[0].0 < w[1].0 || (w[0].0 == w[1].0 && w[0].1 <= w[1].1)),
            "distinct points are numbered by y then x"
        );
    }

    /// Empties the results for `raw`: nothing touched, no splits, ids to be filled.
    fn reset(&mut self, raw: &RawRings) {
        self.touched.clear();
        self.touched.resize(raw.len(), false);
        self.splits.clear();
        self.split_points.clear();
        self.inside_rings.clear();
        self.ids.clear();
        self.ids.resize(raw.points.len(), 0);
        self.distinct.clear();
        self.shared.clear();
        self.shared_ends.clear();
        ring_of(raw, &mut self.ring);
    }

    /// The ring of point `k` (after [`Touches::find`]).
    #[inline]
    pub(crate) fn ring_of(&self, k: usize) -> usize {
        self.ring[k] as usize
    }

    /// The indices of the points before and after point `k` in its ring (after [`Touches::find`]).
    #[inline]
    pub(crate) fn around(&self, raw: &RawRings, k: usize) -> (usize, usize) {
        let r = self.ring[k] as usize;
        let (start, end) = (raw.start(r), raw.ends[r]);
        (if k == start { end - 1 } else { k - 1 }, if k + 1 == end { start } else { k + 1 })
    }

    /// The touched rings that share a point, directly or through other rings, with a ring that
    /// has an edge to split or a vertex inside another's edge: the rings the rebuild must walk.
    /// The other touched rings meet them nowhere, so they can be walked apart.
    pub(crate) fn rings_to_split(&self, raw: &RawRings) -> Vec<bool> {
        // Rings joined by their shared points (union-find, halving the paths).
        let mut root: Vec<u32> = (0..raw.len() as u32).collect();
        fn find(root: &mut [u32], mut r: u32) -> u32 {
            while root[r as usize] != r {
                root[r as usize] = root[root[r as usize] as usize];
                r = root[r as usize];
            }
            r
        }
        let mut from = 0;
        for &end in &self.shared_ends {
            let visits = &self.shared[from..end as usize];
            from = end as usize;
            let first = find(&mut root, self.ring[visits[0] as usize]);
            for &k in &visits[1..] {
                let other = find(&mut root, self.ring[k as usize]);
                root[other as usize] = first;
            }
        }
        let mut split = vec![false; raw.len()];
        for r in self.splits.iter().map(|s| s.ring as u32).chain(self.inside_rings.iter().copied()) {
            split[find(&mut root, r) as usize] = true;
        }
        (0..raw.len()).map(|r| self.touched[r] && split[find(&mut root, r as u32) as usize]).collect()
    }

    /// Bytes the buffers hold (their capacity; split lists not counted).
    pub(crate) fn held_bytes(&self) -> usize {
        use std::mem::size_of;
        self.touched.capacity()
            + self.splits.capacity() * size_of::<SplitEdge>()
            + 4 * (self.split_points.capacity() + self.inside_rings.capacity())
            + 4 * (self.ids.capacity() + self.slot.capacity() + self.ring.capacity())
            + 4 * (self.shared.capacity() + self.shared_ends.capacity())
            + self.distinct.capacity() * size_of::<Point>()
            + self.run.capacity() * size_of::<(f64, u32)>()
            + self.sorted.capacity() * size_of::<(f64, f64, u32)>()
    }
}

/// Ring index of every point, into `ring`.
fn ring_of(raw: &RawRings, ring: &mut Vec<u32>) {
    ring.clear();
    ring.reserve(raw.points.len());
    for i in 0..raw.len() {
        ring.resize(raw.ends[i], i as u32);
    }
}

impl Touches {
    /// The touches from runs of equal y in emission order; false (and nothing found) when that
    /// order goes down in y.
    fn by_emission_order(&mut self, raw: &RawRings) -> bool {
        let mut slot = std::mem::take(&mut self.slot);
        slot.clear();
        slot.resize(raw.stamps, NONE);
        for (k, &s) in raw.emitted.iter().enumerate() {
            slot[s as usize] = k as u32;
        }
        self.reset(raw);
        let (ring, mut run) = (std::mem::take(&mut self.ring), std::mem::take(&mut self.run));
        // One pass in emission order, a run of equal y at a time.
        let (mut y, mut seen, mut monotone) = (f64::NEG_INFINITY, 0, true);
        run.clear();
        for &k in slot.iter().filter(|&&k| k != NONE) {
            let p = raw.points[k as usize];
            if p.y != y {
                if p.y < y {
                    monotone = false;
                    break;
                }
                self.take_run(raw, &ring, &mut run);
                y = p.y;
            }
            run.push((p.x, k));
            seen += 1;
        }
        // Every point stamped once (the sweep's stamps are distinct; this guards the reading).
        let found = monotone && seen == raw.points.len();
        if found {
            self.take_run(raw, &ring, &mut run);
            self.splits.sort_unstable_by_key(|s| (s.ring, s.edge));
        }
        (self.slot, self.ring, self.run) = (slot, ring, run);
        found
    }

    /// The distinct points of one run of equal y (`run`, emptied: x and point index), the points
    /// shared in it, and its horizontal edges with vertices inside. Most runs are one point,
    /// named here without a call.
    #[inline]
    fn take_run(&mut self, raw: &RawRings, ring: &[u32], run: &mut Vec<(f64, u32)>) {
        match run[..] {
            [] => {}
            [(_, k)] => {
                self.ids[k as usize] = self.distinct.len() as u32;
                self.distinct.push(raw.points[k as usize]);
                run.clear();
            }
            _ => self.take_long_run(raw, ring, run),
        }
    }

    /// [`Touches::take_run`] of two points or more.
    #[inline(never)]
    fn take_long_run(&mut self, raw: &RawRings, ring: &[u32], run: &mut Vec<(f64, u32)>) {
        if !insertion_sorted_by(run, |a, b| a.0.total_cmp(&b.0).is_lt()) {
            // The run comes in emission order, ascending in x over long stretches: the stable
            // sort merges those stretches, and integer keys compare cheaper than the floats.
            run.sort_by_key(|a| height_key(a.0));
        }
        for equal in run.chunk_by(|a, b| a.0 == b.0) {
            self.name_point(raw, ring, equal.iter().map(|&(_, k)| k));
        }
        for &(_, k) in run.iter() {
            let r = ring[k as usize] as usize;
            let next = if k as usize + 1 == raw.ends[r] { raw.start(r) } else { k as usize + 1 };
            let (a, b) = (raw.points[k as usize], raw.points[next]);
            if a.y != b.y {
                continue;
            }
            let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
            let from = run.partition_point(|&(x, _)| x <= lo);
            let start = self.split_points.len();
            for &(_, j) in run[from..].iter().take_while(|&&(x, _)| x < hi) {
                self.touched[ring[j as usize] as usize] = true;
                self.inside_rings.push(ring[j as usize]);
                let id = self.ids[j as usize];
                if self.split_points.len() == start || self.split_points.last() != Some(&id) {
                    self.split_points.push(id);
                }
            }
            if self.split_points.len() == start {
                continue;
            }
            self.touched[r] = true;
            if a.x > b.x {
                self.split_points[start..].reverse();
            }
            let inside = start..self.split_points.len();
            self.splits.push(SplitEdge { ring: r, edge: k as usize - raw.start(r), inside });
        }
        run.clear();
    }

    /// Gives the visits (point indices, at least one) of one distinct point its id, and shares
    /// them when there are several.
    #[inline]
    fn name_point(&mut self, raw: &RawRings, ring: &[u32], visits: impl Iterator<Item = u32> + Clone) {
        let id = self.distinct.len() as u32;
        let mut count = 0;
        for k in visits.clone() {
            if count == 0 {
                self.distinct.push(raw.points[k as usize]);
            }
            self.ids[k as usize] = id;
            count += 1;
        }
        if count > 1 {
            self.share(ring, visits);
        }
    }

    /// Records the visits (point indices) of one point visited more than once, and marks their
    /// rings touched.
    fn share(&mut self, ring: &[u32], visits: impl Iterator<Item = u32>) {
        for k in visits {
            self.touched[ring[k as usize] as usize] = true;
            self.shared.push(k);
        }
        self.shared_ends.push(self.shared.len() as u32);
    }

    /// The touches by sorting every point by y then x (exact keys, so equal points come
    /// together), which numbers the distinct points in that order too.
    fn by_sorting(&mut self, raw: &RawRings) {
        self.reset(raw);
        let t = self;
        let ring = std::mem::take(&mut t.ring);
        // `+ 0.0` reads -0 as 0; `height_key` orders as the floats do.
        let mut keyed: Vec<((i64, i64), u32)> = raw
            .points
            .iter()
            .enumerate()
            .map(|(k, &p)| ((height_key(p.y + 0.0), height_key(p.x + 0.0)), k as u32))
            .collect();
        keyed.sort_unstable();
        for same in keyed.chunk_by(|a, b| a.0 == b.0) {
            t.name_point(raw, &ring, same.iter().map(|&(_, k)| k));
        }
        drop(keyed);
        if has_horizontal(raw) {
            t.points_by_id(raw);
            t.splits =
                split_edges(raw, &ring, &mut t.touched, &t.ids, (&mut t.split_points, &mut t.inside_rings), &t.sorted);
        }
        t.ring = ring;
    }
}

/// Whether some ring has a horizontal edge.
fn has_horizontal(raw: &RawRings) -> bool {
    (0..raw.len()).any(|i| {
        let r = raw.ring(i);
        (0..r.len()).any(|k| r[k].y == r[(k + 1) % r.len()].y)
    })
}

/// Every horizontal edge with vertices strictly inside it, in ring and edge order, their inside
/// points appended to `points` (emptied first); its ring and the vertices' rings are marked
/// touched. `by_y`: every point as (y, x, index), by y then x.
fn split_edges(
    raw: &RawRings,
    ring: &[u32],
    touched: &mut [bool],
    ids: &[u32],
    (points, inside_rings): (&mut Vec<u32>, &mut Vec<u32>),
    by_y: &[(f64, f64, u32)],
) -> Vec<SplitEdge> {
    points.clear();
    inside_rings.clear();
    let mut splits = Vec::new();
    let mut inside = Vec::new();
    for ri in 0..raw.len() {
        let r = raw.ring(ri);
        let n = r.len();
        for i in 0..n {
            let (a, b) = (r[i], r[(i + 1) % n]);
            let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
            inside.clear();
            if a.y == b.y {
                let start = by_y.partition_point(|&(y, x, _)| y < a.y || (y == a.y && x <= lo));
                for &(_, _, k) in by_y[start..].iter().take_while(|&&(y, x, _)| y == a.y && x < hi) {
                    inside.push(k);
                }
                if a.x > b.x {
                    inside.reverse();
                }
            }
            if inside.is_empty() {
                continue;
            }
            touched[ri] = true;
            for &k in &inside {
                touched[ring[k as usize] as usize] = true;
                inside_rings.push(ring[k as usize]);
            }
            let start = points.len();
            for &k in &inside {
                let id = ids[k as usize];
                if points.len() == start || points.last() != Some(&id) {
                    points.push(id);
                }
            }
            splits.push(SplitEdge { ring: ri, edge: i, inside: start..points.len() });
        }
    }
    splits
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ring(points: &[(f64, f64)]) -> Vec<Point> {
        points.iter().map(|&(x, y)| Point::new(x, y)).collect()
    }

    /// Both ways agree, on rings stamped in y order (ids may differ, but not which are equal).
    fn both(rings: Vec<Vec<Point>>) -> Touches {
        let raw = RawRings::from_rings(rings);
        let mut fast = Touches::default();
        assert!(fast.by_emission_order(&raw), "stamped in y order");
        let mut sorted = Touches::default();
        sorted.by_sorting(&raw);
        assert_eq!((&fast.touched, fast.distinct.len()), (&sorted.touched, sorted.distinct.len()));
        for k in 0..raw.points.len() {
            assert_eq!(fast.distinct[fast.ids[k] as usize], raw.points[k]);
            assert_eq!(sorted.distinct[sorted.ids[k] as usize], raw.points[k]);
        }
        let inside = |t: &Touches| -> Vec<(usize, usize, Vec<Point>)> {
            t.splits
                .iter()
                .map(|s| {
                    (s.ring, s.edge, t.split_points[s.inside.clone()].iter().map(|&i| t.distinct[i as usize]).collect())
                })
                .collect()
        };
        assert_eq!(inside(&fast), inside(&sorted));
        fast
    }

    #[test]
    fn shared_points_and_horizontal_splits_are_found_both_ways() {
        let top = ring(&[(0.0, 0.0), (2.0, 0.0), (2.0, 1.0), (0.0, 1.0)]);
        let bottom = ring(&[(1.0, -1.0), (3.0, -1.0), (3.0, 0.0), (1.0, 0.0)]);
        let apart = ring(&[(10.0, 0.0), (11.0, 0.0), (11.0, 1.0)]);
        let t = both(vec![top, bottom, apart]);
        assert_eq!(t.touched, vec![true, true, false]);
        assert_eq!(t.splits.len(), 2);
        let bow = ring(&[(0.0, 0.0), (1.0, 1.0), (2.0, 0.0), (2.0, 2.0), (1.0, 1.0), (0.0, 2.0)]);
        let corner = ring(&[(2.0, 2.0), (3.0, 2.0), (3.0, 3.0)]);
        let t = both(vec![bow, corner]);
        assert_eq!(t.touched, vec![true, true]);
        assert!(t.splits.is_empty());
    }

    #[test]
    fn emission_out_of_y_order_falls_back_to_sorting() {
        let mut raw = RawRings::from_rings(vec![ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)])]);
        raw.emitted.reverse();
        assert!(!Touches::default().by_emission_order(&raw));
        let mut t = Touches::default();
        t.find(&raw);
        assert_eq!(t.touched, vec![false]);
    }
}
