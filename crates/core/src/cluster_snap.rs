//! Merges ring points a few ulps apart into one and routes edges passing that close through it.
//!
//! Where edges nearly pass through a vertex and nearly parallel to its edges, their crossings round
//! to points an ulp or two apart, with edges running between them on either side: a clipper's
//! rings can cross there though each rounded point is within rounding of where it belongs, and
//! sweeping them again rounds new crossings among the same edges (found by the `vatti` fuzz target
//! near (0.87, 7.34) and (5e5, 4e6)). As snap rounding does (J. D. Hobby, *Practical segment
//! intersection with finite precision output*, Computational Geometry: Theory and Applications
//! 13(4):199-214, 1999), every point of such a cluster becomes one point and every edge passing
//! within reach of it goes through it, so rings meet there only at that point. Unlike snap
//! rounding, points are not moved to a grid: only points within [`SNAP_ULPS`] ulps of another move
//! (onto the cluster's lowest point), and only edges that close bend. Limits: clusters chain, so a
//! long run of points each that close to the next becomes one point; and an edge is bent at most
//! a few rounds, each by [`SNAP_ULPS`] ulps of a merged point.

use crate::predicates::orient2d;
use crate::{Point, Ring};

/// How near, in ulps of the larger coordinate magnitude of a point, another point must be (in
/// each coordinate) to merge with it, and an edge to be routed through it. Rounded crossings of
/// nearly parallel edges sit a few ulps from each other: the fuzz inputs' clusters span 3.
pub const SNAP_ULPS: f64 = 4.0;

/// Rounds of routing edges through merged points at most: a routed edge moves by a reach at
/// most and can pass near another merged point only within that.
const MAX_ROUTING_ROUNDS: usize = 4;

/// How far from `p` another point merges with it: [`SNAP_ULPS`] ulps of `p`'s larger coordinate
/// magnitude (at least the smallest normal number's worth).
fn reach(p: Point) -> f64 {
    let magnitude = p.x.abs().max(p.y.abs());
    // The power of two at or below the magnitude, times epsilon: one ulp there.
    let binade = f64::from_bits(magnitude.to_bits() & 0x7ff0_0000_0000_0000);
    SNAP_ULPS * (binade * f64::EPSILON).max(f64::MIN_POSITIVE)
}

/// The points of `rings` with every cluster of points within [`SNAP_ULPS`] ulps of each other
/// (in both coordinates, chained) made one point, and every edge passing that close to such a
/// merged point (strictly between its ends) split there. Rings keep their order; repeated and
/// collinear points are left for the caller to drop. `None` when no two distinct points are that
/// close: there is nothing to snap.
pub fn snap_clusters(rings: &[Ring]) -> Option<Vec<Vec<Point>>> {
    let points: Vec<Point> = rings.iter().flat_map(|r| r.points.iter().copied()).collect();
    let (target, merged) = merge_clusters(&points)?;
    let mut at = 0;
    let mut out: Vec<Vec<Point>> = rings
        .iter()
        .map(|r| {
            let ring = target[at..at + r.len()].iter().map(|&k| points[k]).collect();
            at += r.len();
            ring
        })
        .collect();
    for _ in 0..MAX_ROUTING_ROUNDS {
        if !route_through(&mut out, &merged) {
            break;
        }
    }
    Some(out)
}

/// For each of `points`, the index of the point its cluster merges into, and the merged points
/// (sorted by x); `None` when every cluster is one point (repeats aside). A cluster's point is
/// its lowest (by y, then x), so the result does not depend on the order of the rings.
fn merge_clusters(points: &[Point]) -> Option<(Vec<usize>, Vec<Point>)> {
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_unstable_by(|&a, &b| points[a].x.total_cmp(&points[b].x).then(points[a].y.total_cmp(&points[b].y)));
    // Runs of equal x in `order`, so that a scan along a vertical line skips by binary search.
    let mut runs: Vec<(usize, usize)> = Vec::new();
    for (i, &k) in order.iter().enumerate() {
        match runs.last_mut() {
            Some(run) if points[order[run.0]].x == points[k].x => run.1 = i + 1,
            _ => runs.push((i, i + 1)),
        }
    }
    let mut parent: Vec<usize> = (0..points.len()).collect();
    for (g, &(start, end)) in runs.iter().enumerate() {
        for &k in &order[start..end] {
            let (p, r) = (points[k], reach(points[k]));
            // Points with x in [p.x, p.x + r] and y within r of p.y: this run and those after it.
            for &(s, e) in runs[g..].iter().take_while(|&&(s, _)| points[order[s]].x - p.x <= r) {
                let from = s + order[s..e].partition_point(|&j| points[j].y < p.y - r);
                for &j in order[from..e].iter().take_while(|&&j| points[j].y <= p.y + r) {
                    // Within reach of both, so the merge does not depend on which point scans.
                    if (points[j].x - p.x).abs().max((points[j].y - p.y).abs()) <= reach(points[j]) {
                        union(&mut parent, k, j);
                    }
                }
            }
        }
    }
    // Each cluster's lowest point, by y then x, and whether a distinct point merges into it.
    let lower = |a: usize, b: usize| (points[a].y, points[a].x) < (points[b].y, points[b].x);
    let mut best: Vec<usize> = (0..points.len()).collect();
    for k in 0..points.len() {
        let root = find(&mut parent, k);
        if lower(k, best[root]) {
            best[root] = k;
        }
    }
    let target: Vec<usize> = (0..points.len()).map(|k| best[find(&mut parent, k)]).collect();
    let mut moved = vec![false; points.len()];
    for (k, &t) in target.iter().enumerate() {
        moved[t] |= points[k] != points[t];
    }
    let mut merged: Vec<Point> = (0..points.len()).filter(|&k| moved[k]).map(|k| points[k]).collect();
    if merged.is_empty() {
        return None;
    }
    merged.sort_unstable_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    merged.dedup();
    Some((target, merged))
}

fn find(parent: &mut [usize], mut k: usize) -> usize {
    while parent[k] != k {
        parent[k] = parent[parent[k]];
        k = parent[k];
    }
    k
}

/// Joins the clusters of `a` and `b`.
fn union(parent: &mut [usize], a: usize, b: usize) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    parent[ra.max(rb)] = ra.min(rb);
}

/// Splits every edge of `rings` at each of `merged` (sorted by x) within [`reach`] of it and
/// strictly between its ends, in order along the edge. True when an edge was split.
fn route_through(rings: &mut [Vec<Point>], merged: &[Point]) -> bool {
    let mut split = false;
    for ring in rings.iter_mut() {
        let n = ring.len();
        let mut routed: Vec<Point> = Vec::with_capacity(n);
        let mut inside: Vec<(f64, Point)> = Vec::new();
        for i in 0..n {
            let (a, b) = (ring[i], ring[(i + 1) % n]);
            routed.push(a);
            if a == b {
                continue;
            }
            inside.clear();
            let (lo, hi) = (a.x.min(b.x), a.x.max(b.x));
            let first = merged.partition_point(|h| h.x < lo - reach(*h));
            for &h in merged[first..].iter().take_while(|h| h.x <= hi + reach(**h)) {
                if let Some(t) = passes_within_reach(a, b, h) {
                    inside.push((t, h));
                }
            }
            inside.sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
            split |= !inside.is_empty();
            routed.extend(inside.iter().map(|&(_, h)| h));
        }
        *ring = routed;
    }
    split
}

/// Where along `a -> b` (a parameter in (0, 1)) the point `h` lies when it is within [`reach`]
/// of the edge, strictly between its ends.
fn passes_within_reach(a: Point, b: Point, h: Point) -> Option<f64> {
    if h == a || h == b {
        return None;
    }
    let (d, r) = (b - a, reach(h));
    let len2 = d.dot(d);
    if (h - a).dot(d) <= 0.0 || (h - b).dot(a - b) <= 0.0 {
        return None;
    }
    let t = (h - a).dot(d) / len2;
    // The distance from the line, from an accurate determinant: the edge can be 1e140 long.
    (orient2d(a, b, h).abs() <= r * len2.sqrt()).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn snapped(rings: &[Ring]) -> Option<Vec<Ring>> {
        snap_clusters(rings).map(|rings| rings.into_iter().map(Ring::new).collect())
    }

    fn ring(points: &[(f64, f64)]) -> Ring {
        Ring::new(points.iter().map(|&(x, y)| Point::new(x, y)).collect())
    }

    #[test]
    fn nothing_within_reach_is_left_alone() {
        let square = ring(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let touching = ring(&[(1.0, 1.0), (2.0, 1.0), (2.0, 2.0)]);
        assert!(snapped(&[square, touching]).is_none());
    }

    #[test]
    fn points_an_ulp_apart_merge_and_edges_passing_them_go_through() {
        // Two triangles meeting near (1, 1) at points an ulp apart, and a third ring whose edge
        // passes an ulp below them.
        let up = 1.0 + f64::EPSILON;
        let left = ring(&[(0.0, 0.0), (1.0, 1.0), (0.0, 2.0)]);
        let right = ring(&[(up, 1.0), (2.0, 0.0), (2.0, 2.0)]);
        let under = ring(&[(0.0, 1.0 - f64::EPSILON), (2.0, 1.0 - f64::EPSILON), (1.0, -1.0)]);
        let out = snapped(&[left, right, under]).expect("points to merge");
        assert_eq!(out.len(), 3);
        let meet = Point::new(1.0, 1.0);
        assert!(out[1].points.contains(&meet), "{:?}", out[1]);
        assert!(!out[1].points.contains(&Point::new(up, 1.0)));
        assert!(out[2].points.contains(&meet), "the edge below is routed through: {:?}", out[2]);
    }

    #[test]
    fn far_from_the_origin_the_reach_grows_with_the_magnitude() {
        // At 1e15 an ulp is 0.125: points 0.25 apart merge, points 1 apart do not.
        let a = ring(&[(1e15, 1e15), (1e15 + 64.0, 1e15), (1e15, 1e15 + 64.0)]);
        let b = ring(&[(1e15 + 0.25, 1e15), (1e15 + 0.25, 1e15 - 64.0), (1e15 + 64.0, 1e15 - 64.0)]);
        let out = snapped(&[a.clone(), b]).expect("points to merge");
        assert!(out[1].points.contains(&Point::new(1e15, 1e15)));
        let c = ring(&[(1e15 + 1.0, 1e15), (1e15 + 1.0, 1e15 - 64.0), (1e15 + 64.0, 1e15 - 64.0)]);
        assert!(snapped(&[a, c]).is_none());
    }

    #[test]
    fn a_chain_of_points_an_ulp_apart_becomes_one_and_snapping_again_finds_nothing() {
        // Points an ulp apart in a row along y = 1, each within reach of the next only: they chain
        // into one cluster, merged into the lowest (leftmost here). Merged points are pairwise
        // beyond reach, so a second snap has nothing to do: the repair's snap cannot feed itself.
        let ulp = f64::EPSILON;
        let fan: Vec<Ring> = (0..8)
            .map(|i| {
                let x = 1.0 + 3.0 * ulp * f64::from(i);
                ring(&[(x, 1.0), (x + 1.0, 2.0 + f64::from(i)), (x - 1.0, 2.0 + f64::from(i))])
            })
            .collect();
        let out = snapped(&fan).expect("points to merge");
        assert!(out.iter().all(|r| r.points.contains(&Point::new(1.0, 1.0))), "{out:?}");
        assert!(snapped(&out).is_none());
    }
}
