//! `clipbench report`: every result in the output folder recomputed from its raw CSV into
//! markdown tables and plots, gathered in REPORT.md.

pub mod bench_tables;
pub mod beyond_paper;
pub mod document;
pub mod lecture_curves;
pub mod lecture_sh;
pub mod lecture_text;
pub mod markdown;
mod oracle_failures;
mod provenance_line;
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

/// Runs the command: recomputes every table and plot from the CSVs present, then REPORT.md.
pub fn run(args: &ReportArgs) -> Result<ExitCode, CliError> {
    if !args.out.is_dir() {
        return Err(CliError::usage(format!(
            "{} is not a folder of results (run `clipbench reproduce all` or `clipbench bench` first)",
            args.out.display()
        )));
    }
    let out = ready_out_dir(&args.out)?;
    table3::write(&out)?;
    table4::write(&out)?;
    beyond_paper::write(&out)?;
    lecture_curves::write(&out)?;
    bench_tables::write(&out)?;
    lecture_text::write(&out)?;
    write_report(&out)?;
    Ok(ExitCode::SUCCESS)
}

/// Writes REPORT.md from every result in `out` and says where it is.
pub fn write_report(out: &Path) -> Result<(), CliError> {
    document::write(out)?;
    eprintln!("clipbench: wrote {}", out.join(document::REPORT_FILE).display());
    Ok(())
}

/// Writes a section's own markdown file (`file` in `out`) when `out` holds its results.
fn write_markdown(out: &Path, file: &str, section: Option<String>) -> Result<(), CliError> {
    match section {
        Some(section) => crate::write::write_file(&out.join(file), &section),
        None => Ok(()),
    }
}
