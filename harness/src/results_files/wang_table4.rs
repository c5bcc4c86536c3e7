//! The files of `clipbench reproduce wang-table4`: timings, the windows, the rejection stages, the sidecar.

use serde::{Deserialize, Serialize};

/// The raw timings, one [`Measurement`](crate::measure::raw::Measurement) per row.
pub const CSV: &str = "wang-table4.csv";
/// Each window's measured W1 and W2, one [`WindowRecord`] per row.
pub const WINDOWS_CSV: &str = "wang-table4-windows.csv";
/// Segments settled by each stage of each clipper, one [`StageRecord`] per row.
pub const STAGES_CSV: &str = "wang-table4-stages.csv";
/// New2 and Liu timed on the segments each New2 stage settles, one [`StageTimeRecord`] per row.
pub const STAGE_TIMES_CSV: &str = "wang-table4-stage-times.csv";
/// The sidecar of [`CSV`].
pub const META: &str = "wang-table4.meta.json";

/// One row of [`WINDOWS_CSV`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct WindowRecord {
    /// `concave` (the table) or `convex` (the extra table with Cyrus-Beck).
    pub shape: String,
    /// `W1` for the paper's first size row (its own polygon), `W2` for the second (W1 = 4, W2 = 80).
    pub size_row: String,
    /// Window edges.
    pub edges: usize,
    /// 600 / (MEB width + height), measured on our window.
    pub w1: f64,
    /// 600 x 800 / MEB area, measured on our window.
    pub w2: f64,
    /// The paper's W1 for this row.
    pub paper_w1: f64,
    /// The paper's W2 for this row.
    pub paper_w2: f64,
}

/// One row of [`STAGES_CSV`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StageRecord {
    /// Window shape, as in [`WindowRecord::shape`].
    pub shape: String,
    /// Size row, as in [`WindowRecord::size_row`].
    pub size_row: String,
    /// Window edges.
    pub edges: usize,
    /// The clipper.
    pub clipper: String,
    /// The stage (`meb`, `rotated-box`, `virtual-box`, `code-sum`, `intersected`, `visible`, ...).
    pub stage: String,
    /// Segments that stage settled.
    pub segments: usize,
    /// Segments in the batch.
    pub of: usize,
}

/// One row of [`STAGE_TIMES_CSV`]: one clipper timed on the segments of one window that New2
/// settles at one stage.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StageTimeRecord {
    /// Size row, as in [`WindowRecord::size_row`] (concave windows only).
    pub size_row: String,
    /// Window edges.
    pub edges: usize,
    /// New2's stage (`meb`, `rotated-box`, `virtual-box`, `code-sum`, `intersected`).
    pub stage: String,
    /// Segments of the batch New2 settles there.
    pub segments: usize,
    /// Segments in the batch.
    pub of: usize,
    /// `virtual-box` (New2) or `liu`.
    pub clipper: String,
    /// Median ns per segment on those segments.
    pub ns_per_segment: f64,
}
