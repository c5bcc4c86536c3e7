//! Edges of the rebuild that leave or arrive at one point in the same direction: they overlap
//! along the shorter one, running the same way, so two rings' insides overlap there or a hole
//! pokes out of its outer. The rebuild reports it as a broken form, for the snap fallback to replace.

use clip_core::Point;

use super::directions::one_way;

/// Edges in the same direction at one point, as [`has_same_way_edges`] finds them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum SameWay {
    None,
    /// Only where an edge back cancelled one of them: two edges one way and one back along a
    /// stretch bound it once (a hole retracing its outer's edge, common in grid unions).
    Retraced,
    /// Two left after opposite edges cancelled: the insides overlap.
    Remaining,
}

/// Whether two edges leave one point, or arrive at one point, in the same direction
/// ([`SameWay`]; `cancelled` are the edges opposite edges cancelled). Ends are compared exactly,
/// so this also catches overlaps of slanted edges that were not split. `shared` are the points
/// left by two edges or more, `outgoing[row[v]..row[v + 1]]` the edges leaving point `v`, and
/// `ring_ends[r]` where ring `r`'s edges end in `edges`: an edge is arrived at by the one before
/// it in its ring. Kept out of line: the rebuild's walk is the hot part.
#[inline(never)]
pub(crate) fn has_same_way_edges(
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
    a == b || one_way(v, pts[a as usize], pts[b as usize])
}
