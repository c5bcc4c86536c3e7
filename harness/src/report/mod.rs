//! `clipbench report`: every result in the output folder recomputed from its raw CSV into
//! markdown tables and plots, gathered in REPORT.md.

pub mod bench_tables;
pub mod document;
pub mod markdown;
pub mod table3;
pub mod table4;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use crate::cli_error::CliError;
use crate::measure::out_dir::ready_out_dir;
use crate::measure::provenance::Provenance;

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
    bench_tables::write(&out)?;
    write_report(&out)?;
    Ok(ExitCode::SUCCESS)
}

/// Writes REPORT.md from every result in `out` and says where it is.
pub fn write_report(out: &Path) -> Result<(), CliError> {
    document::write(out)?;
    eprintln!("clipbench: wrote {}", out.join(document::REPORT_FILE).display());
    Ok(())
}

/// A result file's sidecar, and a markdown paragraph giving its provenance and notes.
pub fn provenance_line(meta: &Path) -> Result<(Provenance, String), CliError> {
    let p = Provenance::read(meta)?;
    let file = meta.file_name().map_or_else(String::new, |f| f.to_string_lossy().into_owned());
    let mut text = format!("Run: `clipbench {}`, {} (`{file}`).\n\n", p.command, p.summary());
    for note in &p.notes {
        text.push_str(&format!("- Note: {note}\n"));
    }
    Ok((p, text))
}
