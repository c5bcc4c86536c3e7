//! Buffers that one thread's clips reuse, so a small clip does not allocate its tables anew.

use std::cell::RefCell;
use std::mem::size_of;

use clip_core::Point;

use crate::bounds::{Bounds, LocalMinimum, Vertex};
use crate::cleanup::{Touches, Turns};
use crate::raw_rings::RawRings;
use crate::sweep::SweepBuffers;

/// Buffers larger than this (bytes of capacity) are freed after the call rather than kept: a
/// very large clip's allocations cost little next to its sweep, and a thread should not hold
/// them. Up to here they are kept: freed and allocated again, a clip of 10^4 vertices spent a
/// fifth of its time in the kernel's page faults on the fresh pages (about 3.5 MiB a call for
/// a 10^4-vertex xor, whose output is twice an intersection's).
const KEEP_AT_MOST: usize = 4 * 1024 * 1024;

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

/// The input bounds, the sweep's tables, the raw output rings and the clean-up's touch search
/// and turns of one clip.
#[derive(Debug, Default)]
pub(crate) struct Scratch {
    pub bounds: Bounds,
    pub sweep: SweepBuffers,
    pub raw: RawRings,
    pub touches: Touches,
    pub turns: Turns,
}

impl Scratch {
    /// Runs `f` on this thread's kept buffers, borrowed in place (they are several hundred bytes
    /// of vector headers, which a small clip should not copy in and out), or on new empty ones
    /// while another clip on this thread holds them or the thread is being torn down. Large
    /// buffers are freed afterwards rather than kept.
    pub(crate) fn with<T>(f: impl FnOnce(&mut Scratch) -> T) -> T {
        // During thread teardown there is nothing to borrow (and `with` below would panic).
        if SCRATCH.try_with(|_| ()).is_err() {
            return f(&mut Scratch::default());
        }
        SCRATCH.with(|cell| match cell.try_borrow_mut() {
            Ok(mut scratch) => {
                let result = f(&mut scratch);
                if scratch.held_bytes() > KEEP_AT_MOST {
                    *scratch = Scratch::default();
                }
                result
            }
            Err(_) => f(&mut Scratch::default()),
        })
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
            + self.turns.held_bytes()
    }
}
