//! The files of `clipbench reproduce vatti-table3`: timings, the pixel check's record, the sidecar.

use serde::{Deserialize, Serialize};

/// The raw timings, one [`Measurement`](crate::measure::raw::Measurement) per row.
pub const CSV: &str = "vatti-table3.csv";
/// The pixel check's record, one [`PixelRecord`] per row.
pub const PIXELS_CSV: &str = "vatti-table3-pixels.csv";
/// The sidecar of [`CSV`].
pub const META: &str = "vatti-table3.meta.json";

/// Method 1's clipper name in the raw rows.
pub const METHOD1: &str = "vatti";
/// Method 2's clipper name in the raw rows.
pub const METHOD2: &str = "sutherland-hodgman";

/// One row of [`PIXELS_CSV`]: the agreed rendering of one case.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PixelRecord {
    /// Subject edges.
    pub size: usize,
    /// Case index.
    pub case: usize,
    /// Trapezoids Method 1 filled.
    pub trapezoids: usize,
    /// Vertices of Method 2's clipped polygon.
    pub polygon_vertices: usize,
    /// Pixels both methods lit.
    pub lit_pixels: usize,
    /// Checksum of the frame (FNV-1a, hexadecimal).
    pub checksum: String,
}
