//! `clipbench referee`: an exact clipper outside this project (CGAL's Boolean_set_operations_2 on
//! an exact kernel, `adapters/cgal/`) as an independent check of clip-oracle. On every polygon
//! workload's cases, each operation and fill rule the referee takes, the area of its result is
//! set against clip-oracle's region area of the same operation on the same operands. The
//! referee's output is exact until it is rounded to f64 on the way out, and the oracle's area
//! is exact in topology with f64 arithmetic, so the two may differ by what rounding moves and no
//! more: an edge moves by at most [`rounding_distance`] (a few ulps of the largest coordinate), so
//! the area by at most that times the perimeters of the inputs and of the result, plus the
//! f64 error of summing the areas. A difference beyond that is a bug in one of the two.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;

use clip_core::{BoolOp, FillRule, Polygons, WindowKind};
use clip_oracle::polygon::{region_area, rounding_distance};
use clip_testkit::workload::{POLYGON_WORKLOADS, polygon_case};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde::Serialize;

use crate::checks::run_polygon;
use crate::cli_error::CliError;
use crate::console;
use crate::partition::Partition;
use crate::registry::{PolygonEntry, Registry};
use crate::results_files::atlas::RefereeTally;
use crate::write::write_file;

/// Arguments of `clipbench referee`.
#[derive(Debug, clap::Args)]
pub struct RefereeArgs {
    /// The exact clipper whose result areas are set against the oracle's (an external clipper's
    /// name from --external or --clippers, e.g. `cgal`).
    #[arg(long, value_name = "NAME")]
    pub referee: String,
    /// Polygon workload to run (repeat for several; default: every polygon workload).
    #[arg(long = "workload", value_name = "NAME")]
    pub workloads: Vec<String>,
    /// Generated cases per workload; each case runs every operation and fill rule the referee takes.
    #[arg(long, default_value_t = 100)]
    pub cases: usize,
    /// Seed of the case generators (the same as `verify`'s for the same cases).
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Worker threads, 1 to 1024 (default: one per core). The result does not depend on it.
    #[arg(long, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=crate::verify::MAX_THREADS as u64))]
    pub threads: Option<usize>,
    /// Run only part K of N of the cases (case j of the run's list, workload by workload and
    /// index by index from 0, is in part j mod N + 1), so that a long run can be split over
    /// jobs or sessions; the report joins the parts' JSON files (all N in one folder) into the
    /// tally of the whole run.
    #[arg(long, value_name = "K/N")]
    pub partition: Option<Partition>,
    /// Also write the summary and every case beyond rounding as JSON to this file.
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
    /// External clippers (docs/PROTOCOL.md).
    #[command(flatten)]
    pub external: crate::external::ExternalArgs,
}

/// One result set against the oracle.
#[derive(Clone, Debug, Serialize)]
pub struct Comparison {
    /// Workload.
    pub workload: &'static str,
    /// Case index (with the run's seed, `polygon_case` gives the operands again).
    pub index: usize,
    /// Operation.
    pub op: &'static str,
    /// Fill rule.
    pub fill: &'static str,
    /// The oracle's area of `subject op clip`.
    pub oracle_area: f64,
    /// The shoelace area of the referee's result.
    pub referee_area: f64,
    /// What rounding to f64 can account for.
    pub rounding_bound: f64,
}

impl Comparison {
    fn difference(&self) -> f64 {
        (self.referee_area - self.oracle_area).abs()
    }

    /// The difference relative to the larger of the two areas (0 when both are 0).
    pub fn relative(&self) -> f64 {
        let scale = self.oracle_area.abs().max(self.referee_area.abs());
        if scale == 0.0 { 0.0 } else { self.difference() / scale }
    }

    /// The difference as a multiple of what rounding accounts for.
    pub fn of_bound(&self) -> f64 {
        if self.rounding_bound == 0.0 {
            if self.difference() == 0.0 { 0.0 } else { f64::INFINITY }
        } else {
            self.difference() / self.rounding_bound
        }
    }
}

/// What `--json` writes.
#[derive(Debug, Serialize)]
struct RefereeFile<'a> {
    referee: &'a str,
    seed: u64,
    cases_per_workload: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    partition: Option<Partition>,
    workloads: &'a [RefereeTally],
    beyond_rounding: Vec<&'a Comparison>,
    failures: &'a [(String, String)],
}

/// The bound on the area difference that rounding accounts for: every edge of the inputs and of
/// the result may sit [`rounding_distance`] off its exact place, and each of the two areas is a
/// sum of f64 terms (a relative error of one epsilon per term at most, over the box's area).
pub fn rounding_bound(subject: &Polygons, clip: &Polygons, output: &Polygons) -> f64 {
    let b = subject.bounds().union(clip.bounds()).union(output.bounds());
    if b.is_empty() {
        return 0.0;
    }
    let perimeter: f64 = subject.edges().chain(clip.edges()).chain(output.edges()).map(|e| e.a.distance(e.b)).sum();
    let terms = (subject.edges().count() + clip.edges().count() + output.edges().count()) as f64;
    rounding_distance(&b) * perimeter + terms * f64::EPSILON * b.area()
}

/// Runs the command: exit 1 when a result differs from the oracle beyond rounding.
pub fn run(args: &RefereeArgs, registry: &Registry) -> Result<ExitCode, CliError> {
    let Some(referee) = registry.find_polygon(&args.referee) else {
        return Err(CliError::usage(format!(
            "no polygon clipper named '{}' (give it with --external or --clippers; registered: {})",
            args.referee,
            registry.names().join(", ")
        )));
    };
    let workloads: Vec<&'static str> = if args.workloads.is_empty() {
        POLYGON_WORKLOADS.to_vec()
    } else {
        args.workloads
            .iter()
            .map(|n| {
                POLYGON_WORKLOADS.iter().copied().find(|w| w == n).ok_or_else(|| {
                    CliError::usage(format!("unknown polygon workload '{n}' (known: {})", POLYGON_WORKLOADS.join(", ")))
                })
            })
            .collect::<Result<_, _>>()?
    };
    let items: Vec<(&'static str, usize)> = workloads
        .iter()
        .flat_map(|&w| (0..args.cases).map(move |i| (w, i)))
        .enumerate()
        .filter(|&(j, _)| args.partition.is_none_or(|p| p.keeps(j)))
        .map(|(_, item)| item)
        .collect();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.unwrap_or(0))
        .build()
        .map_err(|e| CliError::failed(format!("cannot start worker threads: {e}")))?;
    let progress = progress_bar(items.len());
    let outcomes: Vec<Result<CaseResult, String>> = pool.install(|| {
        items
            .par_iter()
            .map(|&(w, i)| {
                let r = referee_case(referee, w, args.seed, i);
                progress.inc(1);
                r
            })
            .collect()
    });
    progress.finish_and_clear();

    let mut tallies: Vec<RefereeTally> = workloads
        .iter()
        .map(|&workload| RefereeTally { workload: workload.to_owned(), ..RefereeTally::default() })
        .collect();
    let mut beyond: Vec<Comparison> = Vec::new();
    let mut failures: Vec<(String, String)> = Vec::new();
    for ((w, i), outcome) in items.iter().zip(outcomes) {
        let outcome = outcome.map_err(CliError::failed)?;
        let Some(t) = tallies.iter_mut().find(|t| t.workload == *w) else { continue };
        t.cases += 1;
        t.failed += outcome.failures.len();
        for (what, message) in outcome.failures {
            failures.push((format!("{w} {i} {what}"), message));
        }
        for c in outcome.comparisons {
            t.compared += 1;
            t.largest_relative = t.largest_relative.max(c.relative());
            t.largest_of_bound = t.largest_of_bound.max(c.of_bound());
            if c.of_bound() > 1.0 {
                t.beyond_rounding += 1;
                beyond.push(c);
            }
        }
    }
    console::print(&table(&args.referee, &tallies))?;
    for c in &beyond {
        console::print_line(format_args!(
            "beyond rounding: {} case {} {} {}: oracle {:e}, {} {:e} (difference {:.3} x the rounding bound {:e})",
            c.workload,
            c.index,
            c.op,
            c.fill,
            c.oracle_area,
            args.referee,
            c.referee_area,
            c.of_bound(),
            c.rounding_bound
        ))?;
    }
    for (what, message) in failures.iter().take(20) {
        console::print_line(format_args!("no result: {what}: {message}"))?;
    }
    if let Some(path) = &args.json {
        let file = RefereeFile {
            referee: &args.referee,
            seed: args.seed,
            cases_per_workload: args.cases,
            partition: args.partition,
            workloads: &tallies,
            beyond_rounding: beyond.iter().collect(),
            failures: &failures,
        };
        let text = serde_json::to_string_pretty(&file).map_err(|e| CliError::failed(e.to_string()))? + "\n";
        write_file(path, &text)?;
    }
    Ok(if beyond.is_empty() { ExitCode::SUCCESS } else { ExitCode::FAILURE })
}

/// What one case gave: the comparisons, and the calls that gave no result (what, message).
struct CaseResult {
    comparisons: Vec<Comparison>,
    failures: Vec<(String, String)>,
}

fn referee_case(referee: &PolygonEntry, workload: &'static str, seed: u64, index: usize) -> Result<CaseResult, String> {
    let case = polygon_case(workload, seed, index, WindowKind::Any).map_err(|e| e.to_string())?;
    let (subject, clip) = (&case.subject, &case.clip);
    let caps = referee.clipper.capabilities();
    let mut result = CaseResult { comparisons: Vec::new(), failures: Vec::new() };
    for &fill in FillRule::ALL.iter().filter(|f| caps.fill_rules.contains(f)) {
        for &op in BoolOp::ALL.iter().filter(|o| caps.ops.contains(o)) {
            match run_polygon(referee, subject, clip, op, fill) {
                Ok(output) => {
                    let oracle_area = region_area(&[(subject, fill), (clip, fill)], |i| op.apply(i[0], i[1]));
                    result.comparisons.push(Comparison {
                        workload,
                        index,
                        op: op.name(),
                        fill: fill.name(),
                        oracle_area,
                        referee_area: output.signed_area(),
                        rounding_bound: rounding_bound(subject, clip, &output),
                    });
                }
                Err(failure) => result.failures.push((format!("{} {}", op.name(), fill.name()), failure.message)),
            }
        }
    }
    Ok(result)
}

/// The summary table, one row per workload.
fn table(referee: &str, tallies: &[RefereeTally]) -> String {
    let mut s = format!(
        "{referee} against clip-oracle's region areas\n{:<14} {:>6} {:>8} {:>7} {:>18} {:>16} {:>16}\n",
        "workload", "cases", "compared", "failed", "largest rel. diff", "largest / bound", "beyond rounding"
    );
    for t in tallies {
        s += &format!(
            "{:<14} {:>6} {:>8} {:>7} {:>18.3e} {:>16.3e} {:>16}\n",
            t.workload, t.cases, t.compared, t.failed, t.largest_relative, t.largest_of_bound, t.beyond_rounding
        );
    }
    s
}

/// A progress bar on standard error, hidden when that is not a terminal.
fn progress_bar(len: usize) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(len as u64);
    if let Ok(style) = ProgressStyle::with_template("referee {bar:40} {pos}/{len} cases, {elapsed} elapsed, eta {eta}")
    {
        bar.set_style(style);
    }
    bar
}

#[cfg(test)]
mod tests {
    use super::*;
    use clip_core::Rect;

    #[test]
    fn the_bound_grows_with_the_coordinates_magnitude_and_the_perimeters() {
        let near = Polygons::from(Rect::new(0.0, 0.0, 1.0, 1.0));
        let far = Polygons::from(Rect::new(1e9, 1e9, 1e9 + 1.0, 1e9 + 1.0));
        let empty = Polygons::default();
        assert!(rounding_bound(&far, &far, &far) > 1e6 * rounding_bound(&near, &near, &near));
        assert!(rounding_bound(&near, &near, &near) > rounding_bound(&near, &near, &empty));
        assert_eq!(rounding_bound(&empty, &empty, &empty), 0.0);
    }

    #[test]
    fn a_difference_is_measured_against_the_larger_area_and_the_bound() {
        let c = |oracle_area: f64, referee_area: f64, rounding_bound: f64| Comparison {
            workload: "star",
            index: 0,
            op: "union",
            fill: "even-odd",
            oracle_area,
            referee_area,
            rounding_bound,
        };
        assert_eq!(c(0.0, 0.0, 0.0).relative(), 0.0);
        assert_eq!(c(0.0, 0.0, 0.0).of_bound(), 0.0);
        assert_eq!(c(4.0, 3.0, 0.5).relative(), 0.25);
        assert_eq!(c(4.0, 3.0, 0.5).of_bound(), 2.0);
        assert!(c(1.0, 1.0 + 1e-9, 0.0).of_bound().is_infinite());
    }
}
