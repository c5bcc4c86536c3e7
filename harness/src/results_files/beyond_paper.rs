//! The files of `clipbench reproduce beyond-paper`: timings per segment, preparation, the 10^6-segment point, the sidecar.

use serde::{Deserialize, Serialize};

/// The raw timings, one [`Measurement`](crate::measure::raw::Measurement) per row: `case` is
/// `<shape>-<segments>` (`concave-long`, `convex-short`), `size` the window's edges, `iterations`
/// the segments in the timed batch and `time_ns` the time per segment.
pub const CSV: &str = "beyond-paper.csv";
/// Preparation time and memory per clipper and window, one [`PrepareRecord`] per row.
pub const PREPARE_CSV: &str = "beyond-paper-prepare.csv";
/// The many-segments point, one [`LargeRecord`] per row.
pub const LARGE_CSV: &str = "beyond-paper-large.csv";
/// The sidecar of [`CSV`].
pub const META: &str = "beyond-paper.meta.json";

/// One row of [`PREPARE_CSV`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PrepareRecord {
    /// `concave` (lobed) or `convex`.
    pub shape: String,
    /// Window edges.
    pub edges: usize,
    /// The clipper.
    pub clipper: String,
    /// Median wall-clock nanoseconds of one `prepare`.
    pub prepare_ns: f64,
    /// Bytes the prepared window holds, where the clipper reports it.
    pub memory_bytes: Option<usize>,
}

/// One row of [`LARGE_CSV`]: one timed clip of the whole batch.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LargeRecord {
    /// The clipper.
    pub clipper: String,
    /// Worker threads (1: the plain `clip_batch`).
    pub threads: usize,
    /// Segments in the batch.
    pub segments: usize,
    /// Window edges.
    pub edges: usize,
    /// Window rings.
    pub rings: usize,
    /// Round number.
    pub repetition: usize,
    /// Wall-clock seconds for the batch.
    pub seconds: f64,
    /// CPU seconds all threads of the process spent meanwhile (Linux; empty elsewhere): on a
    /// shared machine, the wall clock also counts the time other jobs held the cores.
    pub cpu_seconds: Option<f64>,
    /// Visible pieces written.
    pub pieces: usize,
}
