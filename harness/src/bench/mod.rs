//! `clipbench bench`: every registered polygon clipper against geo and Clipper2 on the seeded
//! workloads, all four operations, timed in interleaved rounds; ratios to Clipper2 come from the
//! same run. Rectangle windows add the rectangle-only clippers; large cases also get peak memory.
//! Writes the raw files only; `report` turns them into tables and plots.

mod memory_probe;
mod plan;
mod rounds;

use std::path::PathBuf;
use std::process::ExitCode;

use clip_core::BoolOp;
use serde_json::json;

use crate::cli_error::CliError;
use crate::measure::out_dir::ready_out_dir;
use crate::measure::provenance::Provenance;
use crate::measure::raw::write_csv;
use crate::registry::Registry;
use crate::results_files::bench::{BASELINE, CSV, META, write_memory};

/// Arguments of `clipbench bench`.
#[derive(Debug, clap::Args)]
pub struct BenchArgs {
    /// Fewer sizes (large cases up to 10^5 vertices), rounds and a shorter cap: a few minutes.
    #[arg(long)]
    pub quick: bool,
    /// Folder for the CSV, markdown, SVG and REPORT.md files.
    #[arg(long, default_value = "results")]
    pub out: PathBuf,
    /// Seed of the generated cases.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Time cap per point in seconds: once one call takes longer, larger sizes of that workload
    /// are skipped for that clipper (default 2, quick 0.5).
    #[arg(long, value_name = "SECONDS")]
    pub cap: Option<f64>,
    /// Timed rounds per point (default 7, quick 3).
    #[arg(long, value_name = "N")]
    pub rounds: Option<usize>,
    /// Clipper to time (repeat for several; default: every registered polygon clipper). The
    /// baseline (Clipper2) is always timed too, so every point keeps its ratio.
    #[arg(long = "clipper", value_name = "NAME")]
    pub clippers: Vec<String>,
    /// Bench group to run, by its name in bench.csv (`star`, `scribble`, `grid`, `holes`,
    /// `large-smooth`, `large-checkerboard`, `spiky-box`, `many-subjects`, `star-rect`, `large-rect`;
    /// repeat; default: all).
    #[arg(long = "workload", value_name = "NAME")]
    pub workloads: Vec<String>,
    /// Operation to time (repeat; default: all four).
    #[arg(long = "op", value_name = "OP")]
    pub ops: Vec<BoolOp>,
    /// External clippers (docs/PROTOCOL.md).
    #[command(flatten)]
    pub external: crate::external::ExternalArgs,
    /// Internal: measure one call's peak memory in this fresh process and print it (the bench
    /// runs itself with this, so no earlier allocation hides the peak).
    #[arg(long, hide = true, value_name = "SPEC")]
    pub memory_probe: Option<String>,
}

/// The hidden `--memory-probe` mode: one call's peak memory, measured in this fresh process.
pub fn run_memory_probe(spec: &str, seed: u64, registry: &Registry) -> Result<ExitCode, CliError> {
    memory_probe::child(spec, seed, registry)
}

/// Measures and writes the raw files (timings, peak memory, sidecar) into the output folder,
/// which it returns.
pub fn run(args: &BenchArgs, registry: Registry) -> Result<PathBuf, CliError> {
    let cap = args.cap.unwrap_or(if args.quick { 0.5 } else { 2.0 });
    if !(cap.is_finite() && cap > 0.0) {
        return Err(CliError::usage("--cap must be a positive number of seconds"));
    }
    let rounds = args.rounds.unwrap_or(if args.quick { 3 } else { 7 });
    if rounds == 0 {
        return Err(CliError::usage("--rounds must be at least 1"));
    }
    if registry.find_polygon(BASELINE).is_none() {
        return Err(CliError::failed(format!("the baseline clipper '{BASELINE}' is not registered")));
    }
    let registry = &select_clippers(registry, &args.clippers)?;
    let groups = plan::select(plan::groups(args.quick), &args.workloads, &args.ops)?;
    let out = ready_out_dir(&args.out)?;
    let settings = rounds::Settings { seed: args.seed, rounds, cap_seconds: cap, quick: args.quick };
    let measured = rounds::run(&groups, registry, &settings)?;

    write_csv(&out.join(CSV), &measured.rows)?;
    write_memory(&out, &measured.memory)?;
    let parameters = json!({
        "quick": args.quick,
        "filtered": !(args.clippers.is_empty() && args.workloads.is_empty() && args.ops.is_empty()),
        "rounds": rounds,
        "cap_seconds": cap,
        "fill_rule": "even-odd",
        "groups": groups.iter().map(plan::Group::describe).collect::<Vec<_>>(),
        "clippers": registry.polygon.iter().map(|e| e.clipper.name()).collect::<Vec<_>>(),
        "baseline": BASELINE,
    });
    let mut provenance = Provenance::now(if args.quick { "bench --quick" } else { "bench" }, args.seed, parameters);
    if registry.polygon.iter().any(|e| e.own_time.is_some()) {
        provenance.notes.push(
            "External clippers (docs/PROTOCOL.md) are timed by round trip through their pipe and JSON under their own \
             name, and by the time they report for themselves as `NAME (own time)`; their peak memory is their \
             process's and is not measured."
                .to_owned(),
        );
    }
    provenance.notes.push(
        "The rectangle-window groups also time Clipper2's dedicated rectangle clipper (RectClip64, through its C \
         API: the clip-clipper2-rect crate) as `clipper2-rect`; ratios in the tables stay against Clipper2's \
         general intersection, and the rectangle clippers' ratios to clipper2-rect are listed above."
            .to_owned(),
    );
    provenance.notes.extend(measured.notes);
    provenance.write(&out.join(META))?;
    Ok(out)
}

/// The registry cut down to the named polygon clippers plus the baseline (all when none named).
fn select_clippers(registry: Registry, names: &[String]) -> Result<Registry, CliError> {
    if names.is_empty() {
        return Ok(registry);
    }
    let mut names = names.to_vec();
    if !names.iter().any(|n| n == BASELINE) {
        names.push(BASELINE.to_owned());
    }
    let mut selected = registry.select(&names)?;
    selected.line.clear();
    if let Some(line) = names.iter().find(|n| selected.find_polygon(n).is_none()) {
        return Err(CliError::usage(format!("--clipper {line}: bench times polygon clippers only")));
    }
    Ok(selected)
}
