//! `clipbench bench`: every registered polygon clipper against geo and Clipper2 on the seeded
//! workloads, all four operations, timed in interleaved rounds; ratios to Clipper2 come from the
//! same run. Rectangle windows add the rectangle-only clippers; large cases also get peak memory.
//! The `text` group times clip-text's strategies on a paragraph as the window shrinks.
//! Writes the raw files only; `report` turns them into tables and plots.

mod checkpoint;
mod correctness;
mod memory_probe;
mod plan;
mod rounds;
mod slowed;
mod text_rounds;

use std::path::PathBuf;
use std::process::ExitCode;

use clip_core::BoolOp;
use serde_json::json;

use crate::cli_error::CliError;
use crate::measure::git_revision::checkout_revision;
use crate::measure::out_dir::ready_out_dir;
use crate::measure::provenance::Provenance;
use crate::measure::raw::write_csv;
use crate::registry::Registry;
use crate::results_files::bench::{BASELINE, CSV, META, TEXT_GROUP, write_memory};
use checkpoint::Checkpoint;

/// Why `bench` has no `--partition`, for `clipbench bench --help`.
const NOT_PARTITIONED: &str = "\
bench has no --partition (verify and conformance have one): its results are ratios of times measured in \
one run on one machine, interleaved round by round, and times taken on different machines, or at different \
moments of a shared one, cannot be compared. Split a bench by --workload and --clipper on one machine \
instead; Clipper2, the baseline, is timed in every part. A run stopped part way is taken up by the same \
command with --resume: each group is measured in one stretch and kept as it finishes.";

/// Arguments of `clipbench bench`.
#[derive(Debug, clap::Args)]
#[command(after_help = NOT_PARTITIONED)]
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
    /// Take up a run that stopped part way: the groups it finished (kept in OUT/bench-groups-done/
    /// as each finishes) are not measured again if this run has the same revision and options;
    /// the rest are. Without it, a run starts afresh.
    #[arg(long)]
    pub resume: bool,
    /// Clipper to time (repeat for several; default: every registered polygon clipper). The
    /// baseline (Clipper2) is always timed too, so every point keeps its ratio. The text group's
    /// rows are `text-string`, `text-char`, `text-outline` (Vatti), `text-outline-sh-split` and
    /// `text-bitmap`.
    #[arg(long = "clipper", value_name = "NAME")]
    pub clippers: Vec<String>,
    /// Bench group to run, by its name in bench.csv (`star`, `scribble`, `grid`, `holes`,
    /// `large-smooth`, `large-checkerboard`, `spiky-box`, `many-subjects`, `star-rect`, `large-rect`;
    /// the sweep stresses `comb`, `comb-box`, `nested`, `concentric`, `spiral`, `windows`,
    /// `corrosion`, `lines-net`, `checkerboard`, `not-overlap`, `wind-mill`, `maps-dissolve`,
    /// `maps-tiles`, `maps-neighbours`; and `text`: the text strategies on a paragraph as the
    /// window shrinks; repeat; default: all).
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
    let plan = Plan::new(args)?;
    let mut slowed_note = None;
    let settings = rounds::Settings { seed: args.seed, rounds, cap_seconds: cap, quick: args.quick };
    let (registry, groups) = if plan.polygon {
        if registry.find_polygon(BASELINE).is_none() {
            return Err(CliError::failed(format!("the baseline clipper '{BASELINE}' is not registered")));
        }
        let registry = select_clippers(registry, &plan.polygon_clippers)?;
        let mut registry = registry;
        slowed_note = slowed::apply(&mut registry)?;
        let groups = plan::select(plan::groups(args.quick), &plan.polygon_groups, &args.ops)?;
        (registry, groups)
    } else {
        // Text only: no polygon clipper is timed.
        let mut registry = registry;
        registry.polygon.clear();
        (registry, Vec::new())
    };
    let out = ready_out_dir(&args.out)?;
    let run_key = format!(
        "revision {}, seed {}, rounds {rounds}, cap {cap} s, quick {}, clippers {}",
        checkout_revision().unwrap_or_else(|| "unknown".to_owned()),
        args.seed,
        args.quick,
        registry.polygon.iter().map(|e| e.clipper.name()).collect::<Vec<_>>().join(" ")
    );
    // Code that differs from its commit is not named by its revision: its groups are not taken up.
    let resume = args.resume && !run_key.contains("+dirty");
    let checkpoint = Checkpoint::new(&out, run_key, resume)?;
    let mut measured = if groups.is_empty() {
        rounds::Measured { rows: Vec::new(), memory: Vec::new(), notes: Vec::new() }
    } else {
        rounds::run(&groups, &registry, &settings, &checkpoint)?
    };
    let text = if plan.text_rows.is_empty() { None } else { Some(text_rounds::run(&plan.text_rows, &settings)?) };
    if let Some(t) = &text {
        measured.rows.extend(t.rows.iter().cloned());
    }

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
        TEXT_GROUP: text.as_ref().map(|t| t.parameters.clone()),
    });
    let mut provenance = Provenance::now(if args.quick { "bench --quick" } else { "bench" }, args.seed, parameters);
    if registry.polygon.iter().any(|e| e.own_time.is_some()) {
        provenance.notes.push(
            "External clippers (docs/PROTOCOL.md) are timed by round trip through their pipe and JSON under their own \
             name, and by the time they report for themselves as `NAME (own time)`; their peak memory is their own \
             process's, one call in a process started for it, and includes reading the request, writing the answer \
             and what their runtime (a JavaScript or Java heap) takes on its own."
                .to_owned(),
        );
    }
    if groups.iter().any(|g| g.window == clip_core::WindowKind::Rectangle) {
        provenance.notes.push(
            "The rectangle-window groups also time Clipper2's dedicated rectangle clipper (RectClip64, through its C \
             API: the clip-clipper2-rect crate) as `clipper2-rect`; ratios in the tables stay against Clipper2's \
             general intersection, and the rectangle clippers' ratios to clipper2-rect are listed above."
                .to_owned(),
        );
    }
    if text.is_some() {
        provenance.notes.push(
            "The text group times clip-text's strategies on a fixed paragraph (six 24 px lines of the notes' text) \
             under centred windows; its rows' time is per paragraph and its size the paragraph's characters, so \
             ns per character is time / size; each output is checked by clip-text's raster oracle before it is timed."
                .to_owned(),
        );
    }
    provenance.notes.extend(slowed_note);
    provenance.notes.extend(measured.notes);
    provenance.write(&out.join(META))?;
    checkpoint.remove()?;
    Ok(out)
}

/// Which parts of the bench run: the polygon groups with their clippers, and the text rows.
struct Plan {
    polygon: bool,
    polygon_groups: Vec<String>,
    polygon_clippers: Vec<String>,
    text_rows: Vec<&'static str>,
}

impl Plan {
    /// From the filters: `--workload text` and `text-*` clipper names pick the text group, the
    /// rest the polygon groups. With no filter both run; a filter naming only one part runs only
    /// that part. The text group times intersection only, so an `--op` list without it drops it.
    fn new(args: &BenchArgs) -> Result<Plan, CliError> {
        let is_text = |n: &String| n.starts_with("text-");
        let (text_clippers, polygon_clippers): (Vec<String>, Vec<String>) =
            args.clippers.iter().cloned().partition(is_text);
        let (text_groups, polygon_groups): (Vec<String>, Vec<String>) =
            args.workloads.iter().cloned().partition(|w| w == TEXT_GROUP);
        let text_wanted = (args.workloads.is_empty() || !text_groups.is_empty())
            && (args.clippers.is_empty() || !text_clippers.is_empty() || !text_groups.is_empty())
            && (args.ops.is_empty() || args.ops.contains(&BoolOp::Intersection));
        let text_rows = if text_wanted { text_rounds::select_rows(&text_clippers)? } else { Vec::new() };
        if !text_clippers.is_empty() && text_rows.is_empty() {
            return Err(CliError::usage("the text rows time intersection only, but --op leaves it out"));
        }
        let polygon = (args.workloads.is_empty() || !polygon_groups.is_empty())
            && (args.clippers.is_empty() || !polygon_clippers.is_empty());
        if !polygon && text_rows.is_empty() {
            return Err(CliError::usage("nothing to bench: the filters select no group"));
        }
        Ok(Plan { polygon, polygon_groups, polygon_clippers, text_rows })
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(flatten)]
        bench: BenchArgs,
    }

    fn plan(args: &[&str]) -> Result<Plan, CliError> {
        let cli = Cli::try_parse_from(std::iter::once("bench").chain(args.iter().copied())).unwrap();
        Plan::new(&cli.bench)
    }

    #[test]
    fn text_filters_pick_the_text_group_and_its_rows() {
        let all = plan(&[]).unwrap();
        assert!(all.polygon && all.text_rows.len() == 5);
        let text = plan(&["--workload", "text"]).unwrap();
        assert!(!text.polygon && text.text_rows.len() == 5);
        let star = plan(&["--workload", "star"]).unwrap();
        assert!(star.polygon && star.text_rows.is_empty() && star.polygon_groups == ["star"]);
        let char_row = plan(&["--clipper", "text-char", "--clipper", "text-outline"]).unwrap();
        assert!(!char_row.polygon && char_row.text_rows == ["char", "outline-vatti"]);
        let vatti = plan(&["--clipper", "vatti"]).unwrap();
        assert!(vatti.polygon && vatti.text_rows.is_empty());
        assert!(plan(&["--clipper", "text-nope"]).is_err());
        assert!(plan(&["--workload", "text", "--op", "union"]).is_err());
        assert!(plan(&["--clipper", "text-char", "--op", "union"]).is_err());
        let both = plan(&["--workload", "text", "--workload", "grid", "--op", "union"]).unwrap();
        assert!(both.polygon && both.text_rows.is_empty());
    }
}
