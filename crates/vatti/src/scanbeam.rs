//! The scanbeam table (the paper's SBT): the y values still to come, kept as a min-heap.

use std::cmp::{Ordering, Reverse};
use std::collections::BinaryHeap;

#[derive(Clone, Copy, Debug, PartialEq)]
struct Y(f64);

impl Eq for Y {}

impl PartialOrd for Y {
    fn partial_cmp(&self, other: &Y) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Y {
    fn cmp(&self, other: &Y) -> Ordering {
        self.0.total_cmp(&other.0)
    }
}

/// Pending scanline y values (edge tops, marked as edges become active).
#[derive(Debug, Default)]
pub(crate) struct Scanbeams {
    heap: BinaryHeap<Reverse<Y>>,
}

impl Scanbeams {
    /// Forgets every mark, keeping the buffer.
    pub(crate) fn clear(&mut self) {
        self.heap.clear();
    }

    /// Marks the buffer has room for.
    pub(crate) fn capacity(&self) -> usize {
        self.heap.capacity()
    }

    /// MarkSBT(y): remember a scanline (duplicates are dropped when popped).
    #[inline]
    pub(crate) fn mark(&mut self, y: f64) {
        self.heap.push(Reverse(Y(y)));
    }

    /// The smallest marked y above `y`; marks at or below `y` are discarded.
    pub(crate) fn next_above(&mut self, y: f64) -> Option<f64> {
        while let Some(&Reverse(Y(top))) = self.heap.peek() {
            if top > y {
                return Some(top);
            }
            self.heap.pop();
        }
        None
    }
}
