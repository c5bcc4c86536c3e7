//! A four-way bounding-box hierarchy over runs of consecutive window edges.

use core::ops::Range;

use clip_core::{Point, WindowRings};

/// Window edges per leaf: a leaf is a run of at most this many consecutive edges of one ring.
/// Measured on `lines-large` and the beyond-the-paper windows (instructions and time per
/// segment): 16 is within a few percent of 8 and 32, and needs fewer nodes than 8. Measured again
/// with the branch-free box tests (wang_ns): 8 and 32 are 5-15% slower on wang-t4 at 50 edges.
pub(crate) const LEAF_EDGES: usize = 16;

/// Children per node.
pub(crate) const WAYS: usize = 4;

/// Rows of [`Node::sides`]: a box's least x, least y, greatest x and greatest y. A row's index
/// can be computed (a box test picks the rows of the corner it needs from the ray's direction,
/// without a branch).
pub(crate) const MIN_X: usize = 0;
pub(crate) const MIN_Y: usize = 1;
pub(crate) const MAX_X: usize = 2;
pub(crate) const MAX_Y: usize = 3;

/// One node: the boxes of up to four children side by side (each coordinate in its own array,
/// so the four tests are independent and vectorise), two whole cache lines. Which node or leaf
/// each child is follows from the node's index (see [`EdgeTree`]).
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub(crate) struct Node {
    /// Per row ([`MIN_X`], [`MIN_Y`], [`MAX_X`], [`MAX_Y`]), per child: that side of the child's
    /// box (exact vertex coordinates; an empty box for unused slots).
    pub sides: [[f64; WAYS]; 4],
}

/// The hierarchy: leaves are runs of [`LEAF_EDGES`] consecutive edges of one ring in ring order,
/// so a leaf's box hugs its piece of the boundary; nodes group four consecutive leaves, or four
/// consecutive nodes, level by level up to the root, every leaf at the same depth.
///
/// The nodes are laid out as a four-way heap, level after level: the children of node `k` are
/// nodes `4 k + 1 + i`, or, on the lowest level (from [`EdgeTree::lowest`] on), leaves
/// `4 (k - lowest) + i`. A walk then has the next node's address from its parent's test alone
/// (against a large window a walk is a chain of dependent reads and tests, and a stored child
/// index was one more read in it), and every walk down to a leaf takes as many steps as any
/// other, which the branch predictor learns.
#[derive(Clone, Debug)]
pub(crate) struct EdgeTree {
    /// The nodes, the root first.
    pub nodes: Vec<Node>,
    /// Per node: bit `i` set when slot `i` holds a child (a leaf, or a node over some leaf).
    pub present: Vec<u8>,
    /// The index of the first node of the lowest level, whose children are leaves.
    pub lowest: u32,
    /// Each leaf's edges: edge `i` runs from vertex `i` to `i + 1`.
    pub leaves: Vec<Range<u32>>,
}

impl EdgeTree {
    /// Builds the tree over `rings`' edges: O(n) time, about `n / (3 LEAF_EDGES)` nodes.
    pub fn new(rings: &WindowRings) -> EdgeTree {
        let mut leaves: Vec<Range<u32>> = Vec::new();
        for ring in &rings.rings {
            let mut start = ring.start;
            while start < ring.end {
                let end = (start + LEAF_EDGES).min(ring.end);
                leaves.push(start as u32..end as u32);
                start = end;
            }
        }
        let boxes: Vec<[f64; 4]> =
            leaves.iter().map(|r| bounds_of(&rings.points[r.start as usize..=r.end as usize])).collect();
        // Levels above the lowest are complete; the lowest holds one node per four leaves.
        let lowest_count = leaves.len().div_ceil(WAYS).max(1);
        let (mut lowest, mut width) = (0, 1);
        while width < lowest_count {
            lowest += width;
            width *= WAYS;
        }
        let count = lowest + lowest_count;
        let empty = Node {
            sides: [[f64::INFINITY; WAYS], [f64::INFINITY; WAYS], [f64::NEG_INFINITY; WAYS], [f64::NEG_INFINITY; WAYS]],
        };
        let (mut nodes, mut present, mut totals) = (vec![empty; count], vec![0u8; count], vec![EMPTY; count]);
        // Children before parents: every child's index is above its parent's.
        for k in (0..count).rev() {
            for i in 0..WAYS {
                let child = if k >= lowest {
                    let leaf = WAYS * (k - lowest) + i;
                    (leaf < leaves.len()).then(|| boxes[leaf])
                } else {
                    let c = WAYS * k + 1 + i;
                    (c < count && present[c] != 0).then(|| totals[c])
                };
                if let Some(b) = child {
                    let node = &mut nodes[k];
                    (node.sides[MIN_X][i], node.sides[MIN_Y][i], node.sides[MAX_X][i], node.sides[MAX_Y][i]) =
                        (b[0], b[1], b[2], b[3]);
                    present[k] |= 1 << i;
                    totals[k] = union(totals[k], b);
                }
            }
        }
        EdgeTree { nodes, present, lowest: lowest as u32, leaves }
    }

    /// The number of levels of nodes (tests: the stack of a query holds far more).
    #[cfg(test)]
    pub fn depth(&self) -> usize {
        let mut k = self.lowest as usize;
        let mut depth = 1;
        while k > 0 {
            k = (k - 1) / WAYS;
            depth += 1;
        }
        depth
    }
}

fn bounds_of(points: &[Point]) -> [f64; 4] {
    points.iter().fold(EMPTY, |b, p| [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)])
}

fn union(a: [f64; 4], b: [f64; 4]) -> [f64; 4] {
    [a[0].min(b[0]), a[1].min(b[1]), a[2].max(b[2]), a[3].max(b[3])]
}

const EMPTY: [f64; 4] = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{Polygons, Rect, Ring};

    #[test]
    fn leaves_cover_every_edge_once_and_boxes_nest() {
        let big = Ring::new((0..500).map(|i| Point::new(f64::from(i), f64::from(i % 7))).collect());
        let w = Polygons::new(vec![big, Rect::new(600.0, 0.0, 601.0, 1.0).to_ring()]);
        let rings = WindowRings::new(&w);
        let tree = EdgeTree::new(&rings);
        let mut edges: Vec<usize> = tree.leaves.iter().flat_map(|r| r.start as usize..r.end as usize).collect();
        edges.sort_unstable();
        let expected: Vec<usize> = rings.rings.iter().flat_map(Clone::clone).collect();
        assert_eq!(edges, expected);
        // Every leaf is reached once from the root, inside every box on its way.
        let mut reached = vec![0; tree.leaves.len()];
        let mut stack = vec![(0usize, [f64::NEG_INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::INFINITY])];
        while let Some((n, outer)) = stack.pop() {
            let node = &tree.nodes[n];
            for i in (0..WAYS).filter(|&i| tree.present[n] & (1 << i) != 0) {
                let b = [node.sides[MIN_X][i], node.sides[MIN_Y][i], node.sides[MAX_X][i], node.sides[MAX_Y][i]];
                assert!(b[0] >= outer[0] && b[1] >= outer[1] && b[2] <= outer[2] && b[3] <= outer[3]);
                if n >= tree.lowest as usize {
                    let leaf = WAYS * (n - tree.lowest as usize) + i;
                    let r = &tree.leaves[leaf];
                    assert_eq!(b, bounds_of(&rings.points[r.start as usize..=r.end as usize]));
                    reached[leaf] += 1;
                } else {
                    stack.push((WAYS * n + 1 + i, b));
                }
            }
        }
        assert!(reached.iter().all(|&r| r == 1));
        assert!(tree.depth() <= 4, "{}", tree.depth());
    }
}
