//! Buffers that one thread's clips reuse, so a small clip does not allocate its tables anew.

use std::cell::Cell;
use std::mem::size_of;

use clip_core::Point;

use crate::bounds::{Bounds, LocalMinimum, Vertex};
use crate::raw_rings::RawRings;
use crate::sweep::SweepBuffers;
use crate::touches::Touches;

/// Buffers larger than this (bytes of capacity) are freed after the call rather than kept: a
/// large clip's allocations cost little next to its sweep, and a thread should not hold them.
const KEEP_AT_MOST: usize = 256 * 1024;

thread_local! {
    static SCRATCH: Cell<Option<Scratch>> = const { Cell::new(None) };
}

/// The input bounds, the sweep's tables, the raw output rings and the clean-up's touch search
/// of one clip.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    pub bounds: Bounds,
    pub sweep: SweepBuffers,
    pub raw: RawRings,
    pub touches: Touches,
}

impl Scratch {
    /// This thread's kept buffers, or new empty ones (also while another clip on this thread
    /// holds them, or while the thread is being torn down).
    pub(crate) fn take() -> Scratch {
        SCRATCH.try_with(Cell::take).ok().flatten().unwrap_or_default()
    }

    /// Keeps the buffers for this thread's next clip, unless they are large.
    pub(crate) fn give_back(self) {
        if self.held_bytes() <= KEEP_AT_MOST {
            // During thread teardown there is nowhere to keep them: they are dropped.
            let _ = SCRATCH.try_with(|s| s.set(Some(self)));
        }
    }

    fn held_bytes(&self) -> usize {
        self.bounds.vertices.capacity() * size_of::<Vertex>()
            + self.bounds.minima.capacity() * size_of::<LocalMinimum>()
            + self.bounds.ring_capacity() * size_of::<Point>()
            + self.sweep.held_bytes()
            + self.raw.points.capacity() * size_of::<Point>()
            + self.raw.ends.capacity() * size_of::<usize>()
            + self.raw.emitted.capacity() * size_of::<u32>()
            + self.touches.held_bytes()
    }
}
