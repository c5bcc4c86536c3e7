//! The clean-up's general walk: the touched rings taken apart into directed edges (horizontal
//! edges split at the vertices inside them), opposite edges
//! cancelled, and the rest walked again, leaving each point by the edge that bounds the same
//! corner of the region as the way in: the first one clockwise from the way back.

use clip_core::Point;

use super::directions::clockwise_before;
use super::simple_loops::split_repeats;
use super::touches::Touches;
use crate::raw_rings::RawRings;

/// Rebuilds the rings of `rings` marked in `walked` (touched rings, every one with an edge to
/// split among them, sharing no point with the others) into simple rings, handed to `emit` as
/// points (in the order of the edges they start from).
pub(crate) fn rebuild(rings: &RawRings, touches: &Touches, walked: &[bool], emit: &mut impl FnMut(&[Point])) {
    let Touches { splits, split_points, ids, distinct: pts, .. } = touches;
    // Every vertex visit in ring order, as point ids, horizontals split at the vertices inside.
    let inside: usize = splits.iter().map(|s| s.inside.len()).sum();
    let mut visits: Vec<u32> = Vec::with_capacity(rings.points.len() + inside);
    let mut ring_ends: Vec<usize> = Vec::with_capacity(rings.len());
    let mut next_split = splits.iter().peekable();
    for ri in (0..rings.len()).filter(|&ri| walked[ri]) {
        let start = rings.start(ri);
        for i in 0..rings.ring(ri).len() {
            visits.push(ids[start + i]);
            while next_split.next_if(|s| (s.ring, s.edge) < (ri, i)).is_some() {}
            if let Some(s) = next_split.next_if(|s| (s.ring, s.edge) == (ri, i)) {
                visits.extend_from_slice(&split_points[s.inside.clone()]);
            }
        }
        ring_ends.push(visits.len());
    }
    // The directed edges between them.
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(visits.len());
    let mut first = 0;
    for end in ring_ends {
        for k in first..end {
            let (from, to) = (visits[k], visits[if k + 1 == end { first } else { k + 1 }]);
            if from != to {
                edges.push((from, to));
            }
        }
        first = end;
    }
    drop(visits);
    // Edges by start point (compressed rows, in edge order).
    let mut row = vec![0u32; pts.len() + 1];
    for &(a, _) in &edges {
        row[a as usize + 1] += 1;
    }
    for v in 0..pts.len() {
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
    let mut slot = vec![usize::MAX; pts.len()];
    let mut walk: Vec<u32> = Vec::new();
    let mut stack: Vec<u32> = Vec::new();
    let mut points: Vec<Point> = Vec::new();
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
            points.clear();
            points.extend(ring.iter().map(|&i| pts[i as usize]));
            emit(&points);
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
