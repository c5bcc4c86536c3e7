//! `clipbench reproduce`: the papers' performance tables measured here, and the line clippers'
//! scaling beyond the papers' window sizes, written as raw CSV (and sidecars); `report` turns them
//! into markdown tables and plots beside the papers' own numbers.

mod beyond_paper;
pub mod lecture;
mod pixel_check;
mod table3;
mod table4;

use std::path::{Path, PathBuf};

use crate::cli_error::CliError;
use crate::measure::out_dir::ready_out_dir;

/// The tables `reproduce` knows, by name.
pub const TABLES: [&str; 5] = ["vatti-table3", "wang-table4", "beyond-paper", "lecture", "all"];

/// Arguments of `clipbench reproduce`.
#[derive(Debug, clap::Args)]
pub struct ReproduceArgs {
    /// Which table: vatti-table3 (Vatti 1992, Table 3), wang-table4 (Wang et al. 2005, Table 4),
    /// beyond-paper (line clipping against windows of 6 to 10^4 edges, and 10^6 segments on every
    /// core), lecture (the lecture notes' figures redrawn, the curve clipping bench and what the
    /// text strategies cost) or all.
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

/// One of the papers' tables.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Table {
    /// Vatti 1992, Table 3.
    VattiTable3,
    /// Wang et al. 2005, Table 4.
    WangTable4,
    /// Line clipping beyond Table 4's window sizes (issue 20).
    BeyondPaper,
    /// The lecture notes' figures (Figs. 6-24, 6-27, 6-28 to 6-30), the curve clipping
    /// preliminary tests' savings and the text strategies' cost.
    Lecture,
}

/// What a run is asked to do: its tables in measuring order, and the output folder, made ready.
#[derive(Debug)]
pub struct Plan {
    /// The tables to measure.
    pub tables: Vec<Table>,
    /// The ready output folder.
    pub out: PathBuf,
}

/// Checks the arguments and readies the output folder, before anything is measured.
pub fn plan(args: &ReproduceArgs) -> Result<Plan, CliError> {
    let tables = match args.table.as_str() {
        "vatti-table3" => vec![Table::VattiTable3],
        "wang-table4" => vec![Table::WangTable4],
        "beyond-paper" => vec![Table::BeyondPaper],
        "lecture" => vec![Table::Lecture],
        "all" => vec![Table::VattiTable3, Table::WangTable4, Table::BeyondPaper, Table::Lecture],
        other => {
            return Err(CliError::usage(format!("unknown table '{other}' (valid: {})", TABLES.join(", "))));
        }
    };
    if args.repetitions == Some(0) {
        return Err(CliError::usage("--repetitions must be at least 1"));
    }
    let out = ready_out_dir(&args.out)?;
    Ok(Plan { tables, out })
}

/// Measures one table and writes its raw files into `out`.
pub fn measure(table: Table, args: &ReproduceArgs, out: &Path) -> Result<(), CliError> {
    match table {
        Table::VattiTable3 => table3::measure(&table3::Settings::new(args.seed, args.full, args.repetitions), out),
        Table::WangTable4 => table4::measure(&table4::Settings::new(args.seed, args.full, args.repetitions), out),
        Table::BeyondPaper => {
            beyond_paper::measure(&beyond_paper::Settings::new(args.seed, args.full, args.repetitions), out)
        }
        Table::Lecture => lecture::measure(&lecture::Settings::new(args.seed, args.full, args.repetitions), out),
    }
}
