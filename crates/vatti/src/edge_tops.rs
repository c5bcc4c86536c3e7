//! The event sweep's scanbeam table: the active edges' tops in a heap, so a scanline finds the
//! edges that end on it without visiting the others (the paper's MarkSBT, kept as a priority
//! queue of edges rather than a sorted list of heights).

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use crate::scanbeam::height_key;

/// Active edges by the height of their tops.
#[derive(Debug, Default)]
pub(crate) struct EdgeTops {
    heap: BinaryHeap<Reverse<(i64, u32)>>,
}

impl EdgeTops {
    /// Empties the queue, keeping its buffer.
    pub(crate) fn clear(&mut self) {
        self.heap.clear();
    }

    /// Bytes of capacity held.
    pub(crate) fn held_bytes(&self) -> usize {
        self.heap.capacity() * size_of::<(i64, u32)>()
    }

    /// Edge `id` ends at height `y`.
    #[inline]
    pub(crate) fn push(&mut self, y: f64, id: u32) {
        self.heap.push(Reverse((height_key(y), id)));
    }

    /// The lowest height an edge ends at, as a [`height_key`].
    #[inline]
    pub(crate) fn lowest(&self) -> Option<i64> {
        self.heap.peek().map(|Reverse((k, _))| *k)
    }

    /// Moves every edge ending at height `y` into `out`.
    pub(crate) fn take_at(&mut self, y: f64, out: &mut Vec<u32>) {
        let k = height_key(y);
        while let Some(&Reverse((top, id))) = self.heap.peek() {
            if top != k {
                debug_assert!(top > k, "an edge ended below the sweep");
                break;
            }
            self.heap.pop();
            out.push(id);
        }
    }
}
