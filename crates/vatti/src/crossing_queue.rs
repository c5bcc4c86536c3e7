//! The event sweep's crossings (Bentley & Ottmann 1979): a pair of edges is tested only when it
//! becomes adjacent in the active edge table, and a crossing found waits in a priority queue by
//! height until the sweep reaches it. A crossing that waited while another edge came between
//! its pair is dropped when it comes up: the pair is tested again when it is adjacent again.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use clip_core::Point;

use crate::scanbeam::height_key;

/// A crossing of adjacent edges `left` and `right` (in the table's order when found) at `pt`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct PendingCrossing {
    pub left: u32,
    pub right: u32,
    pub pt: Point,
}

/// Crossings found and not yet passed, lowest first; at one height, in the order found.
#[derive(Debug, Default)]
pub(crate) struct CrossingQueue {
    /// Heights as [`height_key`]s with the slot of their crossing: small entries, cheap to sift.
    heap: BinaryHeap<Reverse<(i64, u32)>>,
    slots: Vec<PendingCrossing>,
    free: Vec<u32>,
}

impl CrossingQueue {
    /// Empties the queue, keeping its buffers.
    pub(crate) fn clear(&mut self) {
        self.heap.clear();
        self.slots.clear();
        self.free.clear();
    }

    /// Bytes of capacity held.
    pub(crate) fn held_bytes(&self) -> usize {
        self.heap.capacity() * size_of::<(i64, u32)>()
            + self.slots.capacity() * size_of::<PendingCrossing>()
            + 4 * self.free.capacity()
    }

    /// Adds the crossing of `left` and `right` at `pt`.
    #[inline]
    pub(crate) fn push(&mut self, left: u32, right: u32, pt: Point) {
        let c = PendingCrossing { left, right, pt };
        let slot = match self.free.pop() {
            Some(s) => {
                self.slots[s as usize] = c;
                s
            }
            None => {
                self.slots.push(c);
                self.slots.len() as u32 - 1
            }
        };
        self.heap.push(Reverse((height_key(pt.y), slot)));
    }

    /// The lowest crossing, left in the queue.
    #[inline]
    pub(crate) fn lowest(&self) -> Option<PendingCrossing> {
        self.heap.peek().map(|&Reverse((_, slot))| self.slots[slot as usize])
    }

    /// Takes the lowest crossing out of the queue.
    #[inline]
    pub(crate) fn pop(&mut self) {
        if let Some(Reverse((_, slot))) = self.heap.pop() {
            self.free.push(slot);
        }
    }

    /// The lowest crossing at or below height `y`, taken out of the queue.
    #[inline]
    pub(crate) fn pop_up_to(&mut self, y: f64) -> Option<PendingCrossing> {
        let &Reverse((k, slot)) = self.heap.peek()?;
        if k > height_key(y) {
            return None;
        }
        self.heap.pop();
        self.free.push(slot);
        Some(self.slots[slot as usize])
    }
}
