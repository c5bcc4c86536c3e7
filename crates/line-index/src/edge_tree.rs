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

/// A child slot that holds nothing: its box is empty, so every test misses it.
const NONE: u32 = u32::MAX;

/// Rows of [`Node::sides`]: a box's least x, least y, greatest x and greatest y. A row's index
/// can be computed (a box test picks the rows of the corner it needs from the ray's direction,
/// without a branch).
pub(crate) const MIN_X: usize = 0;
pub(crate) const MIN_Y: usize = 1;
pub(crate) const MAX_X: usize = 2;
pub(crate) const MAX_Y: usize = 3;

/// One node: the boxes of up to four children side by side (each coordinate in its own array,
/// so the four tests are independent and vectorise), and what each child is.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Node {
    /// Per row ([`MIN_X`], [`MIN_Y`], [`MAX_X`], [`MAX_Y`]), per child: that side of the child's
    /// box (exact vertex coordinates; an empty box for unused slots).
    pub sides: [[f64; WAYS]; 4],
    /// Per child: the node index of an inner child, or the leaf index of a leaf child.
    pub child: [u32; WAYS],
    /// Bit `i` set when child `i` is a leaf.
    pub leaves: u8,
    /// Bit `i` set when slot `i` holds a child.
    pub present: u8,
}

/// The hierarchy: leaves are runs of [`LEAF_EDGES`] consecutive edges of one ring in ring order,
/// so a leaf's box hugs its piece of the boundary; inner nodes group four consecutive runs (or
/// four consecutive groups). The root is node 0; a query keeps its own small stack.
#[derive(Clone, Debug)]
pub(crate) struct EdgeTree {
    /// Inner nodes, the root first.
    pub nodes: Vec<Node>,
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
        let mut nodes = Vec::with_capacity(leaves.len() / 3 + 2);
        let ids: Vec<u32> = (0..leaves.len() as u32).collect();
        build(&ids, &boxes, &mut nodes);
        EdgeTree { nodes, leaves }
    }

    /// The greatest depth of the tree (tests: the stack of a query holds far more).
    #[cfg(test)]
    pub fn depth(&self) -> usize {
        fn depth(t: &EdgeTree, n: usize) -> usize {
            let node = &t.nodes[n];
            (0..WAYS)
                .filter(|&i| node.present & !node.leaves & (1 << i) != 0)
                .map(|i| depth(t, node.child[i] as usize))
                .max()
                .unwrap_or(0)
                + 1
        }
        depth(self, 0)
    }
}

/// Appends the node over the consecutive leaves `leaf_ids` and returns its index and box. The
/// first call's node, the root, is node 0. The leaves are split in runs of the largest power of
/// four below their count (the last run shorter), each a leaf or a node built the same way, so
/// every node but those along the right edge is full: the same depth as four equal runs, with
/// about n / 3 nodes instead of n / 2 (a third less memory to read back when other work has
/// evicted the tree).
fn build(leaf_ids: &[u32], boxes: &[[f64; 4]], nodes: &mut Vec<Node>) -> (u32, [f64; 4]) {
    let at = nodes.len();
    nodes.push(Node {
        sides: [[f64::INFINITY; WAYS], [f64::INFINITY; WAYS], [f64::NEG_INFINITY; WAYS], [f64::NEG_INFINITY; WAYS]],
        child: [NONE; WAYS],
        leaves: 0,
        present: 0,
    });
    let mut total = EMPTY;
    let n = leaf_ids.len();
    let mut run = 1;
    while run * WAYS < n {
        run *= WAYS;
    }
    for part in 0..WAYS {
        let (lo, hi) = ((run * part).min(n), (run * (part + 1)).min(n));
        if lo == hi {
            continue;
        }
        let (child, b, leaf) = if hi - lo == 1 {
            (leaf_ids[lo], boxes[leaf_ids[lo] as usize], true)
        } else {
            let (id, b) = build(&leaf_ids[lo..hi], boxes, nodes);
            (id, b, false)
        };
        let node = &mut nodes[at];
        (node.sides[MIN_X][part], node.sides[MIN_Y][part], node.sides[MAX_X][part], node.sides[MAX_Y][part]) =
            (b[0], b[1], b[2], b[3]);
        node.child[part] = child;
        node.leaves |= u8::from(leaf) << part;
        node.present |= 1 << part;
        total = union(total, b);
    }
    (at as u32, total)
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
            for i in (0..WAYS).filter(|&i| node.present & (1 << i) != 0) {
                let b = [node.sides[MIN_X][i], node.sides[MIN_Y][i], node.sides[MAX_X][i], node.sides[MAX_Y][i]];
                assert!(b[0] >= outer[0] && b[1] >= outer[1] && b[2] <= outer[2] && b[3] <= outer[3]);
                if node.leaves & (1 << i) != 0 {
                    let r = &tree.leaves[node.child[i] as usize];
                    assert_eq!(b, bounds_of(&rings.points[r.start as usize..=r.end as usize]));
                    reached[node.child[i] as usize] += 1;
                } else {
                    stack.push((node.child[i] as usize, b));
                }
            }
        }
        assert!(reached.iter().all(|&r| r == 1));
        assert!(tree.depth() <= 4, "{}", tree.depth());
    }
}
