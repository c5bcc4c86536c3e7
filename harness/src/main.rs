//! The `clipbench` command: parses the command line and dispatches to the library's command
//! modules (see `lib.rs`).

use std::process::ExitCode;

use clap::builder::{PossibleValue, PossibleValuesParser};
use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

use clipbench::cli_error::CliError;
use clipbench::registry::Registry;
use clipbench::report::document::ReportRun;
use clipbench::report::sections;
use clipbench::{
    bench, checks, clip, compare, conformance, external, hostile, merge, referee, registry, report, reproduce,
    text_cmd, verify,
};

/// Polygon and line clipping: verification against exact oracles and the peer libraries (geo,
/// Clipper2), and one-off clipping of WKT/GeoJSON files.
#[derive(Debug, Parser)]
#[command(name = "clipbench", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run every registered clipper on the seeded workloads against the exact oracles and each
    /// other; print a summary table and write shrunk failure cases.
    Verify(verify::VerifyArgs),
    /// Join the results folders of a verify run's parts (`verify --partition K/N --results DIR`)
    /// into the one folder the whole run would have written, which `report` reads.
    Merge(merge::MergeArgs),
    /// Run the registered clippers on an external suite with expected answers (Clipper2's
    /// Polygons.txt and Lines.txt, geo's boolean-op fixtures).
    Conformance(conformance::ConformanceArgs),
    /// One boolean operation (or line clipping) on files with a registered clipper.
    Clip(clip::ClipArgs),
    /// The papers' performance tables (Vatti 1992 Table 3, Wang et al. 2005 Table 4) measured
    /// here beside the papers' own numbers: raw CSV, markdown, SVG plots and REPORT.md.
    Reproduce(reproduce::ReproduceArgs),
    /// Every polygon clipper against geo and Clipper2 on the workloads, as ratios measured in one
    /// run, with log-log scaling plots and peak memory of the large cases.
    Bench(bench::BenchArgs),
    /// Every polygon clipper on the fixed hostile and degenerate set: how often each is right,
    /// wrong, refuses, crashes or hangs.
    Hostile(hostile::HostileArgs),
    /// An exact external clipper (adapters/cgal) as a referee of the oracle: its result areas on
    /// the polygon workloads against the oracle's region areas, beyond what rounding accounts for.
    Referee(referee::RefereeArgs),
    /// Compare two bench results folders: per point, each clipper's ratio to Clipper2 before and
    /// after with intervals; regressions and improvements beyond the noise flagged; exit status 1
    /// on a regression beyond --max-regression (for CI gates).
    Compare(compare::CompareArgs),
    /// Recompute the tables and plots from the raw CSVs of a results folder into REPORT.md.
    Report(report::ReportArgs),
    /// One string clipped to a window by one of the lecture's text strategies, drawn as SVG.
    Text(text_cmd::TextArgs),
}

fn main() -> ExitCode {
    let cli = parse();
    checks::quiet_clipper_panics();
    let registry = registry::registry();
    let result = match &cli.command {
        Command::Verify(args) => {
            external::add_external(registry, &args.external).and_then(|registry| verify::run(args, registry))
        }
        Command::Conformance(args) => {
            external::add_external(registry, &args.external).and_then(|registry| conformance::run(args, registry))
        }
        Command::Clip(args) => external::add_external(registry, &args.external)
            .and_then(|registry| clip::run(args, &registry))
            .map(|()| ExitCode::SUCCESS),
        Command::Hostile(args) => {
            external::add_external(registry, &args.external).and_then(|registry| hostile::run(args, registry))
        }
        Command::Referee(args) => {
            external::add_external(registry, &args.external).and_then(|registry| referee::run(args, &registry))
        }
        Command::Reproduce(args) => reproduce_then_report(args),
        Command::Bench(args) => bench_then_report(args, registry),
        Command::Compare(args) => compare::run(args),
        Command::Report(args) => report::run(args),
        Command::Merge(args) => merge::run(args),
        Command::Text(args) => text_cmd::run(args).map(|()| ExitCode::SUCCESS),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("clipbench: {e}");
            ExitCode::from(e.code)
        }
    }
}

/// The command line, with `reproduce`'s tables (names and what each measures) taken from the
/// report's one list of sections.
fn parse() -> Cli {
    let tables = sections::tables().into_iter().map(|t| PossibleValue::new(t.name).help(t.about));
    let all = PossibleValue::new(sections::ALL_TABLES).help("every table above, in this order");
    let values = PossibleValuesParser::new(tables.chain([all]));
    let command = Cli::command().mut_subcommand("reproduce", |c| c.mut_arg("table", |a| a.value_parser(values)));
    Cli::from_arg_matches(&command.get_matches()).unwrap_or_else(|e| e.exit())
}

/// `clipbench reproduce`: each asked table measured, then the sections it feeds (their markdown
/// and plots), then REPORT.md with the rest. A table's markdown is written before the next table
/// is measured, so a failure later keeps it; no section is derived twice.
fn reproduce_then_report(args: &reproduce::ReproduceArgs) -> Result<ExitCode, CliError> {
    let tables = sections::tables_named(&args.table)?;
    let out = reproduce::ready(args)?;
    let mut report = ReportRun::new(&out);
    for table in tables {
        (table.measure)(args, &out)?;
        report.derive_table(table)?;
    }
    report::finish(report)?;
    Ok(ExitCode::SUCCESS)
}

/// `clipbench bench`: the raw files measured, then every section (the bench's tables and plots
/// among them) and REPORT.md. The hidden memory-probe mode only measures and prints, and writes
/// no files.
fn bench_then_report(args: &bench::BenchArgs, registry: Registry) -> Result<ExitCode, CliError> {
    if let Some(spec) = &args.memory_probe {
        return bench::run_memory_probe(spec, args.seed, &registry);
    }
    let registry = external::add_external(registry, &args.external)?;
    let out = bench::run(args, registry)?;
    report::write_report(&out)?;
    Ok(ExitCode::SUCCESS)
}
