//! clip-testkit: seeded workloads, exact oracles and a shrinker for clipbench.
//!
//! Everything the harness and the algorithm crates' tests need to generate cases and to judge
//! answers, independent of any clipping library:
//!
//! - [`workload`]: every case is a pure function of (workload name, seed, index), seeded with
//!   `rand_pcg::Pcg64` from a hash of the three, so cases do not depend on iteration order or
//!   thread count. Polygon workloads [`workload::POLYGON_WORKLOADS`] (`vatti-t3`, `star`,
//!   `scribble`, `holes`, `multi`, `grid`, `large`), line workloads [`workload::LINE_WORKLOADS`]
//!   (`wang-t4`, `lines-degenerate`), and [`workload::hard_cases`], the fixtures from NOTES.md.
//! - [`polygon_oracle`]: [`polygon_oracle::check_polygon_op`] checks one output: its form
//!   (simple, oriented rings), exact membership at sample points, and the area of the symmetric
//!   difference from [`polygon_oracle::region_area`], a slab decomposition that reads only the
//!   input rings. Plus area identities across the four ops, region comparison and bridge counts.
//! - [`line_oracle`]: [`line_oracle::visible_intervals`], DESIGN.md's closed-set rule computed with
//!   exact incidences, and [`line_oracle::check_line_batch`] for a clipper's pieces.
//! - [`line_probe`]: named singular line cases (through a vertex, along an edge, endpoint on the
//!   boundary, ...) with hand-computed answers, run through any line clipper in both directions
//!   and both window orientations, checked against the answers and against the line oracle.
//! - [`shrink`]: reduces a failing case while it still fails, with bounded work.
//! - [`case_record`]: WKT text and SVG pictures of inputs and outputs for failure reports.
//! - `peers` (feature `peers`): `geo` and Clipper2 behind clip-core's traits, and
//!   `clipper2_suite`: Clipper2's `Polygons.txt` / `Lines.txt` records and the grading of its
//!   own test, shared by the harness's conformance command and clip-vatti's tests.
//!
//! # The papers' vocabulary here
//!
//! - Vatti, "A generic solution to polygon clipping" (../shared/papers/000): Table 3's subject
//!   polygons "of a varying number of edges", concave, fitted in 1280 x 1024, against one convex
//!   clip polygon, are `vatti-t3` ([`workload::VATTI_EDGES`], [`workload::vatti_window`]).
//! - Wang et al., "Line clipping against polygonal window ... multiple virtual boxes"
//!   (../shared/papers/002): Table 4's "10000 random line segments" in an 800 x 600 screen against
//!   polygons of 6-50 edges at sizes W1 and W2 are `wang-t4` ([`workload::wang_window`],
//!   [`workload::wang_segments`]); the MEB is a window's bounding box; how the sizes are read is
//!   documented on [`workload::WangSize`]'s module.
//! - "Visible section of the line segment" (Wang's Table 3) is a visible interval here.
//!
//! # Limits
//!
//! - The polygon oracle's areas are f64 sums of trapezoids with crossing heights rounded, so the
//!   region check has a tolerance ([`polygon_oracle::REGION_TOLERANCE`] of the inputs' box area,
//!   [`polygon_oracle::GEO_TOLERANCE`] against the peers); membership at sample points and the
//!   line oracle's in/out decisions are exact. Sample points within a margin of any edge are
//!   skipped, so a wrong answer thinner than the margin is caught by area only.
//! - Output validity allows rings to touch at points and different rings to share an edge; it
//!   rejects proper crossings, crossings at a shared point, and a ring overlapping itself.
//! - `region_area` costs O(s m + k log k): s distinct vertex heights, m edges crossing a typical
//!   horizontal line, k edge crossings (found as order inversions per slab, not by a global
//!   Bentley-Ottmann sweep). Checking a 20-edge pair takes tens of microseconds, a 200-edge
//!   star pair about half a millisecond, a self-intersecting `scribble` case with a 2000-vertex
//!   output a few milliseconds, two 10^5-vertex smooth blobs tens of milliseconds.
//!
//! # Example
//!
//! ```
//! use clip_core::{BoolOp, FillRule, Polygons, Rect, WindowKind};
//! use clip_testkit::polygon_oracle::{OutputRules, REGION_TOLERANCE, check_polygon_op};
//! use clip_testkit::workload::polygon_case;
//!
//! let case = polygon_case("star", 42, 0, WindowKind::Any).unwrap();
//! // A ∩ A = A: the subject is the right answer for its intersection with itself...
//! let rules = OutputRules::conventional(REGION_TOLERANCE);
//! let a = &case.subject;
//! assert!(check_polygon_op(a, a, BoolOp::Intersection, FillRule::NonZero, a, &rules).is_ok());
//! // ...and the oracle catches a wrong answer.
//! let wrong = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0));
//! assert!(check_polygon_op(a, a, BoolOp::Intersection, FillRule::NonZero, &wrong, &rules).is_err());
//! ```

pub mod case_record;
pub mod line_oracle;
pub mod line_probe;
pub mod polygon_oracle;
pub mod shrink;
pub mod workload;

#[cfg(feature = "peers")]
pub mod clipper2_suite;
#[cfg(feature = "peers")]
pub mod peers;
