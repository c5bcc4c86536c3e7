//! A search tree over the active edges' left-to-right order, so a new edge finds its place in
//! O(log n) comparisons instead of a walk over every active edge.
//!
//! The tree is a treap (Seidel & Aragon 1996): a binary search tree by order whose nodes also
//! form a heap by random priority, which keeps its expected depth logarithmic whatever the
//! order of insertions. It holds edge ids and never compares keys itself: the caller's
//! predicate says, at the point where an edge enters, whether an active edge lies before it
//! (exact, see `active`). Every other change is positional: removal by node, two neighbours
//! swapped by exchanging the ids their nodes hold.
//!
//! A removal only marks the edge's node dead; the dead nodes are taken out of the tree when a
//! search next needs it. Inserting next to a known edge and swapping neighbours are positional and
//! work around dead nodes. So an edge that ends after the sweep's last search (its last local
//! minimum) never costs a rotation, and the others cost what they did.

use crate::bounds::NONE;

#[derive(Clone, Copy, Debug)]
struct Node {
    left: u32,
    right: u32,
    parent: u32,
    priority: u32,
    edge: u32,
}

/// The order of the active edges as a treap of edge ids.
#[derive(Debug, Default)]
pub(crate) struct OrderIndex {
    nodes: Vec<Node>,
    /// Node of every edge id (`NONE` when the edge is not in the tree).
    node_of: Vec<u32>,
    free: Vec<u32>,
    /// Nodes of removed edges still in the tree, taken out before the next search.
    dead: Vec<u32>,
    root: u32,
    /// State of the priorities' generator (xorshift), the same at every reset so a clip's tree
    /// shape, and the place it gives an edge where rounding leaves the order unsorted, repeat.
    seed: u32,
}

impl OrderIndex {
    /// Empties the tree, keeping its buffers, with room for `records` edges (reserved with the
    /// table they index, `ActiveEdges::reset`).
    pub(crate) fn reset(&mut self, records: usize) {
        self.nodes.clear();
        self.nodes.reserve(records);
        self.node_of.clear();
        self.node_of.reserve(records);
        self.free.clear();
        self.dead.clear();
        self.root = NONE;
        self.seed = 0x9e37_79b9;
    }

    /// Bytes of capacity held.
    pub(crate) fn held_bytes(&self) -> usize {
        // Nodes written, not reserved (see `reset`).
        self.nodes.len() * size_of::<Node>() + 4 * (self.node_of.len() + self.free.capacity() + self.dead.capacity())
    }

    /// Inserts `edge` where `before` turns false: every edge for which `before` holds is to its
    /// left, as long as `before` holds on a prefix of the order. Returns the edges that are now
    /// its left and right neighbours (`NONE` at either end).
    pub(crate) fn insert_by(&mut self, edge: u32, mut before: impl FnMut(u32) -> bool) -> (u32, u32) {
        // The search reads every node on its path: none may be dead.
        while let Some(x) = self.dead.pop() {
            self.take_out(x);
        }
        let (mut left, mut right) = (NONE, NONE);
        let (mut parent, mut went_right) = (NONE, false);
        let mut n = self.root;
        while n != NONE {
            let node = self.nodes[n as usize];
            parent = n;
            went_right = before(node.edge);
            if went_right {
                left = node.edge;
                n = node.right;
            } else {
                right = node.edge;
                n = node.left;
            }
        }
        self.attach(edge, parent, went_right);
        (left, right)
    }

    /// Inserts `edge` right after `after` (first when `after` is `NONE`).
    pub(crate) fn insert_after(&mut self, edge: u32, after: u32) {
        let (parent, as_right) = if after == NONE {
            (self.extreme(self.root, false), false)
        } else {
            let a = self.node_of[after as usize];
            let r = self.nodes[a as usize].right;
            if r == NONE { (a, true) } else { (self.extreme(r, false), false) }
        };
        self.attach(edge, parent, as_right);
    }

    /// Removes `edge`: its node stays in the tree, dead, until a search takes it out.
    #[inline]
    pub(crate) fn remove(&mut self, edge: u32) {
        let x = self.node_of[edge as usize];
        self.node_of[edge as usize] = NONE;
        self.dead.push(x);
    }

    /// Takes dead node `x` out of the tree.
    fn take_out(&mut self, x: u32) {
        // Rotate the node down below its higher-priority child until it is a leaf.
        loop {
            let Node { left, right, .. } = self.nodes[x as usize];
            let child = match (left, right) {
                (NONE, NONE) => break,
                (c, NONE) | (NONE, c) => c,
                (l, r) => {
                    if self.nodes[l as usize].priority > self.nodes[r as usize].priority {
                        l
                    } else {
                        r
                    }
                }
            };
            self.rotate_up(child);
        }
        let p = self.nodes[x as usize].parent;
        self.replace_child(p, x, NONE);
        self.free.push(x);
    }

    /// Exchanges the places of `a` and `b` (any two edges in the tree).
    #[inline]
    pub(crate) fn swap(&mut self, a: u32, b: u32) {
        let (na, nb) = (self.node_of[a as usize], self.node_of[b as usize]);
        self.nodes[na as usize].edge = b;
        self.nodes[nb as usize].edge = a;
        self.node_of[a as usize] = nb;
        self.node_of[b as usize] = na;
    }

    fn set_node_of(&mut self, edge: u32, node: u32) {
        let i = edge as usize;
        if i >= self.node_of.len() {
            self.node_of.resize(i + 1, NONE);
        }
        self.node_of[i] = node;
    }

    /// The leftmost (`right == false`) or rightmost node below `n`, or `NONE` for an empty tree.
    fn extreme(&self, mut n: u32, right: bool) -> u32 {
        if n == NONE {
            return NONE;
        }
        loop {
            let node = &self.nodes[n as usize];
            let next = if right { node.right } else { node.left };
            if next == NONE {
                return n;
            }
            n = next;
        }
    }

    /// A new leaf for `edge` as the `right` or left child of `parent` (the root when `NONE`),
    /// rotated up to its place by priority.
    fn attach(&mut self, edge: u32, parent: u32, right: bool) {
        self.seed ^= self.seed << 13;
        self.seed ^= self.seed >> 17;
        self.seed ^= self.seed << 5;
        let node = Node { left: NONE, right: NONE, parent, priority: self.seed, edge };
        let x = if let Some(x) = self.free.pop() {
            self.nodes[x as usize] = node;
            x
        } else {
            self.nodes.push(node);
            self.nodes.len() as u32 - 1
        };
        self.set_node_of(edge, x);
        if parent == NONE {
            self.root = x;
        } else if right {
            self.nodes[parent as usize].right = x;
        } else {
            self.nodes[parent as usize].left = x;
        }
        loop {
            let p = self.nodes[x as usize].parent;
            if p == NONE || self.nodes[p as usize].priority >= node.priority {
                break;
            }
            self.rotate_up(x);
        }
    }

    /// Makes `c` take `old`'s place under `p` (the root when `p` is `NONE`).
    #[inline]
    fn replace_child(&mut self, p: u32, old: u32, c: u32) {
        if p == NONE {
            self.root = c;
        } else if self.nodes[p as usize].left == old {
            self.nodes[p as usize].left = c;
        } else {
            self.nodes[p as usize].right = c;
        }
        if c != NONE {
            self.nodes[c as usize].parent = p;
        }
    }

    /// Rotates `x` above its parent, keeping the in-order sequence.
    fn rotate_up(&mut self, x: u32) {
        let p = self.nodes[x as usize].parent;
        let g = self.nodes[p as usize].parent;
        if self.nodes[p as usize].left == x {
            let inner = self.nodes[x as usize].right;
            self.nodes[p as usize].left = inner;
            if inner != NONE {
                self.nodes[inner as usize].parent = p;
            }
            self.nodes[x as usize].right = p;
        } else {
            let inner = self.nodes[x as usize].left;
            self.nodes[p as usize].right = inner;
            if inner != NONE {
                self.nodes[inner as usize].parent = p;
            }
            self.nodes[x as usize].left = p;
        }
        self.nodes[p as usize].parent = x;
        self.replace_child(g, p, x);
    }

    /// The edges in order, for tests.
    #[cfg(test)]
    fn in_order(&self) -> Vec<u32> {
        let mut out = Vec::new();
        let mut n = self.extreme(self.root, false);
        while n != NONE {
            let edge = self.nodes[n as usize].edge;
            if self.node_of.get(edge as usize) == Some(&n) {
                out.push(edge);
            }
            // In-order successor.
            let r = self.nodes[n as usize].right;
            if r != NONE {
                n = self.extreme(r, false);
            } else {
                let mut c = n;
                n = self.nodes[c as usize].parent;
                while n != NONE && self.nodes[n as usize].right == c {
                    c = n;
                    n = self.nodes[c as usize].parent;
                }
            }
        }
        out
    }

    /// The largest depth, for tests.
    #[cfg(test)]
    fn depth(&self, n: u32) -> usize {
        if n == NONE {
            0
        } else {
            1 + self.depth(self.nodes[n as usize].left).max(self.depth(self.nodes[n as usize].right))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Keys of the edges (edge id -> key), inserted by key.
    fn insert_key(t: &mut OrderIndex, keys: &[i64], edge: u32) -> (u32, u32) {
        t.insert_by(edge, |e| keys[e as usize] < keys[edge as usize])
    }

    #[test]
    fn inserts_removes_and_swaps_keep_the_order_and_the_neighbours() {
        let mut t = OrderIndex::default();
        t.reset(0);
        // Keys by edge id, inserted in a scrambled order.
        let keys: Vec<i64> = (0..200).map(|i| (i * 7919) % 200).collect();
        let mut expect: Vec<u32> = Vec::new();
        for e in 0..200u32 {
            let (l, r) = insert_key(&mut t, &keys, e);
            let at = expect.partition_point(|&k| keys[k as usize] < keys[e as usize]);
            assert_eq!(l, if at == 0 { NONE } else { expect[at - 1] });
            assert_eq!(r, expect.get(at).copied().unwrap_or(NONE));
            expect.insert(at, e);
        }
        assert_eq!(t.in_order(), expect);
        // Logarithmic depth: 200 keys in a tree far shallower than a list.
        assert!(t.depth(t.root) < 40, "depth {}", t.depth(t.root));
        for k in (0..200).step_by(3) {
            let e = expect.remove(k % expect.len());
            t.remove(e);
            assert_eq!(t.in_order(), expect);
        }
        // A search after removals: the dead nodes are taken out first, and it finds its place
        // among the live edges only.
        assert!(!t.dead.is_empty());
        let at = expect.partition_point(|&k| keys[k as usize] < 100);
        let (l, r) = t.insert_by(600, |e| keys[e as usize] < 100);
        assert!(t.dead.is_empty());
        assert_eq!((l, r), (expect[at - 1], expect[at]));
        expect.insert(at, 600);
        assert_eq!(t.in_order(), expect);
        let (a, b) = (expect[5], expect[6]);
        t.swap(a, b);
        expect.swap(5, 6);
        assert_eq!(t.in_order(), expect);
        t.insert_after(501, expect[3]);
        expect.insert(4, 501);
        t.insert_after(502, NONE);
        expect.insert(0, 502);
        assert_eq!(t.in_order(), expect);
        for e in expect.drain(..) {
            t.remove(e);
        }
        assert!(t.in_order().is_empty());
        // The next search empties the tree of them: the new edge is then alone in it.
        assert_eq!(t.insert_by(700, |_| true), (NONE, NONE));
        assert_eq!((t.in_order(), t.depth(t.root)), (vec![700], 1));
    }
}
