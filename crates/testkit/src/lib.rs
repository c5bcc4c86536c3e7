//! clip-testkit: seeded workloads, named singular cases, suite readers and a shrinker for clipbench.
//!
//! Everything the harness and the algorithm crates' tests need to generate cases and to report
//! them, independent of any clipping library (the oracles that judge answers are `clip-oracle`;
//! the peer libraries are `clip-peers`):
//!
//! - [`workload`]: every case is a pure function of (workload name, seed, index), seeded with
//!   `rand_pcg::Pcg64` from a hash of the three, so cases do not depend on iteration order or
//!   thread count. Polygon workloads [`workload::POLYGON_WORKLOADS`] (`vatti-t3`, `star`,
//!   `scribble`, `scribble-rect`, `holes`, `multi`, `grid`, `large`, `spiky-box`,
//!   `many-subjects`, `near-coincident`, and the sweep stresses `comb`, i_overlay's performance suite and `maps`,
//!   which reads the world map in `testdata/world`), line workloads [`workload::LINE_WORKLOADS`]
//!   (`wang-t4`, `lines-degenerate`, `lines-large`), curve workloads
//!   [`workload::CURVE_WORKLOADS`] (`circles`, `ellipses`), and [`workload::hard_cases`], inputs
//!   the mature clippers' bug trackers are full of.
//! - [`line_probe`]: named singular line cases (through a vertex, along an edge, endpoint on the
//!   boundary, ...) with hand-computed answers, run through any line clipper in both directions
//!   and both window orientations, checked against the answers and against the line oracle.
//! - [`clipper2_suite`]: Clipper2's `Polygons.txt` / `Lines.txt` records and the grading of its
//!   own test; [`testdata_dir`] finds the external suites kept in the repository.
//! - [`shrink`]: reduces a failing case while it still fails, with bounded work.
//! - [`case_record`]: WKT text and SVG pictures of inputs and outputs for failure reports.
//!
//! # The papers' vocabulary here
//!
//! - B. R. Vatti, *A generic solution to polygon clipping*, Communications of the ACM 35(7):56-63,
//!   1992: Table 3's subject polygons "of a varying number of edges", concave, fitted in
//!   1280 x 1024, against one convex clip polygon, are `vatti-t3` ([`workload::VATTI_EDGES`],
//!   [`workload::vatti_window`]).
//! - J. Wang, G. Lu, Q. Peng, X. Wu, *Line clipping against polygonal window algorithm based on
//!   the multiple virtual boxes rejecting*, J. Zhejiang Univ. SCIENCE A 6(Suppl. I):100-107, 2005:
//!   Table 4's "10000 random line segments" in an 800 x 600 screen against polygons of 6-50 edges
//!   at sizes W1 and W2 are `wang-t4` ([`workload::wang_window`], [`workload::wang_segments`]);
//!   the MEB is a window's bounding box; how the sizes are read is documented on
//!   [`workload::WangSize`]'s module.
//!
//! # Example
//!
//! ```
//! use clip_core::{BoolOp, FillRule, WindowKind};
//! use clip_oracle::{OutputRules, REGION_TOLERANCE, check_polygon_result};
//! use clip_testkit::workload::polygon_case;
//!
//! // Case 0 of the seeded `star` workload: the same polygons on every machine.
//! let case = polygon_case("star", 42, 0, WindowKind::Any).unwrap();
//! assert_eq!(case, polygon_case("star", 42, 0, WindowKind::Any).unwrap());
//! // A ∩ A = A: the subject is the right answer for its intersection with itself.
//! let a = &case.subject;
//! let rules = OutputRules::conventional(REGION_TOLERANCE);
//! assert!(check_polygon_result(a, a, BoolOp::Intersection, FillRule::NonZero, a, &rules).is_ok());
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

use std::path::PathBuf;

pub mod case_record;
pub mod clipper2_suite;
pub mod line_probe;
pub mod shrink;
pub mod workload;

/// The repository's `testdata/` folder (Clipper2's suites in `clipper2/`, geo's fixtures in
/// `geo/`, the world map in `world/`), found from this crate's source directory, or the folder
/// `CLIPBENCH_TESTDATA` names.
pub fn testdata_dir() -> PathBuf {
    match std::env::var_os("CLIPBENCH_TESTDATA") {
        Some(dir) => PathBuf::from(dir),
        None => PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../testdata")),
    }
}
