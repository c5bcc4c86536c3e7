//! The files of the lecture's curve-clipping bench (`clipbench reproduce lecture`): timings per
//! object, the share each preliminary test settled, the sidecar, and the Fig. 6-27 picture.

use serde::{Deserialize, Serialize};

/// The timings, one [`CurveTiming`] per row.
pub const CSV: &str = "lecture-curves.csv";
/// The stages that settled each batch's objects, one [`CurveStageRecord`] per row.
pub const STAGES_CSV: &str = "lecture-curves-stages.csv";
/// The sidecar of [`CSV`].
pub const META: &str = "lecture-curves.meta.json";
/// The lecture's Fig. 6-27, a filled circle clipped by a rectangle, drawn from a real run.
pub const FIGURE_6_27: &str = "lecture-fig-6-27.svg";

/// The clipper with the preliminary tests.
pub const WITH_TESTS: &str = "curve";
/// The same clipper without them.
pub const WITHOUT_TESTS: &str = "curve-no-tests";
/// Flatten the ellipse, then clip the polygon with Vatti.
pub const FLATTEN_VATTI: &str = "flatten+vatti";
/// Flatten the ellipse, then clip the polygon with geo.
pub const FLATTEN_GEO: &str = "flatten+geo";

/// One timed batch: every object of a radius bin clipped once by one method.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CurveTiming {
    /// `circles` or `ellipses`.
    pub workload: String,
    /// `rectangle` or `polygon` (a concave window with holes).
    pub window: String,
    /// Long radius range of the bin: at least this ...
    pub radius_lo: f64,
    /// ... and below this.
    pub radius_hi: f64,
    /// [`WITH_TESTS`], [`WITHOUT_TESTS`], [`FLATTEN_VATTI`] or [`FLATTEN_GEO`].
    pub method: String,
    /// `outline` (visible arcs) or `filled` (clipped region and its area).
    pub phase: String,
    /// Objects in the batch.
    pub objects: usize,
    /// Round number; within a round every method ran once on every batch, interleaved.
    pub repetition: usize,
    /// Batches timed back to back in this measurement.
    pub iterations: u32,
    /// Wall-clock nanoseconds per object.
    pub ns_per_object: f64,
}

/// How many objects of a batch one stage settled (with the tests on).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CurveStageRecord {
    /// As in [`CurveTiming::workload`].
    pub workload: String,
    /// As in [`CurveTiming::window`].
    pub window: String,
    /// As in [`CurveTiming::radius_lo`].
    pub radius_lo: f64,
    /// As in [`CurveTiming::radius_hi`].
    pub radius_hi: f64,
    /// `box-accept`, `box-reject`, `quadrants`, `octants` or `equations`.
    pub stage: String,
    /// Objects that stage settled.
    pub objects: usize,
    /// Objects in the batch.
    pub of: usize,
}
