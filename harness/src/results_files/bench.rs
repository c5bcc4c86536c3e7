//! The files of `clipbench bench`: timings, peak memory, the sidecar, and the baseline ratios are taken against.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::cli_error::CliError;
use crate::measure::raw::{read_csv, write_csv};

/// The raw timings, one [`Measurement`](crate::measure::raw::Measurement) per row.
pub const CSV: &str = "bench.csv";
/// Peak memory of the large cases, one [`MemoryRecord`] per row.
pub const MEMORY_CSV: &str = "bench-memory.csv";
/// The sidecar of [`CSV`].
pub const META: &str = "bench.meta.json";
/// The bench group of clip-text's strategies (rows `text-*`; case = window side, size = the
/// paragraph's characters, time per paragraph), reported in the text section, not the bench's.
pub const TEXT_GROUP: &str = "text";
/// Every point's figures with their 95% intervals, derived from [`CSV`] by `report`, one
/// [`PointRecord`] per row.
pub const POINTS_CSV: &str = "bench-points.csv";
/// The baseline every ratio is taken against.
pub const BASELINE: &str = "clipper2";

/// The raw-file name of an external clipper's own times (the round trip keeps its plain name).
pub fn own_time_name(clipper: &str) -> String {
    format!("{clipper} (own time)")
}

/// One row of [`MEMORY_CSV`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MemoryRecord {
    /// Group label.
    pub workload: String,
    /// Case index.
    pub case: String,
    /// The clipper.
    pub clipper: String,
    /// Subject edges.
    pub size: usize,
    /// The operation.
    pub op: String,
    /// Resident memory before the call, KiB.
    pub rss_before_kib: u64,
    /// Peak resident memory above that during the call, KiB.
    pub peak_extra_kib: u64,
}

/// One row of [`POINTS_CSV`]: a clipper at one group, operation and size.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PointRecord {
    /// Group label.
    pub workload: String,
    /// The operation.
    pub op: String,
    /// Subject edges (or the group's size measure).
    pub size: usize,
    /// The clipper.
    pub clipper: String,
    /// Cases behind the point.
    pub cases: usize,
    /// Cases whose result was found wrong (then no time or ratio counts).
    pub wrong_cases: usize,
    /// Fewest rounds behind one case's median.
    pub rounds: usize,
    /// Time per call, ns: mean over cases of the median over rounds.
    pub time_ns: f64,
    /// Lower end of its 95% bootstrap interval.
    pub time_low_ns: f64,
    /// Upper end.
    pub time_high_ns: f64,
    /// Ratio to [`BASELINE`] (geometric mean over cases); empty where there is none.
    pub ratio: Option<f64>,
    /// Lower end of its 95% bootstrap interval.
    pub ratio_low: Option<f64>,
    /// Upper end.
    pub ratio_high: Option<f64>,
}

/// Writes [`MEMORY_CSV`] into `out`.
pub fn write_memory(out: &Path, records: &[MemoryRecord]) -> Result<(), CliError> {
    write_csv(&out.join(MEMORY_CSV), records)
}

/// Reads [`MEMORY_CSV`] from `out`; no file means no memory was measured.
pub fn read_memory(out: &Path) -> Result<Vec<MemoryRecord>, CliError> {
    let path = out.join(MEMORY_CSV);
    if path.exists() { read_csv(&path) } else { Ok(Vec::new()) }
}
