//! The event sweep's scanbeam table: the active edges' tops in a priority queue, so a scanline
//! finds the edges that end on it without visiting the others (the paper's MarkSBT, kept as a
//! priority queue of edges rather than a sorted list of heights).
//!
//! Edges that start at local minima between two reads of the queue start at one scanline.
//! Where many start at once (the local minima of a comb, a grid, map tiles: many edges beginning
//! at one height), those past the first few are sorted together into a run and read from it in
//! order, and only the run's head waits in a heap. A heap as large as the table would be sifted
//! at random places in memory at every pop; a run is read sequentially. Tops pushed a few at a
//! time go into the heap one by one. Either way the queue yields (height, edge) in increasing
//! order, ties by edge id, so the sweep sees the same order as from one heap.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use crate::scanbeam::height_key;

/// The first this many tops pushed together go into the heap; the rest of a batch, when it holds
/// as many again, is sorted into a run: below that a heap push each is as cheap as a sort.
const RUN_FROM: usize = 32;

/// Active edges by the height of their tops.
#[derive(Debug, Default)]
pub(crate) struct EdgeTops {
    /// Tops pushed a few at a time: (height key, edge).
    heap: BinaryHeap<Reverse<(i64, u32)>>,
    /// Tops of starting edges pushed since the queue was last read.
    batch: usize,
    /// Those of them past the first [`RUN_FROM`], which wait here to be sorted into a run.
    pending: Vec<(i64, u32)>,
    /// The runs' entries, each run sorted in its own stretch.
    entries: Vec<(i64, u32)>,
    /// Per run, its next entry and its end in `entries` (equal once read out).
    runs: Vec<(usize, usize)>,
    /// Runs read out, whose slot a new run may take.
    free_runs: Vec<u32>,
    /// Each unfinished run's head: (height key, edge, run).
    heads: BinaryHeap<Reverse<(i64, u32, u32)>>,
    /// Entries of `entries` still to be read.
    unread: usize,
}

impl EdgeTops {
    /// Empties the queue, keeping its buffers.
    pub(crate) fn clear(&mut self) {
        self.heap.clear();
        self.batch = 0;
        self.pending.clear();
        self.entries.clear();
        self.runs.clear();
        self.free_runs.clear();
        self.heads.clear();
        self.unread = 0;
    }

    /// Bytes of capacity held.
    pub(crate) fn held_bytes(&self) -> usize {
        let pair = size_of::<(i64, u32)>();
        (self.heap.capacity() + self.pending.capacity() + self.entries.capacity()) * pair
            + self.runs.capacity() * size_of::<(usize, usize)>()
            + self.free_runs.capacity() * 4
            + self.heads.capacity() * size_of::<(i64, u32, u32)>()
    }

    /// Edge `id`, which went on to its bound's next edge, ends at height `y`.
    #[inline]
    pub(crate) fn push(&mut self, y: f64, id: u32) {
        self.heap.push(Reverse((height_key(y), id)));
    }

    /// Edge `id`, which starts at a local minimum, ends at height `y`: many of those at one
    /// scanline make a run.
    #[inline]
    pub(crate) fn push_starting(&mut self, y: f64, id: u32) {
        if self.batch < RUN_FROM {
            self.batch += 1;
            self.heap.push(Reverse((height_key(y), id)));
        } else {
            self.pending.push((height_key(y), id));
        }
    }

    /// The lowest height an edge ends at, as a [`height_key`].
    #[inline]
    pub(crate) fn lowest(&mut self) -> Option<i64> {
        self.settle();
        let single = self.heap.peek().map(|Reverse((k, _))| *k);
        if self.heads.is_empty() {
            return single;
        }
        let run = self.heads.peek().map(|Reverse((k, _, _))| *k);
        match (single, run) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// Moves every edge ending at height `y` into `out`, by increasing edge id. Tops still waiting
    /// to be sorted into a run since [`EdgeTops::lowest`] are not looked at: they belong to edges
    /// that start at or above that height, and so end above it.
    #[inline]
    pub(crate) fn take_at(&mut self, y: f64, out: &mut Vec<u32>) {
        let k = height_key(y);
        debug_assert!(self.pending.iter().all(|&(top, _)| top > k), "an edge pushed ends at the sweep");
        if self.heads.is_empty() {
            while let Some(&Reverse((top, id))) = self.heap.peek() {
                if top != k {
                    debug_assert!(top > k, "an edge ended below the sweep");
                    break;
                }
                self.heap.pop();
                out.push(id);
            }
            return;
        }
        self.take_merged(k, out);
    }

    /// [`EdgeTops::take_at`] while runs wait: the lower of the heap's top and the runs' heads.
    fn take_merged(&mut self, k: i64, out: &mut Vec<u32>) {
        loop {
            let single = self.heap.peek().map(|&Reverse(top)| top);
            let head = self.heads.peek().map(|&Reverse((key, id, _))| (key, id));
            let from_run = match (single, head) {
                (Some(s), Some(h)) => h < s,
                (None, Some(_)) => true,
                (_, None) => false,
            };
            let Some((top, id)) = (if from_run { head } else { single }) else { break };
            if top != k {
                debug_assert!(top > k, "an edge ended below the sweep");
                break;
            }
            if from_run {
                self.advance_run();
            } else {
                self.heap.pop();
            }
            out.push(id);
        }
    }

    /// Files the tops pushed since the last read: many as one sorted run, a few into the heap.
    #[inline]
    fn settle(&mut self) {
        if self.batch != 0 {
            self.batch = 0;
            if !self.pending.is_empty() {
                self.file_pending();
            }
        }
    }

    fn file_pending(&mut self) {
        if self.pending.len() < RUN_FROM {
            // One push each: `extend` guards a possible rebuild, which costs more than these.
            for &top in &self.pending {
                self.heap.push(Reverse(top));
            }
            self.pending.clear();
            return;
        }
        self.pending.sort_unstable();
        self.compact_if_mostly_read();
        let (start, end) = (self.entries.len(), self.entries.len() + self.pending.len());
        self.entries.append(&mut self.pending);
        self.unread += end - start;
        let run = match self.free_runs.pop() {
            Some(r) => {
                self.runs[r as usize] = (start + 1, end);
                r
            }
            None => {
                self.runs.push((start + 1, end));
                self.runs.len() as u32 - 1
            }
        };
        let (key, id) = self.entries[start];
        self.heads.push(Reverse((key, id, run)));
    }

    /// Takes the lowest run head, putting the run's next entry in its place.
    fn advance_run(&mut self) {
        let Some(Reverse((_, _, run))) = self.heads.pop() else { return };
        self.unread -= 1;
        let (next, end) = &mut self.runs[run as usize];
        if *next < *end {
            let (key, id) = self.entries[*next];
            *next += 1;
            self.heads.push(Reverse((key, id, run)));
        } else {
            self.free_runs.push(run);
            if self.heads.is_empty() {
                self.entries.clear();
                self.runs.clear();
                self.free_runs.clear();
            }
        }
    }

    /// Drops the entries already read once they are most of the buffer, so that a long sweep
    /// keeps at most about twice the tops still waiting in runs.
    fn compact_if_mostly_read(&mut self) {
        let read = self.entries.len() - self.unread;
        if read < 4096 || read < self.unread {
            return;
        }
        // Unread stretches moved down in the order they lie, so none is overwritten before it moves.
        let mut live: Vec<(usize, u32)> =
            self.heads.iter().map(|Reverse((_, _, r))| (self.runs[*r as usize].0, *r)).collect();
        live.sort_unstable();
        let mut to = 0;
        for (next, run) in live {
            let end = self.runs[run as usize].1;
            // The head was taken out of `next - 1`: keep it and the rest of the run.
            let from = next - 1;
            self.entries.copy_within(from..end, to);
            self.runs[run as usize] = (to + 1, to + end - from);
            to += end - from;
        }
        self.entries.truncate(to);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Batches of every size, pushed between reads at rising heights, come out as one heap of
    /// them all would give them: by height, ties by edge id.
    #[test]
    fn runs_and_single_tops_come_out_in_the_order_of_one_heap() {
        let mut tops = EdgeTops::default();
        let mut reference: BinaryHeap<Reverse<(i64, u32)>> = BinaryHeap::new();
        let mut seed = 0x2545_f491_u32;
        let mut random = |n: u32| {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed % n
        };
        let mut next_id = 0u32;
        let mut y = 0.0;
        for round in 0..400 {
            // Mostly small batches, now and then a large one; heights above the sweep, with ties.
            let batch = if round % 37 == 0 {
                5000
            } else if round % 5 == 0 {
                40
            } else {
                random(4) as usize
            };
            for _ in 0..batch {
                let top = y + 1.0 + f64::from(random(300));
                // Edges that start and edges that go on are pushed alike here.
                if random(3) == 0 {
                    tops.push(top, next_id)
                } else {
                    tops.push_starting(top, next_id)
                }
                reference.push(Reverse((height_key(top), next_id)));
                next_id += 1;
            }
            let Some(low) = tops.lowest() else { continue };
            assert_eq!(Some(low), reference.peek().map(|Reverse((k, _))| *k));
            y = reference.peek().map(|Reverse((k, _))| *k).map(crate::scanbeam::height).unwrap();
            let mut out = Vec::new();
            tops.take_at(y, &mut out);
            let mut expect = Vec::new();
            while reference.peek().is_some_and(|Reverse((k, _))| *k == low) {
                expect.push(reference.pop().unwrap().0.1);
            }
            assert_eq!(out, expect, "round {round}");
            assert!(tops.entries.len() <= 2 * tops.unread + 4096 + 5000, "{} kept", tops.entries.len());
        }
        // Drain the rest.
        while let Some(low) = tops.lowest() {
            let mut out = Vec::new();
            tops.take_at(crate::scanbeam::height(low), &mut out);
            let mut expect = Vec::new();
            while reference.peek().is_some_and(|Reverse((k, _))| *k == low) {
                expect.push(reference.pop().unwrap().0.1);
            }
            assert_eq!(out, expect);
        }
        assert!(reference.is_empty());
        assert_eq!(tops.entries.len(), 0, "read out, the runs' buffer is emptied");
    }
}
