//! `clipbench merge DIR... --out DIR`: joins the results folders of a verify run's parts (each
//! written by `verify --partition K/N --results DIR` with the same other options) into the folder
//! the run would have written whole: the same rows, the same failure cases, in the same order,
//! which `report` reads like any other.
//!
//! The rows add up. The failures a whole run writes are the first `--max-records` of each clipper,
//! workload and check in case order; each part wrote the first of its own, which include every
//! one of those, so the merge sorts the parts' cases back into case order, keeps the first of each
//! again, and copies their folders (with their replay commands pointing into the new folder).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::cli_error::CliError;
use crate::console;
use crate::measure::out_dir::ready_out_dir;
use crate::measure::provenance::Provenance;
use crate::partition::Partition;
use crate::results_files::verify::{self as verify_files, CaseEntry, VerifyResults, VerifyRow, first_of_each};
use crate::verify::record::{CaseFile, replay_command};
use crate::write::write_file;

/// Arguments of `clipbench merge`.
#[derive(Debug, clap::Args)]
pub struct MergeArgs {
    /// The parts' results folders, each written by `clipbench verify --partition K/N --results
    /// DIR`, every part 1 to N once, with the same other options.
    #[arg(required = true, value_name = "DIR")]
    pub parts: Vec<PathBuf>,
    /// The folder to write the merged results to: verify.json, verify.meta.json and
    /// verify-failures/ (replaced), as `verify --results` writes them.
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
}

/// One part read back.
struct Part {
    dir: PathBuf,
    results: VerifyResults,
    meta: Provenance,
    partition: Partition,
}

/// Runs the command: exit 1 when a clipper of this project failed in some part, as the whole run
/// would have.
pub fn run(args: &MergeArgs) -> Result<ExitCode, CliError> {
    let mut parts: Vec<Part> = args.parts.iter().map(|dir| read_part(dir)).collect::<Result<_, _>>()?;
    parts.sort_by_key(|p| p.partition.k);
    check_parts(&parts, &args.out)?;
    let first = &parts[0];
    let parameters = without_partition(&first.meta.parameters);
    let workloads: Vec<String> = parameters
        .get("workloads")
        .and_then(|w| serde_json::from_value(w.clone()).ok())
        .ok_or_else(|| CliError::usage(format!("{}: its sidecar lists no workloads", first.dir.display())))?;
    let max_records = parameters.get("max_records").and_then(serde_json::Value::as_u64).unwrap_or(0) as usize;
    let ordinal = |w: &str| workloads.iter().position(|x| x == w).unwrap_or(workloads.len());

    // Rows: added up per clipper, kind and workload; workloads in the run's order, and within a
    // workload in the order every part lists them (that of the registry).
    let mut rows: Vec<VerifyRow> = Vec::new();
    for part in &parts {
        for row in &part.results.rows {
            match rows.iter_mut().find(|r| r.clipper == row.clipper && r.kind == row.kind && r.workload == row.workload)
            {
                Some(r) => r.add(row),
                None => rows.push(row.clone()),
            }
        }
    }
    rows.sort_by_key(|r| ordinal(&r.workload));

    // Failure cases back in case order (a case's failures all come from one part, in the order
    // found), then the first of each clipper, workload and check, as a whole run chooses them.
    let mut found: Vec<(&Part, &CaseEntry)> =
        parts.iter().flat_map(|p| p.results.cases.iter().map(move |c| (p, c))).collect();
    found.sort_by_key(|(_, c)| (ordinal(&c.workload), c.index));
    let (kept, _) = first_of_each(&found, max_records, |(_, c)| {
        (c.clipper.clone(), c.workload.clone(), c.check.clone(), c.other.clone())
    });
    let total: usize = parts.iter().map(|p| p.results.failures_recorded + p.results.failures_not_recorded).sum();

    let out = ready_out_dir(&args.out)?;
    let failures = out.join(verify_files::FAILURES);
    if failures.exists() {
        std::fs::remove_dir_all(&failures)
            .map_err(|e| CliError::failed(format!("{}: cannot clear it ({e})", failures.display())))?;
    }
    let mut cases = Vec::new();
    for &i in &kept {
        let (part, entry) = found[i];
        cases.push(copy_case(&part.dir.join(verify_files::FAILURES), &failures, entry)?);
    }
    let merged = VerifyResults {
        seed: first.results.seed,
        cases_per_workload: first.results.cases_per_workload,
        rows,
        failures_recorded: cases.len(),
        failures_not_recorded: total - cases.len(),
        ours_failed: parts.iter().any(|p| p.results.ours_failed),
        cases,
        partition: None,
    };
    let text = serde_json::to_string_pretty(&merged).map_err(|e| CliError::failed(e.to_string()))? + "\n";
    write_file(&out.join(verify_files::JSON), &text)?;
    let mut meta = Provenance::now("verify", merged.seed, parameters);
    meta.notes.push(format!(
        "merged by `clipbench merge` from {} parts: {}",
        parts.len(),
        parts.iter().map(|p| format!("{} ({})", p.dir.display(), p.meta.summary())).collect::<Vec<_>>().join("; ")
    ));
    meta.write(&out.join(verify_files::META))?;
    console::print_line(format_args!(
        "merged {} parts into {}: {} rows, {} failure case(s) written, {} not written (--max-records)",
        parts.len(),
        out.display(),
        merged.rows.len(),
        merged.failures_recorded,
        merged.failures_not_recorded
    ))?;
    Ok(if merged.ours_failed { ExitCode::FAILURE } else { ExitCode::SUCCESS })
}

fn read_part(dir: &Path) -> Result<Part, CliError> {
    let results = verify_files::read(dir)?.ok_or_else(|| {
        CliError::usage(format!("{}: holds no {} (not a `verify --results` folder)", dir.display(), verify_files::JSON))
    })?;
    let meta_path = dir.join(verify_files::META);
    if !meta_path.exists() {
        return Err(CliError::usage(format!("{}: has no {}", dir.display(), verify_files::META)));
    }
    let meta = Provenance::read(&meta_path)?;
    let partition = results.partition.ok_or_else(|| {
        CliError::usage(format!("{}: is a whole run, not a part (it was run without --partition)", dir.display()))
    })?;
    Ok(Part { dir: dir.to_owned(), results, meta, partition })
}

/// The parts (sorted by K) are parts 1 to N of one run, each once, and the output is none of them.
fn check_parts(parts: &[Part], out: &Path) -> Result<(), CliError> {
    let first = &parts[0];
    let n = first.partition.n;
    for part in parts {
        let differs = |what: &str| {
            CliError::usage(format!(
                "{} and {} are not parts of one run: their {what} differ",
                first.dir.display(),
                part.dir.display()
            ))
        };
        if part.partition.n != n {
            return Err(differs("part counts (--partition K/N)"));
        }
        if part.results.seed != first.results.seed {
            return Err(differs("seeds"));
        }
        if part.results.cases_per_workload != first.results.cases_per_workload {
            return Err(differs("case counts (--cases)"));
        }
        if without_partition(&part.meta.parameters) != without_partition(&first.meta.parameters) {
            return Err(differs("options (clippers, workloads, operations, fill rules, segments, --max-records)"));
        }
    }
    for k in 1..=n {
        match parts.iter().filter(|p| p.partition.k == k).count() {
            1 => {}
            0 => return Err(CliError::usage(format!("part {k}/{n} is missing: give every part's folder once"))),
            _ => return Err(CliError::usage(format!("part {k}/{n} is given more than once"))),
        }
    }
    let same = |a: &Path, b: &Path| match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    if let Some(part) = parts.iter().find(|p| same(&p.dir, out)) {
        return Err(CliError::usage(format!(
            "--out {} is one of the parts: merge into another folder",
            part.dir.display()
        )));
    }
    Ok(())
}

/// The run's parameters, which its parts share, without the part itself.
fn without_partition(parameters: &serde_json::Value) -> serde_json::Value {
    let mut p = parameters.clone();
    if let Some(map) = p.as_object_mut() {
        map.remove("partition");
    }
    p
}

/// Copies a failure folder from a part's failures folder `from` into `to`, its replay command
/// (in case.json, replay.txt and the entry) pointing at the copy; returns the entry.
fn copy_case(from: &Path, to: &Path, entry: &CaseEntry) -> Result<CaseEntry, CliError> {
    let (source, target) = (from.join(&entry.folder), to.join(&entry.folder));
    std::fs::create_dir_all(&target)
        .map_err(|e| CliError::failed(format!("{}: cannot create it: {e}", target.display())))?;
    let case_path = source.join("case.json");
    let text = std::fs::read_to_string(&case_path)
        .map_err(|e| CliError::failed(format!("{}: cannot read it: {e}", case_path.display())))?;
    let mut case: CaseFile = serde_json::from_str(&text)
        .map_err(|e| CliError::failed(format!("{}: not a verify case file: {e}", case_path.display())))?;
    // The options after `clipbench verify --replay PATH` (external clippers) are kept.
    let words = shlex::split(&case.replay).unwrap_or_default();
    let options = shlex::try_join(words.iter().skip(4).map(String::as_str)).unwrap_or_default();
    let options: Vec<String> = if options.is_empty() { Vec::new() } else { vec![options] };
    case.replay = replay_command(&target.join("case.json"), &options);
    let entries = std::fs::read_dir(&source)
        .map_err(|e| CliError::failed(format!("{}: cannot read it: {e}", source.display())))?;
    for file in entries {
        let file = file.map_err(|e| CliError::failed(format!("{}: cannot read it: {e}", source.display())))?;
        let name = file.file_name();
        let copied = target.join(&name);
        match name.to_str() {
            Some("case.json") => write_file(
                &copied,
                &(serde_json::to_string_pretty(&case).map_err(|e| CliError::failed(e.to_string()))? + "\n"),
            )?,
            Some("replay.txt") => write_file(&copied, &format!("{}\n", case.replay))?,
            _ => {
                std::fs::copy(file.path(), &copied)
                    .map_err(|e| CliError::failed(format!("{}: cannot copy it: {e}", file.path().display())))?;
            }
        }
    }
    Ok(entry.clone())
}
