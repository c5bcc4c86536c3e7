//! `clipbench report`: every result in the output folder recomputed from its raw CSV into
//! markdown tables and plots, gathered in REPORT.md.

pub mod atlas;
pub mod bench_points;
pub mod bench_tables;
pub mod beyond_paper;
pub mod derived;
pub mod document;
pub mod lecture_curves;
pub mod lecture_sh;
pub mod lecture_text;
pub mod markdown;
mod oracle_failures;
mod provenance_line;
pub mod results_folder;
pub mod revisions;
pub mod sections;
pub mod summary;
pub mod table3;
pub mod table4;
pub mod wording;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::cli_error::CliError;
use crate::measure::out_dir::ready_out_dir;

/// Arguments of `clipbench report`.
#[derive(Debug, clap::Args)]
pub struct ReportArgs {
    /// Folder holding the raw results (`reproduce` and `bench` output); REPORT.md is written there.
    #[arg(long, default_value = "results")]
    pub out: PathBuf,
}

/// Runs the command: derives every section once from the CSVs present (its markdown file and
/// plots), then REPORT.md.
pub fn run(args: &ReportArgs) -> Result<ExitCode, CliError> {
    if !args.out.is_dir() {
        return Err(CliError::usage(format!(
            "{} is not a folder of results (run `clipbench reproduce all` or `clipbench bench` first)",
            args.out.display()
        )));
    }
    let out = ready_out_dir(&args.out)?;
    write_report(&out)?;
    Ok(ExitCode::SUCCESS)
}

/// Derives every section of the results in `out` once, writes their files and REPORT.md, and says
/// where it is.
pub fn write_report(out: &Path) -> Result<(), CliError> {
    finish(document::ReportRun::new(out))
}

/// Writes what `report` has not derived yet and REPORT.md, and says where it is.
pub fn finish(report: document::ReportRun) -> Result<(), CliError> {
    let path = report.write()?;
    eprintln!("clipbench: wrote {}", path.display());
    Ok(())
}
