//! Where a result came from: seed, git revision, machine and date, written beside every CSV.

use std::path::Path;
use std::time::{SystemTime, UNIX_EPOCH};

use serde::{Deserialize, Serialize};

use crate::cli_error::CliError;
use crate::measure::git_revision::checkout_revision;
use crate::write::write_file;

/// The machine a run happened on.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Machine {
    /// Host name, or "unknown".
    pub hostname: String,
    /// CPU model from /proc/cpuinfo, or "unknown".
    pub cpu: String,
    /// Cores available to this process.
    pub cores: usize,
    /// Operating system and architecture, e.g. "linux x86_64".
    pub os: String,
}

/// The sidecar of one raw result file (`<name>.meta.json`): how to reproduce it and where it ran.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Provenance {
    /// The command, e.g. "reproduce vatti-table3".
    pub command: String,
    /// Seed of every generated case.
    pub seed: u64,
    /// The git revision the binary was built from (`git rev-parse HEAD` at build time), with
    /// "+dirty" when the code differed from that commit; "unknown" outside git.
    pub git_revision: String,
    /// Where it ran.
    pub machine: Machine,
    /// UTC time the measurements ended and the files were written, ISO 8601.
    pub date: String,
    /// Command-specific settings (repetitions, sizes, caps), as given.
    pub parameters: serde_json::Value,
    /// Things a reader must know: skipped points, substitutions, missing clippers.
    pub notes: Vec<String>,
}

impl Provenance {
    /// The provenance of a run whose measurements end now.
    pub fn now(command: &str, seed: u64, parameters: serde_json::Value) -> Provenance {
        let built = BUILD_REVISION.to_owned();
        // A long run can outlast the checkout it was built from: say so rather than stamp the new HEAD.
        let notes = match checkout_revision() {
            Some(head) if head != built && built != "unknown" => {
                vec![format!("built from {built}; the checkout was at {head} when the results were written")]
            }
            _ => Vec::new(),
        };
        Provenance {
            command: command.to_owned(),
            seed,
            git_revision: built,
            machine: machine(),
            date: utc_now(),
            parameters,
            notes,
        }
    }

    /// One line for tables: "seed 1, git abc1234, host (CPU, 2 cores), 2026-01-01T00:00:00Z".
    pub fn summary(&self) -> String {
        let rev: String = self.git_revision.chars().take(12).collect();
        format!(
            "seed {}, git {}, {} ({}, {} cores, {}), {}",
            self.seed, rev, self.machine.hostname, self.machine.cpu, self.machine.cores, self.machine.os, self.date
        )
    }

    /// Writes the sidecar as pretty JSON.
    pub fn write(&self, path: &Path) -> Result<(), CliError> {
        let text = serde_json::to_string_pretty(self)
            .map_err(|e| CliError::failed(format!("{}: cannot encode ({e})", path.display())))?;
        write_file(path, &(text + "\n"))
    }

    /// Reads a sidecar written by [`Provenance::write`].
    pub fn read(path: &Path) -> Result<Provenance, CliError> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| CliError::failed(format!("{}: cannot read ({e})", path.display())))?;
        serde_json::from_str(&text)
            .map_err(|e| CliError::failed(format!("{}: not a result sidecar ({e})", path.display())))
    }
}

/// The revision this binary was built from, stamped by the build script.
const BUILD_REVISION: &str = env!("CLIPBENCH_BUILD_REVISION");

fn machine() -> Machine {
    let hostname = std::fs::read_to_string("/proc/sys/kernel/hostname")
        .or_else(|_| std::fs::read_to_string("/etc/hostname"))
        .map(|s| s.trim().to_owned())
        .ok()
        .or_else(|| std::env::var("HOSTNAME").ok())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| "unknown".to_owned());
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|text| {
            text.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, v)| v.split_whitespace().collect::<Vec<_>>().join(" "))
        })
        .unwrap_or_else(|| "unknown".to_owned());
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    Machine { hostname, cpu, cores, os: format!("{} {}", std::env::consts::OS, std::env::consts::ARCH) }
}

fn utc_now() -> String {
    let secs = SystemTime::now().duration_since(UNIX_EPOCH).map_or(0, |d| d.as_secs());
    utc_string(secs)
}

/// `secs` since 1970 as `YYYY-MM-DDThh:mm:ssZ` (proleptic Gregorian, days-to-civil).
fn utc_string(secs: u64) -> String {
    let days = (secs / 86_400) as i64;
    let rem = secs % 86_400;
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1_460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z", rem / 3600, rem / 60 % 60, rem % 60)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates_convert() {
        assert_eq!(utc_string(0), "1970-01-01T00:00:00Z");
        assert_eq!(utc_string(951_782_400), "2000-02-29T00:00:00Z");
        assert_eq!(utc_string(1_795_003_661), "2026-11-18T12:07:41Z");
    }

    #[test]
    fn machine_has_at_least_one_core() {
        assert!(machine().cores >= 1);
    }
}
