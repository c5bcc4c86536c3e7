//! `clipbench reproduce`: the papers' performance tables measured here, and the line clippers'
//! scaling beyond the papers' window sizes, written as raw CSV (and sidecars); `report` turns them
//! into markdown tables and plots beside the papers' own numbers. Which tables there are, by name,
//! is `report`'s one list of sections (`report::sections`); this module only measures.

mod beyond_paper;
pub mod lecture;
mod pixel_check;
mod table3;
mod table4;

use std::path::{Path, PathBuf};

use crate::cli_error::CliError;
use crate::measure::out_dir::ready_out_dir;

/// Arguments of `clipbench reproduce`.
#[derive(Debug, clap::Args)]
pub struct ReproduceArgs {
    /// Which table to measure (see the possible values).
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

/// Checks the arguments and readies the output folder, before anything is measured.
pub fn ready(args: &ReproduceArgs) -> Result<PathBuf, CliError> {
    if args.repetitions == Some(0) {
        return Err(CliError::usage("--repetitions must be at least 1"));
    }
    ready_out_dir(&args.out)
}

/// Measures Vatti 1992's Table 3 and writes its raw files into `out`.
pub fn measure_vatti_table3(args: &ReproduceArgs, out: &Path) -> Result<(), CliError> {
    table3::measure(&table3::Settings::new(args.seed, args.full, args.repetitions), out)
}

/// Measures Wang et al. 2005's Table 4 and writes its raw files into `out`.
pub fn measure_wang_table4(args: &ReproduceArgs, out: &Path) -> Result<(), CliError> {
    table4::measure(&table4::Settings::new(args.seed, args.full, args.repetitions), out)
}

/// Measures line clipping beyond Table 4's window sizes (issue 20) and writes its raw files into `out`.
pub fn measure_beyond_paper(args: &ReproduceArgs, out: &Path) -> Result<(), CliError> {
    beyond_paper::measure(&beyond_paper::Settings::new(args.seed, args.full, args.repetitions), out)
}

/// Redraws the lecture notes' figures (Figs. 6-24, 6-27, 6-28 to 6-30), measures the curve
/// clipping preliminary tests' savings and the text strategies' cost, and writes it all into `out`.
pub fn measure_lecture(args: &ReproduceArgs, out: &Path) -> Result<(), CliError> {
    lecture::measure(&lecture::Settings::new(args.seed, args.full, args.repetitions), out)
}
