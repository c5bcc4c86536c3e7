//! `clipbench reproduce`: the papers' performance tables measured here, written as raw CSV, then
//! as markdown tables and plots beside the papers' own numbers.

mod pixel_check;
pub mod table3;
pub mod table4;

use std::path::PathBuf;
use std::process::ExitCode;

use crate::cli_error::CliError;
use crate::measure::out_dir::ready_out_dir;
use crate::report;

/// The tables `reproduce` knows, by name.
pub const TABLES: [&str; 3] = ["vatti-table3", "wang-table4", "all"];

/// Arguments of `clipbench reproduce`.
#[derive(Debug, clap::Args)]
pub struct ReproduceArgs {
    /// Which table: vatti-table3 (Vatti 1992, Table 3), wang-table4 (Wang et al. 2005, Table 4)
    /// or all.
    #[arg(value_name = "TABLE")]
    pub table: String,
    /// The papers' repetition counts (1000 per point) instead of a quick run's.
    #[arg(long)]
    pub full: bool,
    /// Repetitions per point, overriding both the default and --full.
    #[arg(long, value_name = "N")]
    pub repetitions: Option<usize>,
    /// Folder for the CSV, markdown, SVG and REPORT.md files.
    #[arg(long, default_value = "results")]
    pub out: PathBuf,
    /// Seed of the generated subjects, windows and segments.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
}

/// Runs the command: measures the asked tables, then rewrites their markdown, plots and REPORT.md.
pub fn run(args: &ReproduceArgs) -> Result<ExitCode, CliError> {
    let (vatti, wang) = match args.table.as_str() {
        "vatti-table3" => (true, false),
        "wang-table4" => (false, true),
        "all" => (true, true),
        other => {
            return Err(CliError::usage(format!("unknown table '{other}' (valid: {})", TABLES.join(", "))));
        }
    };
    if args.repetitions == Some(0) {
        return Err(CliError::usage("--repetitions must be at least 1"));
    }
    let out = ready_out_dir(&args.out)?;
    if vatti {
        let settings = table3::Settings::new(args.seed, args.full, args.repetitions);
        table3::measure(&settings, &out)?;
        report::table3::write(&out)?;
    }
    if wang {
        let settings = table4::Settings::new(args.seed, args.full, args.repetitions);
        table4::measure(&settings, &out)?;
        report::table4::write(&out)?;
    }
    report::document::write(&out)?;
    eprintln!("clipbench: wrote {}", out.join(report::document::REPORT_FILE).display());
    Ok(ExitCode::SUCCESS)
}
