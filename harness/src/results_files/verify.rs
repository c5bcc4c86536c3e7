//! The files of `clipbench verify --results DIR`: the summary with its shrunk failure cases, the
//! sidecar, and the folder the cases are written to.

use std::collections::BTreeMap;
use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::cli_error::CliError;

/// The summary, one [`VerifyResults`] (also what `--json` writes).
pub const JSON: &str = "verify.json";
/// The sidecar of [`JSON`].
pub const META: &str = "verify.meta.json";
/// The folder of shrunk failure cases, one sub-folder per [`CaseEntry`].
pub const FAILURES: &str = "verify-failures";

/// A verify run: counts per clipper and workload, and the failure cases written.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VerifyResults {
    /// The seed every case was generated from.
    pub seed: u64,
    /// Cases per workload.
    pub cases_per_workload: usize,
    /// One row per clipper and workload it ran on.
    pub rows: Vec<VerifyRow>,
    /// Failure folders written.
    pub failures_recorded: usize,
    /// Failures found but not written because of `--max-records`.
    pub failures_not_recorded: usize,
    /// True when a clipper whose failures fail the run (ours, or external under `--strict`)
    /// failed the oracle.
    pub ours_failed: bool,
    /// The failure folders written, shrunk, in the order found.
    #[serde(default)]
    pub cases: Vec<CaseEntry>,
}

/// The counts of one clipper on one workload.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct VerifyRow {
    /// Clipper name.
    pub clipper: String,
    /// `ours`, `peer`, `external` or `strict`.
    pub origin: String,
    /// `polygon` or `line`.
    pub kind: String,
    /// Workload name.
    pub workload: String,
    /// Generated input cases the clipper ran on.
    pub cases: usize,
    /// Checked results: one per case, operation and fill rule (one per case for lines).
    pub runs: usize,
    /// Results the oracle rejected (including refusals, failures to answer and failed area
    /// identities).
    pub oracle_failures: usize,
    /// Results that differ from another clipper's while both passed the oracle, per other clipper.
    pub disagreements: BTreeMap<String, usize>,
    /// Zero-width bridges in the output, for clippers whose capabilities say they make them.
    pub bridges: Option<usize>,
}

/// One shrunk failure case written under [`FAILURES`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CaseEntry {
    /// Its folder under the failures folder (holding case.json, WKT and picture.svg).
    pub folder: String,
    /// `polygon` or `line`.
    pub kind: String,
    /// The clipper the failure is counted under.
    pub clipper: String,
    /// Workload the case came from.
    pub workload: String,
    /// `oracle`, `area-identities` or `disagreement`.
    pub check: String,
    /// For a disagreement, the other clipper.
    pub other: Option<String>,
    /// The operation (polygons, except area identities).
    pub op: Option<String>,
    /// The fill rule (polygons).
    pub fill: Option<String>,
    /// Vertex counts of the two shrunk inputs.
    pub shrunk_vertices: [usize; 2],
    /// The failure on the shrunk inputs.
    pub shrunk: String,
}

/// Reads [`JSON`] from `out`; no file means no verify results.
pub fn read(out: &Path) -> Result<Option<VerifyResults>, CliError> {
    let path = out.join(JSON);
    if !path.exists() {
        return Ok(None);
    }
    let text = std::fs::read_to_string(&path)
        .map_err(|e| CliError::failed(format!("{}: cannot read ({e})", path.display())))?;
    serde_json::from_str(&text)
        .map(Some)
        .map_err(|e| CliError::failed(format!("{}: not a verify summary ({e})", path.display())))
}
