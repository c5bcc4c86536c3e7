//! clip-fuzz-checks: what the fuzz targets in `fuzz/` decode from their bytes and check, kept
//! in a normal library so the stable test suite replays the same checks on the checked-in corpora
//! and crashes (`tests/replay.rs`) without nightly or libFuzzer.
//!
//! Each target is a function from bytes to `Result<(), String>` ([`TARGETS`]). The bytes are
//! decoded with `arbitrary` into small structured inputs ([`shape`]): polygons on a grid of any
//! magnitude (so points and edges coincide), with repeated points, collinear runs, spikes, ulp
//! nudges, shared vertices and raw floats. An `Err` (or a panic) is a finding:
//!
//! - `vatti`: B. R. Vatti, *A generic solution to polygon clipping*, Communications of the ACM
//!   35(7):56-63, 1992, on two operands under any fill rule, every operation checked by the
//!   exact oracle (`clip_oracle::check_polygon_result`), the area identities and two region
//!   identities;
//! - `window_clippers`: Sutherland-Hodgman (I. E. Sutherland, G. W. Hodgman, *Reentrant polygon
//!   clipping*, Communications of the ACM 17(1):32-42, 1974) in both forms and the four-state
//!   rectangle clipper, by the oracle (bridged output) and against vatti;
//! - `line_clippers`: Cyrus-Beck, Liu and both virtual-box clippers (J. Wang, G. Lu, Q. Peng,
//!   X. Wu, *Line clipping against polygonal window algorithm based on the multiple virtual boxes
//!   rejecting*, J. Zhejiang Univ. SCIENCE A 6(Suppl. I):100-107, 2005) by the exact line oracle;
//! - `readers`: every file format the `clipbench` CLI reads: a typed error or a value.
//!
//! Limits: inputs are bounded ([`shape::MAX_RINGS`] rings of [`shape::MAX_STEPS`] steps per
//! operand, [`lines::MAX_SEGMENTS`] segments) so one run stays fast; a hang is caught by
//! libFuzzer's `-timeout`, not here. The checks are only as strong as the oracles' tolerances.
//!
//! ```
//! // Bytes too short to decode are not a case; every target accepts them.
//! for target in clip_fuzz_checks::TARGETS {
//!     assert_eq!((target.check)(&[]), Ok(()));
//! }
//! ```

#[cfg(doctest)]
#[doc = include_str!("../README.md")]
pub struct ReadmeDoctests;

pub mod encode;
pub mod lines;
pub mod picture;
pub mod readers;
pub mod shape;
pub mod vatti;
pub mod windows;

use std::path::PathBuf;

use arbitrary::Arbitrary;
use clip_core::{FillRule, Polygons, VisiblePiece};

/// A fill rule, decodable from bytes.
#[derive(Arbitrary, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fill {
    /// `FillRule::EvenOdd`.
    EvenOdd,
    /// `FillRule::NonZero`.
    NonZero,
    /// `FillRule::Positive`.
    Positive,
    /// `FillRule::Negative`.
    Negative,
}

impl From<Fill> for FillRule {
    fn from(f: Fill) -> FillRule {
        match f {
            Fill::EvenOdd => FillRule::EvenOdd,
            Fill::NonZero => FillRule::NonZero,
            Fill::Positive => FillRule::Positive,
            Fill::Negative => FillRule::Negative,
        }
    }
}

/// What a check saw when it passed, for pictures.
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// Every clipper refused the input, as it should have.
    Refused,
    /// Polygon results, by name.
    Polygons(Vec<(&'static str, Polygons)>),
    /// Line clipping results, by clipper name.
    Lines(Vec<(&'static str, Vec<VisiblePiece>)>),
}

/// One fuzz target: its name (as in `fuzz/fuzz_targets/<name>.rs`) and its check.
#[derive(Clone, Copy, Debug)]
pub struct Target {
    /// The name of the target, of its corpus folder and of its regressions folder.
    pub name: &'static str,
    /// Decodes the bytes and checks them; `Err` is a finding.
    pub check: fn(&[u8]) -> Result<(), String>,
}

/// Every target.
pub const TARGETS: &[Target] = &[
    Target { name: "vatti", check: vatti::check_bytes },
    Target { name: "window_clippers", check: windows::check_bytes },
    Target { name: "line_clippers", check: lines::check_bytes },
    Target { name: "readers", check: readers::check_bytes },
];

/// The target called `name`.
pub fn target(name: &str) -> Option<&'static Target> {
    TARGETS.iter().find(|t| t.name == name)
}

/// The repository's `fuzz/` folder (corpora, regressions, the cargo-fuzz crate).
pub fn fuzz_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../fuzz")
}
