//! Whether rings meet cleanly at the points they share: the form that a rebuild over retraced
//! edges near rounding can break while every ring stays simple. Exact: comparisons of
//! coordinates and orientation tests only.

use std::cmp::Ordering;

use clip_core::predicates::on_segment;
use clip_core::{Point, Segment};

use super::directions::counter_clockwise_from_east;

/// True when the closed rings `ids[ends[r - 1]..ends[r]]` (ids of `pts`, none repeated in a
/// row) do not meet cleanly at a point that two of them, or one twice, pass through.
///
/// They meet cleanly at such a point `v` when no ring passes it twice and, counter-clockwise
/// round `v`, the ways out of it alternate between a ring's next vertex (the region on its
/// counter-clockwise side) and a ring's previous vertex (the region on its clockwise side), no
/// two point one way (edges overlapping), and no two passes interleave (their rings cross).
/// Alternation alone is not enough: three rings can alternate and still cross. A ring whose
/// edge passes through `v` without a vertex there (a hole touching its outer's edge from
/// inside while another outer touches it from outside: simplification drops the outer's
/// straight-through vertex) passes `v` too: where the rings' own passes do not meet cleanly,
/// such edges' ways are added before the point is judged. Linear in the passes, but for sorting
/// the ways out of each shared point and, only where passes alone do not meet cleanly, one pass
/// over the edges.
pub(crate) fn cross_at_shared_points(pts: &[Point], ids: &[u32], ends: &[usize]) -> bool {
    // Passes by point (compressed rows, in ring order): `at[row[v]..row[v + 1]]`.
    let mut row = vec![0u32; pts.len() + 1];
    for &v in ids {
        row[v as usize + 1] += 1;
    }
    if row.iter().all(|&n| n < 2) {
        return false;
    }
    for v in 0..pts.len() {
        row[v + 1] += row[v];
    }
    let mut fill = row.clone();
    let mut at = vec![0u32; ids.len()];
    for (k, &v) in ids.iter().enumerate() {
        at[fill[v as usize] as usize] = k as u32;
        fill[v as usize] += 1;
    }
    drop(fill);
    let rings = Rings::new(ids, ends);
    // Points whose passes do not meet cleanly, unless an edge through them mends it.
    let mut suspects: Vec<u32> = Vec::new();
    let mut meeting = Meeting::default();
    for v in 0..pts.len() {
        let passes = &at[row[v] as usize..row[v + 1] as usize];
        if passes.len() < 2 {
            continue;
        }
        // Passes are in ring order: one ring passing twice has two in a row.
        if passes.windows(2).any(|w| rings.ring_of[w[0] as usize] == rings.ring_of[w[1] as usize]) {
            return true;
        }
        meeting.clear();
        meeting.add_passes(&rings, passes, pts, ids);
        if !meeting.clean(pts[v]) {
            suspects.push(v as u32);
        }
    }
    if suspects.is_empty() {
        return false;
    }
    // Each suspect again, with the edges passing through it: their ends as ways, their ring
    // (which must not pass the point otherwise: it would meet itself there).
    let mut through: Vec<(u32, Point, Point, u32)> = Vec::new();
    suspects.sort_unstable_by(|&a, &b| pts[a as usize].x.total_cmp(&pts[b as usize].x));
    for k in 0..ids.len() {
        let (_, next) = rings.around(k);
        let (a, b) = (pts[ids[k] as usize], pts[ids[next] as usize]);
        let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
        let first = suspects.partition_point(|&v| pts[v as usize].x < lo);
        for &v in suspects[first..].iter().take_while(|&&v| pts[v as usize].x <= hi) {
            let p = pts[v as usize];
            if p != a && p != b && on_segment(p, Segment::new(a, b)) {
                through.push((v, b, a, rings.ring_of[k]));
            }
        }
    }
    through.sort_unstable_by_key(|t| t.0);
    let mut passing: Vec<u32> = Vec::new();
    suspects.iter().any(|&v| {
        let passes = &at[row[v as usize] as usize..row[v as usize + 1] as usize];
        let first = through.partition_point(|t| t.0 < v);
        let edges = through[first..].iter().take_while(|t| t.0 == v);
        passing.clear();
        passing.extend(passes.iter().map(|&k| rings.ring_of[k as usize]).chain(edges.clone().map(|t| t.3)));
        passing.sort_unstable();
        if passing.windows(2).any(|w| w[0] == w[1]) {
            return true;
        }
        meeting.clear();
        meeting.add_passes(&rings, passes, pts, ids);
        for &(_, next, prev, _) in edges {
            meeting.add(next, prev);
        }
        !meeting.clean(pts[v as usize])
    })
}

/// The rings of [`cross_at_shared_points`]: ring `r` is `ids[start(r)..ends[r]]`, `ring_of[k]`
/// the ring of pass `k`.
struct Rings<'a> {
    ends: &'a [usize],
    ring_of: Vec<u32>,
}

impl<'a> Rings<'a> {
    fn new(ids: &[u32], ends: &'a [usize]) -> Rings<'a> {
        let mut ring_of = vec![0u32; ids.len()];
        let mut start = 0;
        for (r, &end) in ends.iter().enumerate() {
            ring_of[start..end].fill(r as u32);
            start = end;
        }
        Rings { ends, ring_of }
    }

    fn start(&self, r: usize) -> usize {
        if r == 0 { 0 } else { self.ends[r - 1] }
    }

    /// The passes before and after pass `k` in its ring.
    fn around(&self, k: usize) -> (usize, usize) {
        let r = self.ring_of[k] as usize;
        let (start, end) = (self.start(r), self.ends[r]);
        (if k == start { end - 1 } else { k - 1 }, if k + 1 == end { start } else { k + 1 })
    }
}

/// The ways out of one point, each pass's two: far end, pass, and whether it leaves along the
/// ring (towards the next vertex).
#[derive(Default)]
struct Meeting {
    ways: Vec<(Point, u32, bool)>,
    open: Vec<u32>,
}

impl Meeting {
    fn clear(&mut self) {
        self.ways.clear();
    }

    /// The passes `passes` of `rings` (indices into `ids`, ids of `pts`).
    fn add_passes(&mut self, rings: &Rings, passes: &[u32], pts: &[Point], ids: &[u32]) {
        for &k in passes {
            let (prev, next) = rings.around(k as usize);
            self.add(pts[ids[next] as usize], pts[ids[prev] as usize]);
        }
    }

    /// A pass arriving from `prev` and leaving towards `next`.
    fn add(&mut self, next: Point, prev: Point) {
        let pass = (self.ways.len() / 2) as u32;
        self.ways.extend([(next, pass, true), (prev, pass, false)]);
    }

    /// True when the passes meet cleanly at `v` (see [`cross_at_shared_points`]).
    fn clean(&mut self, v: Point) -> bool {
        self.ways.sort_unstable_by(|a, b| counter_clockwise_from_east(v, a.0, b.0));
        let one_way = |w: &[(Point, u32, bool)]| counter_clockwise_from_east(v, w[0].0, w[1].0) == Ordering::Equal;
        if self.ways.windows(2).any(|w| one_way(w) || w[0].2 == w[1].2) {
            return false;
        }
        // A pass's two ways close it; another pass opened between them and not closed crosses it.
        self.open.clear();
        for &(_, pass, _) in &self.ways {
            if self.open.last() == Some(&pass) {
                self.open.pop();
            } else {
                self.open.push(pass);
            }
        }
        self.open.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The rings as distinct points, their ids ring after ring, and where each ring ends.
    fn flat(rings: &[&[(f64, f64)]]) -> (Vec<Point>, Vec<u32>, Vec<usize>) {
        let (mut pts, mut ids, mut ends) = (Vec::new(), Vec::new(), Vec::new());
        for r in rings {
            for &(x, y) in *r {
                let p = Point::new(x, y);
                let id = pts.iter().position(|&q| q == p).unwrap_or_else(|| {
                    pts.push(p);
                    pts.len() - 1
                });
                ids.push(id as u32);
            }
            ends.push(ids.len());
        }
        (pts, ids, ends)
    }

    fn cross(rings: &[&[(f64, f64)]]) -> bool {
        let (pts, ids, ends) = flat(rings);
        cross_at_shared_points(&pts, &ids, &ends)
    }

    #[test]
    fn rings_touching_at_a_corner_or_a_hole_on_its_outer_meet_cleanly() {
        let a: &[(f64, f64)] = &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        let b: &[(f64, f64)] = &[(1.0, 1.0), (2.0, 1.0), (2.0, 2.0), (1.0, 2.0)];
        assert!(!cross(&[a, b]));
        // A clockwise hole touching its outer's bottom edge at a vertex of both, from inside.
        let outer: &[(f64, f64)] = &[(0.0, 0.0), (2.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)];
        let hole: &[(f64, f64)] = &[(2.0, 0.0), (1.0, 1.0), (3.0, 1.0)];
        assert!(!cross(&[outer, hole]));
        // Three squares round one point, each on its own quarter: clean.
        let c: &[(f64, f64)] = &[(0.0, 0.0), (-1.0, 0.0), (-1.0, -1.0), (0.0, -1.0)];
        assert!(!cross(&[a, c, &[(0.0, 0.0), (-0.5, 1.0), (-1.0, 0.5)]]));
        assert!(!cross(&[a]));
    }

    #[test]
    fn rings_crossing_or_overlapping_at_a_shared_point_do_not() {
        // Two counter-clockwise triangles through the origin whose wedges interleave.
        let a: &[(f64, f64)] = &[(0.0, 0.0), (2.0, 1.0), (-2.0, 1.0)];
        let b: &[(f64, f64)] = &[(0.0, 0.0), (1.0, -2.0), (1.0, 2.0)];
        assert!(cross(&[a, b]));
        // One counter-clockwise wedge inside another's: their insides overlap.
        let wide: &[(f64, f64)] = &[(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)];
        let narrow: &[(f64, f64)] = &[(0.0, 0.0), (2.0, 1.0), (1.0, 2.0)];
        assert!(cross(&[wide, narrow]));
        // Two edges leaving the origin one way.
        let along: &[(f64, f64)] = &[(0.0, 0.0), (2.0, 0.0), (2.0, -1.0)];
        assert!(cross(&[wide, along]));
        // One ring passing a point twice (a figure eight).
        assert!(cross(&[&[(0.0, 0.0), (1.0, 1.0), (-1.0, 1.0), (0.0, 0.0), (-1.0, -1.0), (1.0, -1.0)]]));
    }

    #[test]
    fn an_edge_through_the_point_counts_as_a_pass() {
        // The outer's bottom edge passes straight through (2, 0), a vertex of neither: a hole
        // touches it there from inside, another outer from outside. Clean (the grid union case
        // that made the snap fallback run for nothing).
        let outer: &[(f64, f64)] = &[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)];
        let hole: &[(f64, f64)] = &[(2.0, 0.0), (1.0, 1.0), (3.0, 1.0)];
        let below: &[(f64, f64)] = &[(2.0, 0.0), (1.0, -1.0), (3.0, -1.0)];
        assert!(!cross(&[outer, hole, below]));
        // The rings at the point alone would not meet cleanly.
        assert!(cross(&[hole, below]));
        // The same edge running the other way (the outer clockwise) does not mend it.
        let turned: &[(f64, f64)] = &[(0.0, 0.0), (0.0, 4.0), (4.0, 4.0), (4.0, 0.0)];
        assert!(cross(&[turned, hole, below]));
        // A ring pinched onto its own edge there meets itself, whatever the ways say.
        let pinched: &[(f64, f64)] =
            &[(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (3.0, 4.0), (2.0, 0.0), (1.0, 4.0), (0.0, 4.0)];
        assert!(cross(&[pinched, below]));
        // An edge that ends short of the point does not pass through it.
        let short: &[(f64, f64)] = &[(0.0, 0.0), (1.5, 0.0), (4.0, 4.0), (0.0, 4.0)];
        assert!(cross(&[short, hole, below]));
    }

    #[test]
    fn three_passes_alternating_round_a_point_can_still_cross() {
        // Ways out of the origin counter-clockwise from east: a out, b back, c out, a back, b out,
        // c back. They alternate, but a's two ways hold one of b's and one of c's between them.
        let a: &[(f64, f64)] = &[(0.0, 0.0), (1.0, 0.0), (1.0, 2.0), (-1.0, 2.0), (-1.0, 0.5)];
        let b: &[(f64, f64)] = &[(0.0, 0.0), (-1.0, -1.0), (1.0, -1.0), (1.0, 1.0)];
        let c: &[(f64, f64)] = &[(0.0, 0.0), (-1.0, 1.0), (-1.5, 0.0), (0.5, -1.0)];
        let v = Point::new(0.0, 0.0);
        let p = |(x, y): (f64, f64)| Point::new(x, y);
        let mut ways = vec![(p(a[1]), 'a', true), (p(a[4]), 'a', false), (p(b[1]), 'b', true), (p(b[3]), 'b', false)];
        ways.extend([(p(c[1]), 'c', true), (p(c[3]), 'c', false)]);
        ways.sort_by(|x, y| counter_clockwise_from_east(v, x.0, y.0));
        let order: String = ways.iter().map(|w| if w.2 { w.1.to_ascii_uppercase() } else { w.1 }).collect();
        assert_eq!(order, "AbCaBc", "the test's rings are not laid out as the comment says");
        assert!(cross(&[a, b, c]));
    }
}
