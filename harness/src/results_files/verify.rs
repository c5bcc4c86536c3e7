//! The files of `clipbench verify --results DIR`: the summary with its shrunk failure cases, the
//! sidecar, and the folder the cases are written to.

use std::collections::BTreeMap;
use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::cli_error::CliError;
use crate::partition::Partition;

/// The summary, one [`VerifyResults`] (also what `--json` writes).
pub const JSON: &str = "verify.json";
/// The sidecar of [`JSON`].
pub const META: &str = "verify.meta.json";
/// The folder of shrunk failure cases, one sub-folder per [`CaseEntry`].
pub const FAILURES: &str = "verify-failures";
/// The picture of the failure in each case's folder, which the report shows.
pub const PICTURE: &str = "picture.svg";

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
    /// The part of the cases run (`verify --partition K/N`), none for all of them.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub partition: Option<Partition>,
}

/// The counts of one clipper on one workload, as the file holds them.
pub type VerifyRow = CountsRow<String>;

/// The counts of one clipper on one workload, its names of type `S`: owned in the file
/// ([`VerifyRow`]), static while verify counts.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct CountsRow<S: Ord> {
    /// Clipper name.
    pub clipper: S,
    /// `ours`, `peer`, `external` or `strict`.
    pub origin: S,
    /// `polygon` or `line`.
    pub kind: S,
    /// Workload name.
    pub workload: S,
    /// Generated input cases the clipper ran on.
    pub cases: usize,
    /// Checked results: one per case, operation and fill rule (one per case for lines).
    pub runs: usize,
    /// Results the oracle rejected (including refusals and failures to answer, but not hangs):
    /// with `hung`, at most `runs`.
    pub oracle_failures: usize,
    /// Runs where an external clipper gave no answer within the call time-out: not a wrong
    /// answer (counted in `oracle_failures` by files written before they were counted apart).
    #[serde(default)]
    pub hung: usize,
    /// Cases and fill rules whose four results break an area identity (not runs themselves;
    /// counted in `oracle_failures` by files written before they were counted apart).
    #[serde(default)]
    pub identity_failures: usize,
    /// Results that differ by region (or by visible intervals) from another clipper's while both
    /// passed the oracle, per other clipper; where one side failed, the difference is counted as
    /// that side's oracle failure instead.
    pub disagreements: BTreeMap<S, usize>,
    /// Zero-width bridges in the output, for clippers whose capabilities say they make them.
    pub bridges: Option<usize>,
}

impl<S: Ord + Clone> CountsRow<S> {
    /// Adds another part's counts of the same clipper, kind and workload.
    pub fn add(&mut self, other: &CountsRow<S>) {
        self.cases += other.cases;
        self.runs += other.runs;
        self.oracle_failures += other.oracle_failures;
        self.hung += other.hung;
        self.identity_failures += other.identity_failures;
        for (name, n) in &other.disagreements {
            *self.disagreements.entry(name.clone()).or_default() += n;
        }
        if let Some(b) = other.bridges {
            self.bridges = Some(self.bridges.unwrap_or(0) + b);
        }
    }

    /// The same counts with owned names, as the file holds them.
    pub fn to_file(&self) -> VerifyRow
    where
        S: AsRef<str>,
    {
        let own = |s: &S| s.as_ref().to_owned();
        CountsRow {
            clipper: own(&self.clipper),
            origin: own(&self.origin),
            kind: own(&self.kind),
            workload: own(&self.workload),
            cases: self.cases,
            runs: self.runs,
            oracle_failures: self.oracle_failures,
            hung: self.hung,
            identity_failures: self.identity_failures,
            disagreements: self.disagreements.iter().map(|(k, v)| (own(k), *v)).collect(),
            bridges: self.bridges,
        }
    }
}

/// One shrunk failure case written under [`FAILURES`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CaseEntry {
    /// Its folder under the failures folder (holding case.json, WKT and picture.svg).
    pub folder: String,
    /// The run's seed.
    #[serde(default)]
    pub seed: u64,
    /// The case's index in its workload.
    #[serde(default)]
    pub index: usize,
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

/// The positions of the first `max` items of each group (`key`) in order, all of them when `max`
/// is 0, and how many were left out: which failures a run shrinks and writes (the first of each
/// clipper, workload and check), and so which a merge of a run's parts keeps.
pub fn first_of_each<T, K: PartialEq>(items: &[T], max: usize, key: impl Fn(&T) -> K) -> (Vec<usize>, usize) {
    let mut chosen: Vec<usize> = Vec::new();
    let mut skipped = 0;
    for (i, item) in items.iter().enumerate() {
        let k = key(item);
        if max == 0 || chosen.iter().filter(|&&c| key(&items[c]) == k).count() < max {
            chosen.push(i);
        } else {
            skipped += 1;
        }
    }
    (chosen, skipped)
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
