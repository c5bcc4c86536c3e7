//! `clipbench verify`: every selected clipper on every workload, operation and fill rule it
//! supports, against the exact oracles and against each other, in parallel and deterministic per
//! seed whatever the thread count.

mod case_geojson;
mod curve_runs;
mod failure_mark;
mod finding;
mod line_runs;
mod polygon_runs;
mod recheck;
pub mod record;
pub mod replay;
pub mod replay_case;
mod summary;
mod text_runs;

use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use clip_core::{BoolOp, FillRule};
use clip_testkit::shrink::{MAX_TRIES, ShrinkLimit};
use clip_testkit::workload::{CURVE_WORKLOADS, LINE_WORKLOADS, POLYGON_WORKLOADS, TEXT_WORKLOADS};
use clip_text::{DEJAVU_SANS, OutlineFont};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde_json::json;

use self::curve_runs::CurvePlan;
use self::finding::{CaseOutcome, Finding};
use self::line_runs::LinePlan;
use self::polygon_runs::PolygonPlan;
use self::summary::{Row, Summary, table};
use self::text_runs::{TEXT_STRATEGIES, TextPlan};
use crate::cli_error::CliError;
use crate::console;
use crate::measure::out_dir::ready_out_dir;
use crate::measure::provenance::Provenance;
use crate::partition::Partition;
use crate::registry::Registry;
use crate::results_files::verify::{self as verify_files, CaseEntry, first_of_each};
use crate::write::write_file;

/// Arguments of `clipbench verify`.
#[derive(Debug, clap::Args)]
pub struct VerifyArgs {
    /// Clipper to verify (repeat for several; default: every registered clipper). The text
    /// workload's rows are named text-string, text-char, text-outline and text-bitmap.
    #[arg(long = "clipper", value_name = "NAME")]
    pub clippers: Vec<String>,
    /// Workload to run (repeat for several; default: every workload). Polygon workloads run
    /// the polygon clippers, line workloads the line clippers, curve workloads (`circles`,
    /// `ellipses`) the curve clippers.
    #[arg(long = "workload", value_name = "NAME")]
    pub workloads: Vec<String>,
    /// Generated cases per workload (1 or more); each case runs every supported operation and
    /// fill rule.
    #[arg(long, default_value_t = 100, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..))]
    pub cases: usize,
    /// Seed of the case generators: the same seed gives the same cases and the same summary.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Operation to run (repeat; default: all four).
    #[arg(long = "op", value_name = "OP")]
    pub ops: Vec<BoolOp>,
    /// Fill rule to run (repeat; default: all four).
    #[arg(long = "fill", value_name = "RULE")]
    pub fills: Vec<FillRule>,
    /// Segments per line case.
    #[arg(long, default_value_t = 100)]
    pub segments: usize,
    /// Folder the failure cases are written to, one sub-folder each (default: verify-failures,
    /// or RESULTS/verify-failures with --results).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Failures shrunk and written per clipper, workload and check (0: all of them).
    #[arg(long, default_value_t = 10)]
    pub max_records: usize,
    /// Seconds a failure may spend being shrunk, after which its smallest failing case so far is
    /// written (a hang costs the whole --call-timeout on every try). The case file says when it
    /// stopped early.
    #[arg(long, value_name = "SECONDS", default_value_t = 60.0, value_parser = parse_shrink_seconds)]
    pub shrink_seconds: f64,
    /// Worker threads, 1 to 1024 (default: one per core; never more than there are cases). The
    /// summary does not depend on it.
    #[arg(long, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=MAX_THREADS as u64))]
    pub threads: Option<usize>,
    /// Run only part K of N of the cases (as 3/8): N jobs, each with the same options and its own
    /// K and --results folder, run the whole set between them with no coordination; `clipbench
    /// merge` then joins their folders into the one a single run writes. Case j of the run's list
    /// (workload by workload, index by index, from 0) is in part j mod N + 1.
    #[arg(long, value_name = "K/N")]
    pub partition: Option<Partition>,
    /// Also write the summary as JSON to this file.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
    /// Write the run as a result for `clipbench report` into this folder: verify.json (the
    /// summary and the failure cases), its verify.meta.json sidecar, and the shrunk cases under
    /// verify-failures/ (replacing that folder). REPORT.md's "Where the clippers disagree with
    /// the oracle" is drawn from them.
    #[arg(long, value_name = "DIR", conflicts_with = "out")]
    pub results: Option<PathBuf>,
    /// External clippers (docs/PROTOCOL.md).
    #[command(flatten)]
    pub external: crate::external::ExternalArgs,
    /// Re-run one saved failure (the case.json of a failure folder) instead of a verify run.
    #[arg(long, value_name = "FILE", conflicts_with_all = ["workloads", "cases", "json", "threads", "partition"])]
    pub replay: Option<PathBuf>,
}

/// The most worker threads `--threads` takes: more than cases or cores only costs time, and some
/// thousands of threads exhaust what a process may start.
pub const MAX_THREADS: usize = 1024;

/// `--shrink-seconds`' value: at least 0 (0 writes each failure as generated) and at most a day.
fn parse_shrink_seconds(text: &str) -> Result<f64, String> {
    let seconds: f64 = text.trim().parse().map_err(|_| format!("'{text}' is not a number of seconds"))?;
    let day = crate::external::MAX_CALL_TIMEOUT_SECONDS;
    if !(0.0..=day).contains(&seconds) {
        return Err(format!("{text} seconds: the shrinking time must be at least 0 and at most {day} (a day)"));
    }
    Ok(seconds)
}

/// Runs the command: exit 1 when a clipper of this project fails the oracle.
pub fn run(args: &VerifyArgs, registry: Registry) -> Result<ExitCode, CliError> {
    if let Some(path) = &args.replay {
        return replay::replay(path, &registry);
    }
    let out = match (&args.out, &args.results) {
        (Some(out), _) => out.clone(),
        (None, Some(dir)) => {
            let failures = ready_out_dir(dir)?.join(verify_files::FAILURES);
            if failures.exists() {
                std::fs::remove_dir_all(&failures)
                    .map_err(|e| CliError::failed(format!("{}: cannot clear it ({e})", failures.display())))?;
            }
            failures
        }
        (None, None) => PathBuf::from("verify-failures"),
    };
    // Text strategies are named beside the registry's clippers; naming only them selects no clipper.
    let (text_names, clipper_names): (Vec<String>, Vec<String>) =
        args.clippers.iter().cloned().partition(|n| TEXT_STRATEGIES.contains(&n.as_str()));
    let registry = if !text_names.is_empty() && clipper_names.is_empty() {
        Registry::default()
    } else {
        registry.select(&clipper_names)?
    };
    let workloads = select_workloads(&args.workloads)?;
    let text_names: Vec<&'static str> =
        TEXT_STRATEGIES.into_iter().filter(|n| args.clippers.is_empty() || text_names.iter().any(|t| t == n)).collect();
    let wants_text = !text_names.is_empty() && workloads.iter().any(|w| TEXT_WORKLOADS.contains(w));
    let text =
        TextPlan { font: if wants_text { Some(load_dejavu()?) } else { None }, names: text_names, seed: args.seed };
    let polygon = PolygonPlan {
        entries: registry.polygon.iter().collect(),
        ops: if args.ops.is_empty() { BoolOp::ALL.to_vec() } else { args.ops.clone() },
        fills: if args.fills.is_empty() { FillRule::ALL.to_vec() } else { args.fills.clone() },
        seed: args.seed,
    };
    let line = LinePlan { entries: registry.line.iter().collect(), segments: args.segments, seed: args.seed };
    let curve = CurvePlan { entries: registry.curve.iter().collect(), seed: args.seed };
    // Work items in a fixed order: (workload, case index).
    let items: Vec<(&'static str, usize)> = workloads
        .iter()
        .filter(|w| {
            if POLYGON_WORKLOADS.contains(w) {
                !polygon.entries.is_empty()
            } else if CURVE_WORKLOADS.contains(w) {
                !curve.entries.is_empty()
            } else if TEXT_WORKLOADS.contains(w) {
                !text.names.is_empty()
            } else {
                !line.entries.is_empty()
            }
        })
        .flat_map(|&w| (0..args.cases).map(move |i| (w, i)))
        .collect();
    if items.is_empty() {
        return Err(CliError::usage("nothing to run: no selected clipper handles the selected workloads"));
    }
    // This part's cases; a part may have none (more parts than cases) and writes empty results.
    let items: Vec<(&'static str, usize)> = match args.partition {
        Some(part) => items.into_iter().enumerate().filter(|(j, _)| part.keeps(*j)).map(|(_, item)| item).collect(),
        None => items,
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.map_or(0, |t| t.min(items.len().max(1))))
        .build()
        .map_err(|e| CliError::failed(format!("cannot start worker threads: {e}")))?;
    let progress = progress_bar(items.len());
    let outcomes: Vec<Result<CaseOutcome, String>> = pool.install(|| {
        items
            .par_iter()
            .map(|&(w, i)| {
                let outcome = if POLYGON_WORKLOADS.contains(&w) {
                    polygon.run(w, i)
                } else if CURVE_WORKLOADS.contains(&w) {
                    curve.run(w, i)
                } else if TEXT_WORKLOADS.contains(&w) {
                    text.run(w, i)
                } else {
                    line.run(w, i)
                };
                progress.inc(1);
                outcome
            })
            .collect()
    });
    progress.finish_and_clear();

    // Reduce in case order, so the result does not depend on scheduling.
    let mut rows: Vec<Row> = Vec::new();
    let mut findings: Vec<Finding> = Vec::new();
    for outcome in outcomes {
        let outcome = outcome.map_err(CliError::failed)?;
        for row in &outcome.rows {
            match rows.iter_mut().find(|r| r.clipper == row.clipper && r.kind == row.kind && r.workload == row.workload)
            {
                Some(r) => r.add(row),
                None => rows.push(row.clone()),
            }
        }
        findings.extend(outcome.findings);
    }
    rows.retain(|r| r.cases > 0);
    let ours: Vec<&str> = registry
        .polygon
        .iter()
        .filter(|e| e.origin.fails_run())
        .map(|e| e.clipper.name())
        .chain(registry.line.iter().filter(|e| e.origin.fails_run()).map(|e| e.clipper.name()))
        .chain(registry.curve.iter().filter(|e| e.origin.fails_run()).map(|e| e.clipper.name()))
        .chain(text.names.iter().copied())
        .collect();
    let ours_failed =
        rows.iter().any(|r| ours.contains(&r.clipper) && r.oracle_failures + r.hung + r.identity_failures > 0);

    // Shrink and write the first failures of each clipper and workload.
    let (chosen, skipped) = first_of_each(&findings, args.max_records, |f| (f.clipper, f.workload, f.check));
    let chosen: Vec<&Finding> = chosen.into_iter().map(|i| &findings[i]).collect();
    let records: Vec<Result<record::Record, String>> = pool.install(|| {
        let limit = ShrinkLimit { tries: MAX_TRIES, time: Some(Duration::from_secs_f64(args.shrink_seconds)) };
        chosen
            .par_iter()
            .map(|f| record::record(&registry, (args.seed, args.segments), limit, f, &out, &text))
            .collect()
    });
    let mut written = Vec::new();
    let mut cases = Vec::new();
    let mut replay = None;
    for r in records {
        let r = r.map_err(CliError::failed)?;
        written.push(r.write(&out)?);
        cases.push(case_entry(&r));
        replay.get_or_insert(r.case.replay);
    }

    let summary = Summary {
        seed: args.seed,
        cases_per_workload: args.cases,
        rows,
        failures_recorded: written.len(),
        failures_not_recorded: skipped,
        ours_failed,
        partition: args.partition,
    };
    console::print(&table(&summary.rows))?;
    console::print_line(
        "(vs X: results that differ from X's while both passed the oracle; a difference where one fails is its oracle failure)",
    )?;
    if let Some(first) = replay {
        console::print_line(format_args!(
            "{} failure case(s) shrunk and written under {}{}; replay one with: {}",
            written.len(),
            out.display(),
            if skipped > 0 { format!(" ({skipped} more not written: --max-records)") } else { String::new() },
            first
        ))?;
    }
    let results = summary.to_file(cases);
    let text = serde_json::to_string_pretty(&results).map_err(|e| CliError::failed(e.to_string()))? + "\n";
    if let Some(path) = &args.json {
        write_file(path, &text)?;
    }
    if let Some(dir) = &args.results {
        write_file(&dir.join(verify_files::JSON), &text)?;
        let parameters = json!({
            "cases_per_workload": args.cases,
            "segments": args.segments,
            "max_records": args.max_records,
            "shrink_seconds": args.shrink_seconds,
            "clippers": registry.names(),
            "workloads": workloads,
            "ops": polygon.ops.iter().map(|o| o.name()).collect::<Vec<_>>(),
            "fill_rules": polygon.fills.iter().map(|f| f.name()).collect::<Vec<_>>(),
            "partition": args.partition.map(|p| p.to_string()),
        });
        Provenance::now("verify", args.seed, parameters).write(&dir.join(verify_files::META))?;
    }
    if ours_failed {
        console::print_line("FAILED: a clipper of this project failed the oracle")?;
        Ok(ExitCode::FAILURE)
    } else {
        Ok(ExitCode::SUCCESS)
    }
}

/// The summary entry of a written failure folder.
fn case_entry(r: &record::Record) -> CaseEntry {
    let c = &r.case;
    CaseEntry {
        folder: r.folder.clone(),
        seed: c.seed,
        index: c.index,
        kind: c.kind.clone(),
        clipper: c.clipper.clone(),
        workload: c.workload.clone(),
        check: c.check.clone(),
        other: c.other.clone(),
        op: c.op.clone(),
        fill: c.fill.clone(),
        shrunk_vertices: c.shrunk_vertices,
        shrunk: c.shrunk.clone(),
    }
}

/// DejaVu Sans, which the text workload's outline rows draw with.
fn load_dejavu() -> Result<OutlineFont, CliError> {
    OutlineFont::from_file(std::path::Path::new(DEJAVU_SANS)).map_err(|e| {
        CliError::failed(format!("the text workload needs DejaVu Sans (Debian package fonts-dejavu-core): {e}"))
    })
}

/// The workloads named (all when none), or a usage error listing the valid names.
fn select_workloads(names: &[String]) -> Result<Vec<&'static str>, CliError> {
    let all: Vec<&'static str> =
        POLYGON_WORKLOADS.iter().chain(LINE_WORKLOADS).chain(CURVE_WORKLOADS).chain(TEXT_WORKLOADS).copied().collect();
    if names.is_empty() {
        return Ok(all);
    }
    names
        .iter()
        .map(|n| {
            all.iter()
                .copied()
                .find(|w| w == n)
                .ok_or_else(|| CliError::usage(format!("unknown workload '{n}' (workloads: {})", all.join(", "))))
        })
        .collect()
}

/// A progress bar on standard error, hidden when that is not a terminal.
fn progress_bar(len: usize) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(len as u64);
    if let Ok(style) = ProgressStyle::with_template("verify {bar:40} {pos}/{len} cases, {elapsed} elapsed, eta {eta}") {
        bar.set_style(style);
    }
    bar
}
