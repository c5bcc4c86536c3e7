//! A bounding-box hierarchy over runs of consecutive window edges, stored in pre-order with skip links.

use core::ops::Range;

use clip_core::{Point, WindowRings};

/// Window edges per leaf: a leaf is a run of at most this many consecutive edges of one ring.
/// Measured on `lines-large` and the beyond-the-paper windows: 8 and 16 are within a few percent,
/// 4 is slower (more box tests), 32 slower at 10^4 edges (more vertex signs per hit leaf).
pub(crate) const LEAF_EDGES: usize = 8;

/// One node: its box, where its subtree ends, and for a leaf the vertices of its edge run.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Node {
    /// `[min x, min y, max x, max y]` over the node's vertices (exact coordinates).
    pub bounds: [f64; 4],
    /// Index of the first node after this node's subtree.
    pub skip: u32,
    /// For a leaf, the first vertex of its run (edge `i` is vertex `i` to `i + 1`).
    pub first: u32,
    /// For a leaf, one past its last edge (so `first..end` are its edges); 0 for an inner node.
    pub end: u32,
}

impl Node {
    /// True for a leaf.
    #[inline(always)]
    pub fn is_leaf(&self) -> bool {
        self.end != 0
    }
}

/// The hierarchy: leaves are runs of [`LEAF_EDGES`] consecutive edges of one ring in ring order,
/// so a leaf's box hugs its piece of the boundary; inner nodes pair consecutive runs. Nodes are
/// stored in pre-order, each with the index just past its subtree, so a query walks the array
/// front to back, jumping over subtrees whose box the query misses: no stack, no recursion.
#[derive(Clone, Debug)]
pub(crate) struct EdgeTree {
    /// Nodes in pre-order; the root (the window's bounding box) first.
    pub nodes: Vec<Node>,
}

impl EdgeTree {
    /// Builds the tree over `rings`' edges: O(n) time, about `2n / LEAF_EDGES` nodes.
    pub fn new(rings: &WindowRings) -> EdgeTree {
        let mut leaves: Vec<Range<usize>> = Vec::new();
        for ring in &rings.rings {
            let mut start = ring.start;
            while start < ring.end {
                let end = (start + LEAF_EDGES).min(ring.end);
                leaves.push(start..end);
                start = end;
            }
        }
        let mut nodes = Vec::with_capacity(2 * leaves.len());
        build(&rings.points, &leaves, &mut nodes);
        EdgeTree { nodes }
    }
}

/// Appends the subtree over `leaves` in pre-order and returns its box.
fn build(points: &[Point], leaves: &[Range<usize>], nodes: &mut Vec<Node>) -> [f64; 4] {
    let at = nodes.len();
    nodes.push(Node { bounds: [0.0; 4], skip: 0, first: 0, end: 0 });
    let bounds = if let [leaf] = leaves {
        nodes[at].first = leaf.start as u32;
        nodes[at].end = leaf.end as u32;
        points[leaf.start..=leaf.end]
            .iter()
            .fold(EMPTY, |b, p| [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)])
    } else {
        let (left, right) = leaves.split_at(leaves.len() / 2);
        let l = build(points, left, nodes);
        let r = build(points, right, nodes);
        [l[0].min(r[0]), l[1].min(r[1]), l[2].max(r[2]), l[3].max(r[3])]
    };
    nodes[at].bounds = bounds;
    nodes[at].skip = nodes.len() as u32;
    bounds
}

const EMPTY: [f64; 4] = [f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY];

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::{Polygons, Rect, Ring};

    #[test]
    fn leaves_cover_every_edge_once_and_boxes_nest() {
        let big = Ring::new((0..50).map(|i| Point::new(f64::from(i), f64::from(i % 7))).collect());
        let w = Polygons::new(vec![big, Rect::new(100.0, 0.0, 101.0, 1.0).to_ring()]);
        let rings = WindowRings::new(&w);
        let tree = EdgeTree::new(&rings);
        let mut edges: Vec<usize> =
            tree.nodes.iter().filter(|n| n.is_leaf()).flat_map(|n| n.first as usize..n.end as usize).collect();
        edges.sort_unstable();
        let expected: Vec<usize> = rings.rings.iter().flat_map(Clone::clone).collect();
        assert_eq!(edges, expected);
        for (i, n) in tree.nodes.iter().enumerate() {
            assert!(n.skip as usize > i && n.skip as usize <= tree.nodes.len());
            for c in &tree.nodes[i + 1..n.skip as usize] {
                assert!(c.bounds[0] >= n.bounds[0] && c.bounds[1] >= n.bounds[1]);
                assert!(c.bounds[2] <= n.bounds[2] && c.bounds[3] <= n.bounds[3]);
            }
        }
        assert_eq!(tree.nodes[0].bounds, [0.0, 0.0, 101.0, 6.0]);
    }
}
