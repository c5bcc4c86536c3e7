//! `clipbench hostile`: every selected polygon clipper on the fixed hostile and degenerate set
//! (`clip_testkit::workload::hard_cases`: near-coincident edges, spikes, offsets of 1e9, repeated
//! points, self-touching rings, holes touching their outer, ...), every operation and fill rule
//! it declares, each result sorted into one outcome: right (the oracle passes it), wrong (the
//! oracle rejects it), refused (the library's own error), crashed (a panic, or an external process
//! that died or answered garbage) or hung (no answer within `--call-timeout`).

use std::path::PathBuf;
use std::process::ExitCode;

use clip_core::{BoolOp, FailureKind, FillRule, WindowKind};
use clip_testkit::workload::hard_cases;
use rayon::prelude::*;
use serde::Serialize;

use crate::checks::{Failing, Failure, polygon_oracle, run_polygon};
use crate::cli_error::CliError;
use crate::console;
use crate::registry::Registry;
use crate::results_files::atlas::HostileTally;
use crate::write::write_file;

/// Arguments of `clipbench hostile`.
#[derive(Debug, clap::Args)]
pub struct HostileArgs {
    /// Clipper to run (repeat for several; default: every registered polygon clipper that takes any clip operand).
    #[arg(long = "clipper", value_name = "NAME")]
    pub clippers: Vec<String>,
    /// Worker threads, 1 to 1024 (default: one per core). The result does not depend on it.
    #[arg(long, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=crate::verify::MAX_THREADS as u64))]
    pub threads: Option<usize>,
    /// Also write the tally and every result that is not right as JSON to this file.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
    /// External clippers (docs/PROTOCOL.md).
    #[command(flatten)]
    pub external: crate::external::ExternalArgs,
}

/// What became of one call.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Outcome {
    /// The oracle passed the result.
    Right,
    /// The oracle rejected the result.
    Wrong,
    /// The clipper said no: its own error, or a refusal of the input.
    Refused,
    /// A panic, or an external process that exited or answered something that is not a reply.
    Crashed,
    /// No answer within the call time-out.
    Hung,
}

impl Outcome {
    /// The outcome of a failed call, from how it failed.
    pub fn of_failure(failure: &Failure) -> Outcome {
        match failure.how {
            Failing::NoAnswer(FailureKind::Hung) => Outcome::Hung,
            Failing::Panicked | Failing::NoAnswer(FailureKind::Crashed | FailureKind::Garbled) => Outcome::Crashed,
            Failing::Refused | Failing::NoAnswer(FailureKind::Internal | FailureKind::Declined) => Outcome::Refused,
            Failing::Invalid | Failing::Wrong | Failing::AreaIdentity | Failing::Disagrees => Outcome::Wrong,
        }
    }
}

/// A call that was not right.
#[derive(Clone, Debug, Serialize)]
struct Incident {
    clipper: &'static str,
    case: &'static str,
    op: &'static str,
    fill: &'static str,
    outcome: Outcome,
    message: String,
}

/// Runs the command; it reports, and fails only on a usage error.
pub fn run(args: &HostileArgs, registry: Registry) -> Result<ExitCode, CliError> {
    let registry = registry.select(&args.clippers)?;
    let entries: Vec<_> =
        registry.polygon.iter().filter(|e| e.clipper.capabilities().window == WindowKind::Any).collect();
    if entries.is_empty() {
        return Err(CliError::usage("no selected polygon clipper takes any clip operand"));
    }
    let cases = hard_cases();
    let calls: Vec<(usize, usize, BoolOp, FillRule)> = (0..entries.len())
        .flat_map(|e| {
            let caps = entries[e].clipper.capabilities();
            (0..cases.len()).flat_map(move |c| {
                BoolOp::ALL.into_iter().filter(move |o| caps.ops.contains(o)).flat_map(move |op| {
                    FillRule::ALL
                        .into_iter()
                        .filter(move |f| caps.fill_rules.contains(f))
                        .map(move |fill| (e, c, op, fill))
                })
            })
        })
        .collect();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.unwrap_or(0))
        .build()
        .map_err(|e| CliError::failed(format!("cannot start worker threads: {e}")))?;
    let results: Vec<(Outcome, String)> = pool.install(|| {
        calls
            .par_iter()
            .map(|&(e, c, op, fill)| {
                let (entry, case) = (entries[e], &cases[c]);
                match run_polygon(entry, &case.subject, &case.clip, op, fill) {
                    Err(failure) => (Outcome::of_failure(&failure), failure.message),
                    Ok(out) => match polygon_oracle(entry, &case.subject, &case.clip, op, fill, &out) {
                        Ok(_) => (Outcome::Right, String::new()),
                        Err(failure) => (Outcome::Wrong, failure.message),
                    },
                }
            })
            .collect()
    });
    let mut tallies: Vec<HostileTally> = entries
        .iter()
        .map(|e| HostileTally {
            clipper: e.clipper.name().to_owned(),
            handshake: e.handshake.clone(),
            ..HostileTally::default()
        })
        .collect();
    let mut incidents = Vec::new();
    for (&(e, c, op, fill), (outcome, message)) in calls.iter().zip(results) {
        let t = &mut tallies[e];
        t.runs += 1;
        *match outcome {
            Outcome::Right => &mut t.right,
            Outcome::Wrong => &mut t.wrong,
            Outcome::Refused => &mut t.refused,
            Outcome::Crashed => &mut t.crashed,
            Outcome::Hung => &mut t.hung,
        } += 1;
        if outcome != Outcome::Right {
            incidents.push(Incident {
                clipper: entries[e].clipper.name(),
                case: cases[c].name,
                op: op.name(),
                fill: fill.name(),
                outcome,
                message,
            });
        }
    }
    let mut s = format!(
        "{} hostile cases ({}), every operation and fill rule each clipper declares\n{:<18} {:>5} {:>6} {:>6} {:>8} {:>8} {:>5}\n",
        cases.len(),
        cases.iter().map(|c| c.name).collect::<Vec<_>>().join(", "),
        "clipper",
        "runs",
        "right",
        "wrong",
        "refused",
        "crashed",
        "hung"
    );
    for t in &tallies {
        s += &format!(
            "{:<18} {:>5} {:>6} {:>6} {:>8} {:>8} {:>5}\n",
            t.clipper, t.runs, t.right, t.wrong, t.refused, t.crashed, t.hung
        );
    }
    console::print(&s)?;
    // Which cases each clipper gets wrong or fails on, in one line per clipper.
    for t in &tallies {
        let mut names: Vec<&str> = incidents.iter().filter(|i| i.clipper == t.clipper).map(|i| i.case).collect();
        names.dedup();
        if !names.is_empty() {
            console::print_line(format_args!("{}: not right on {}", t.clipper, names.join(", ")))?;
        }
    }
    if let Some(path) = &args.json {
        let text = serde_json::to_string_pretty(&serde_json::json!({ "tallies": tallies, "incidents": incidents }))
            .map_err(|e| CliError::failed(e.to_string()))?
            + "\n";
        write_file(path, &text)?;
    }
    Ok(ExitCode::SUCCESS)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failures_are_sorted_by_how_they_failed() {
        let of = |how| Outcome::of_failure(&Failure { how, message: String::new() });
        assert_eq!(of(Failing::NoAnswer(FailureKind::Hung)), Outcome::Hung);
        assert_eq!(of(Failing::NoAnswer(FailureKind::Crashed)), Outcome::Crashed);
        assert_eq!(of(Failing::NoAnswer(FailureKind::Garbled)), Outcome::Crashed);
        assert_eq!(of(Failing::Panicked), Outcome::Crashed);
        assert_eq!(of(Failing::NoAnswer(FailureKind::Declined)), Outcome::Refused);
        assert_eq!(of(Failing::NoAnswer(FailureKind::Internal)), Outcome::Refused);
        assert_eq!(of(Failing::Refused), Outcome::Refused);
    }
}
