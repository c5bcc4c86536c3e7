//! `clipbench conformance SUITE`: the registered clippers on external suites with expected
//! answers (Clipper2's `Polygons.txt` and `Lines.txt`, geo's boolean-op fixtures), one line per
//! failing case and a `N passed, M failed` line per clipper.

pub mod clipper2_suites;
pub mod geo_booleanop;
pub mod suite_case;

use std::path::PathBuf;
use std::process::ExitCode;

use clip_core::{BoolOp, FillRule, PolygonClipper, Polygons, VisiblePiece};
use clip_oracle::polygon::{same_region, tolerance};
use clip_peers::{Clipper2Clipper, normalised_counts_agree};
use clip_testkit::case_record::{lines_svg, polygons_svg};
use clip_testkit::clipper2_suite::{Passed, Record, judge};
use clip_vatti::Vatti;

use self::suite_case::{CaseInput, PolygonExpectation, SuiteCase};
use crate::checks::{line_oracle, output_rules, run_line, run_polygon};
use crate::cli_error::CliError;
use crate::console;
use crate::registry::{LineEntry, Origin, PolygonEntry, Registry};
use crate::results_files::atlas::{ConformanceResults, ConformanceTally};
use crate::write::write_file;

/// The external suites.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Suite {
    /// Clipper2's Polygons.txt: 195 cases judged by stored area and count, with the tolerances
    /// of Clipper2's own test.
    Clipper2Polygons,
    /// Clipper2's Lines.txt: open paths clipped by polygons, judged by the exact line oracle.
    Clipper2Lines,
    /// geo's Martinez-Rueda GeoJSON fixtures and tcases.json, judged by region.
    GeoBooleanop,
}

/// Arguments of `clipbench conformance`.
#[derive(Debug, clap::Args)]
pub struct ConformanceArgs {
    /// The suite to run.
    #[arg(value_enum)]
    pub suite: Suite,
    /// Clipper to run (repeat for several; default: every registered clipper that applies).
    #[arg(long = "clipper", value_name = "NAME")]
    pub clippers: Vec<String>,
    /// Run only this case: a record number (clipper2-*), or `file/operation` or `file` (geo-booleanop).
    #[arg(long, value_name = "NAME")]
    pub case: Option<String>,
    /// With --case: write an SVG picture of the case's inputs and each clipper's result here.
    #[arg(long, value_name = "FILE", requires = "case")]
    pub svg: Option<PathBuf>,
    /// The folder holding clipper2/ and geo/ (default: the repository's testdata/, or the folder
    /// CLIPBENCH_TESTDATA names).
    #[arg(long, value_name = "DIR", default_value_os_t = clip_testkit::testdata_dir())]
    pub testdata: PathBuf,
    /// Run only part K of N of the suite's cases (as 3/8), as `verify --partition`: case j of
    /// the suite (in its order, after --case, from 0) is in part j mod N + 1, so N jobs run the
    /// whole suite between them; their per-clipper counts add up to a whole run's.
    #[arg(long, value_name = "K/N")]
    pub partition: Option<crate::partition::Partition>,
    /// Also write each clipper's passed, failed and skipped counts here as JSON (the report's
    /// atlas reads it).
    #[arg(long, value_name = "FILE")]
    pub json: Option<PathBuf>,
    /// External clippers (docs/PROTOCOL.md).
    #[command(flatten)]
    pub external: crate::external::ExternalArgs,
}

/// One clipper's verdict on one case.
enum Verdict {
    /// Passed; for Clipper2's records, by which readings (stored values when both are false).
    Pass(Passed),
    /// Expected, got.
    Fail(String, String),
    Skip,
}

/// Runs the command: exit 1 when a clipper of this project fails a case.
pub fn run(args: &ConformanceArgs, registry: Registry) -> Result<ExitCode, CliError> {
    let mut registry = registry.select(&args.clippers)?;
    if args.suite == Suite::Clipper2Polygons {
        // Clipper2's test data is Clipper64 data: integers meant to be used unscaled. Its path
        // counts depend on the scale (Clipper2 drops rings of tiny area in its integer space),
        // so the clipper2 peer runs it on the native grid, as Clipper2's own test does.
        for entry in registry.polygon.iter_mut().filter(|e| e.clipper.name() == "clipper2") {
            entry.clipper = Box::new(Clipper2Clipper::native());
        }
    }
    let suite_name = match args.suite {
        Suite::Clipper2Polygons => "clipper2-polygons",
        Suite::Clipper2Lines => "clipper2-lines",
        Suite::GeoBooleanop => "geo-booleanop",
    };
    let mut cases = match args.suite {
        Suite::Clipper2Polygons => clipper2_suites::polygon_cases(&args.testdata)?,
        Suite::Clipper2Lines => clipper2_suites::line_cases(&args.testdata)?,
        Suite::GeoBooleanop => geo_booleanop::cases(&args.testdata)?,
    };
    if let Some(name) = &args.case {
        cases.retain(|c| &c.name == name || c.name.split('/').next() == Some(name.as_str()));
        if cases.is_empty() {
            return Err(CliError::usage(format!("{suite_name} has no case '{name}'")));
        }
    }
    if let Some(part) = args.partition {
        cases = cases.into_iter().enumerate().filter(|(j, _)| part.keeps(*j)).map(|(_, c)| c).collect();
    }
    let lines = args.suite == Suite::Clipper2Lines;
    let clippers: Vec<(&'static str, Origin)> = if lines {
        registry.line.iter().map(|e| (e.clipper.name(), e.origin)).collect()
    } else {
        registry.polygon.iter().map(|e| (e.clipper.name(), e.origin)).collect()
    };
    if clippers.is_empty() {
        return Err(CliError::usage(format!("no selected clipper can run {suite_name}")));
    }
    // (passed, failed, skipped) per clipper, and passes by the exact area / normalised count.
    let mut tally = vec![(0usize, 0usize, 0usize); clippers.len()];
    let mut readings = vec![(0usize, 0usize); clippers.len()];
    for case in &cases {
        for (k, t) in tally.iter_mut().enumerate() {
            let verdict =
                if lines { judge_line(&registry.line[k], case) } else { judge_polygon(&registry.polygon[k], case) };
            match verdict {
                Verdict::Pass(by) => {
                    t.0 += 1;
                    readings[k].0 += usize::from(by.by_exact_area);
                    readings[k].1 += usize::from(by.by_normalised_count);
                }
                Verdict::Skip => t.2 += 1,
                Verdict::Fail(expected, got) => {
                    t.1 += 1;
                    console::print_line(format_args!(
                        "{suite_name} {} {}: expected {expected}, got {got}",
                        case.name, clippers[k].0
                    ))?;
                }
            }
        }
    }
    let tallies: Vec<ConformanceTally> = clippers
        .iter()
        .zip(&tally)
        .enumerate()
        .map(|(k, ((name, _), &(passed, failed, skipped)))| ConformanceTally {
            clipper: (*name).to_owned(),
            passed,
            failed,
            skipped,
            handshake: if lines { None } else { registry.polygon[k].handshake.clone() },
        })
        .collect();
    for t in &tallies {
        console::print_line(format_args!("{}", t.line()))?;
    }
    for ((name, _), (exact, normalised)) in clippers.iter().zip(&readings).filter(|(_, r)| r.0 + r.1 > 0) {
        console::print_line(format_args!(
            "  ({name}: of its passes, {exact} by the exact area where the stored one is off, {normalised} by \
             Clipper2's live ring count in our ring convention)"
        ))?;
    }
    if let Some(path) = &args.json {
        let results = ConformanceResults { suite: suite_name.to_owned(), clippers: tallies };
        let text = serde_json::to_string_pretty(&results).map_err(|e| CliError::failed(e.to_string()))? + "\n";
        write_file(path, &text)?;
    }
    if let (Some(path), Some(case)) = (&args.svg, cases.first()) {
        write_file(path, &picture(&registry, case))?;
    }
    let ours_failed = clippers.iter().zip(&tally).any(|((_, origin), t)| origin.fails_run() && t.1 > 0);
    Ok(if ours_failed { ExitCode::FAILURE } else { ExitCode::SUCCESS })
}

fn judge_polygon(entry: &PolygonEntry, case: &SuiteCase) -> Verdict {
    let (subject, clip, op, fill, expected) = match &case.input {
        CaseInput::Polygon { subject, clip, op, fill, expected } => (subject, clip, *op, *fill, expected),
        CaseInput::Malformed(problem) => return Verdict::Fail("a readable case".into(), problem.clone()),
        CaseInput::Line { .. } | CaseInput::NotApplicable(_) => return Verdict::Skip,
    };
    let caps = entry.clipper.capabilities();
    if !caps.supports(op, fill) || !caps.window.accepts(clip) {
        return Verdict::Skip;
    }
    let output = match run_polygon(entry, subject, clip, op, fill) {
        Ok(output) => output,
        Err(failure) => return Verdict::Fail("a result".into(), failure.message),
    };
    let judged = match expected {
        PolygonExpectation::Clipper2 { number, area, count } => {
            let record = Record { number: *number, subject, clip, op, fill, area: *area, count: *count };
            judge(&record, &output, &output_rules(entry, subject, fill), &live_recount)
        }
        PolygonExpectation::Region(want) => {
            let allowed = tolerance(subject, clip, entry.tolerance);
            same_region((&output, output_rules(entry, subject, fill).output_fill), (want, fill), allowed)
                .map(|()| Passed::default())
                .map_err(|area| {
                    ("the expected region".into(), format!("symmetric difference {area:e} > tolerance {allowed:e}"))
                })
        }
    };
    match judged {
        Ok(by) => Verdict::Pass(by),
        Err((expected, got)) => Verdict::Fail(expected, got),
    }
}

/// One ring convention for counting rings of any library's output: ours (docs/DESIGN.md's simple
/// rings, split at pinch points), by a union with nothing under non-zero.
fn normalise_rings(rings: &Polygons) -> Result<Polygons, String> {
    Vatti.clip(rings, &Polygons::empty(), BoolOp::Union, FillRule::NonZero).map_err(|e| e.to_string())
}

/// A count off the stored one passes when Clipper2, run live, shows the same count once both are
/// normalised to our ring convention.
fn live_recount(record: &Record<'_>, output: &Polygons) -> Result<(), String> {
    normalised_counts_agree(record, output, &normalise_rings)
}

fn judge_line(entry: &LineEntry, case: &SuiteCase) -> Verdict {
    let (window, segments) = match &case.input {
        CaseInput::Line { window, segments } => (window, segments),
        CaseInput::Malformed(problem) => return Verdict::Fail("a readable case".into(), problem.clone()),
        CaseInput::Polygon { .. } | CaseInput::NotApplicable(_) => return Verdict::Skip,
    };
    if !entry.clipper.capabilities().window.accepts(window) {
        return Verdict::Skip;
    }
    match run_line(entry, window, segments).and_then(|pieces| line_oracle(entry, window, segments, &pieces)) {
        Ok(()) => Verdict::Pass(Passed::default()),
        Err(failure) => Verdict::Fail("the exact visible intervals".into(), failure.message),
    }
}

/// The case's inputs and every selected clipper's result (and the expected region, if any).
fn picture(registry: &Registry, case: &SuiteCase) -> String {
    match &case.input {
        CaseInput::Polygon { subject, clip, op, fill, expected } => {
            let mut outputs: Vec<(String, Polygons)> = registry
                .polygon
                .iter()
                .filter_map(|e| {
                    run_polygon(e, subject, clip, *op, *fill).ok().map(|o| (e.clipper.name().to_owned(), o))
                })
                .collect();
            if let PolygonExpectation::Region(want) = expected {
                outputs.push(("expected".into(), want.clone()));
            }
            let named: Vec<(&str, &Polygons)> = outputs.iter().map(|(n, p)| (n.as_str(), p)).collect();
            polygons_svg(subject, clip, &named)
        }
        CaseInput::Line { window, segments } => {
            let outputs: Vec<(&str, Vec<VisiblePiece>)> = registry
                .line
                .iter()
                .filter_map(|e| run_line(e, window, segments).ok().map(|p| (e.clipper.name(), p)))
                .collect();
            let named: Vec<(&str, &[VisiblePiece])> = outputs.iter().map(|(n, p)| (*n, p.as_slice())).collect();
            lines_svg(window, segments, &named)
        }
        CaseInput::NotApplicable(_) | CaseInput::Malformed(_) => {
            polygons_svg(&Polygons::empty(), &Polygons::empty(), &[])
        }
    }
}
