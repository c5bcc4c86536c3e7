//! The files of the atlas (`scripts/atlas.sh`): what `conformance --json`, `hostile --json` and
//! `referee --json` write, beside `verify --json` and `bench` files of their own kinds. The
//! commands write these types and `report` reads them back, so neither imports the other.

use std::path::Path;

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use crate::cli_error::CliError;

/// The atlas's folder inside a results folder.
pub const FOLDER: &str = "atlas";
/// `hostile --json`'s file in [`FOLDER`].
pub const HOSTILE_JSON: &str = "hostile.json";
/// The folder of `bench`'s files in [`FOLDER`].
pub const BENCH_FOLDER: &str = "bench";
/// Folders `verify-N` hold `verify --json` files, one per workload, of N cases each.
pub const VERIFY_PREFIX: &str = "verify-";
/// Folders `referee-N` hold `referee --json` files, one per workload, of N cases each.
pub const REFEREE_PREFIX: &str = "referee-";

/// The conformance suites of the atlas, by the name `conformance` prints before each failure.
pub const CONFORMANCE_SUITES: [&str; 2] = ["clipper2-polygons", "geo-booleanop"];

/// `conformance-SUITE.json` (what `conformance --json` writes) or, from runs before it
/// existed, `conformance-SUITE.txt` (its printed lines).
pub fn conformance_file(suite: &str, extension: &str) -> String {
    format!("conformance-{suite}.{extension}")
}

/// What `conformance --json` writes: one suite's counts per clipper.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ConformanceResults {
    /// The suite (`clipper2-polygons`, `clipper2-lines`, `geo-booleanop`).
    pub suite: String,
    /// One tally per clipper run, in the order run.
    pub clippers: Vec<ConformanceTally>,
}

/// One clipper's counts on a conformance suite.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ConformanceTally {
    /// Clipper name.
    pub clipper: String,
    /// Cases whose expected answer it gave.
    pub passed: usize,
    /// Cases it answered wrongly, refused or failed on.
    pub failed: usize,
    /// Cases it does not declare (operation, fill rule or window) or that do not apply.
    pub skipped: usize,
    /// For an external clipper, the name its handshake gave (library and version).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub handshake: Option<String>,
}

impl ConformanceTally {
    /// The line `conformance` prints for it: `NAME: P passed, F failed, S skipped` (no skipped
    /// part when none was skipped).
    pub fn line(&self) -> String {
        let skipped = if self.skipped > 0 { format!(", {} skipped", self.skipped) } else { String::new() };
        format!("{}: {} passed, {} failed{skipped}", self.clipper, self.passed, self.failed)
    }

    /// The tally of a [`ConformanceTally::line`]; `None` for any other line (a failing case's,
    /// a note's).
    pub fn from_line(line: &str) -> Option<ConformanceTally> {
        let (clipper, counts) = line.split_once(": ")?;
        if clipper.is_empty() || clipper.contains(' ') {
            return None;
        }
        let mut tally = ConformanceTally { clipper: clipper.to_owned(), ..ConformanceTally::default() };
        let parts: Vec<&str> = counts.trim_end().split(", ").collect();
        if !(2..=3).contains(&parts.len()) {
            return None;
        }
        for (part, word) in parts.iter().zip(["passed", "failed", "skipped"]) {
            let (n, w) = part.split_once(' ')?;
            if w != word {
                return None;
            }
            let n: usize = n.parse().ok()?;
            match word {
                "passed" => tally.passed = n,
                "failed" => tally.failed = n,
                _ => tally.skipped = n,
            }
        }
        Some(tally)
    }
}

/// One clipper's counts on the hostile cases (`hostile --json`'s `tallies`).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct HostileTally {
    /// Clipper name.
    pub clipper: String,
    /// Calls made.
    pub runs: usize,
    /// Results the oracle passed.
    pub right: usize,
    /// Results the oracle rejected.
    pub wrong: usize,
    /// Refusals and library errors.
    pub refused: usize,
    /// Panics, exits, garbage.
    pub crashed: usize,
    /// Time-outs.
    pub hung: usize,
    /// For an external clipper, the name its handshake gave (library and version).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub handshake: Option<String>,
}

/// The part of `hostile --json` the report reads (the incidents are for people).
#[derive(Clone, Debug, Deserialize)]
pub struct HostileResults {
    /// One tally per clipper.
    pub tallies: Vec<HostileTally>,
}

/// One workload's tally of a referee against the oracle's region areas.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct RefereeTally {
    /// Workload.
    pub workload: String,
    /// Cases run.
    pub cases: usize,
    /// Results compared.
    pub compared: usize,
    /// Calls the referee did not answer with a result (its error, a crash or a time-out).
    pub failed: usize,
    /// The largest relative area difference.
    pub largest_relative: f64,
    /// The largest difference as a multiple of the rounding bound.
    pub largest_of_bound: f64,
    /// Results whose difference is beyond rounding.
    pub beyond_rounding: usize,
}

impl RefereeTally {
    /// Adds another part's tally of the same workload (`referee --partition`): counts add up,
    /// the largest differences are the larger of the two.
    pub fn join(&mut self, part: &RefereeTally) {
        self.cases += part.cases;
        self.compared += part.compared;
        self.failed += part.failed;
        self.largest_relative = self.largest_relative.max(part.largest_relative);
        self.largest_of_bound = self.largest_of_bound.max(part.largest_of_bound);
        self.beyond_rounding += part.beyond_rounding;
    }
}

/// The part of `referee --json` the report reads.
#[derive(Clone, Debug, Deserialize)]
pub struct RefereeResults {
    /// The referee clipper's name.
    pub referee: String,
    /// Cases per workload asked for.
    pub cases_per_workload: usize,
    /// The part of the cases run (`referee --partition K/N`), none for all of them.
    #[serde(default)]
    pub partition: Option<crate::partition::Partition>,
    /// One tally per workload.
    pub workloads: Vec<RefereeTally>,
}

/// A JSON file read as `T`, with its path in any error.
pub fn read_json<T: DeserializeOwned>(path: &Path, what: &str) -> Result<T, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::failed(format!("{}: cannot read ({e})", path.display())))?;
    serde_json::from_str(&text).map_err(|e| CliError::failed(format!("{}: not {what} ({e})", path.display())))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_printed_tally_line_reads_back_and_other_lines_do_not() {
        let line = "martinez: 68 passed, 12 failed, 3 skipped";
        let t = ConformanceTally::from_line(line).unwrap();
        assert_eq!((t.clipper.as_str(), t.passed, t.failed, t.skipped), ("martinez", 68, 12, 3));
        assert_eq!(t.line(), line);
        let none_skipped = ConformanceTally { clipper: "vatti".into(), passed: 5, ..ConformanceTally::default() };
        assert_eq!(ConformanceTally::from_line(&none_skipped.line()), Some(none_skipped));
        for other in [
            "geo-booleanop fatal2/union polybooljs: expected a result, got polybooljs failed: it answered",
            "  (clipper2: of its passes, 3 by the exact area where the stored one is off, 0 by Clipper2's live ring count)",
            "x: 1 passed",
            "x: 1 passed, 2 skipped",
            "x: many passed, 0 failed",
        ] {
            assert_eq!(ConformanceTally::from_line(other), None, "{other}");
        }
    }
}
