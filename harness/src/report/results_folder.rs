//! A results folder as `report` reads it: the raw files more than one section needs (the bench's
//! rows, their bootstrapped points and peak memory, the verify summary) read and computed once, on first use.

use std::cell::OnceCell;
use std::path::{Path, PathBuf};

use super::bench_points::{Points, points};
use crate::cli_error::CliError;
use crate::measure::raw::{Measurement, read_csv};
use crate::results_files::bench::{CSV, MemoryRecord, TEXT_GROUP, read_memory};
use crate::results_files::verify::{VerifyResults, read};

/// One folder's raw results, each shared file read at most once.
#[derive(Debug)]
pub struct ResultsFolder {
    path: PathBuf,
    bench: OnceCell<Option<Vec<Measurement>>>,
    bench_points: OnceCell<Points>,
    bench_memory: OnceCell<Vec<MemoryRecord>>,
    verify: OnceCell<Option<VerifyResults>>,
}

impl ResultsFolder {
    /// The folder at `path`; nothing is read yet.
    pub fn new(path: &Path) -> ResultsFolder {
        ResultsFolder {
            path: path.to_owned(),
            bench: OnceCell::new(),
            bench_points: OnceCell::new(),
            bench_memory: OnceCell::new(),
            verify: OnceCell::new(),
        }
    }

    /// Where it is.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// `name` in the folder.
    pub fn join(&self, name: &str) -> PathBuf {
        self.path.join(name)
    }

    /// Every row of the bench's raw timings; `None` when the folder has none.
    pub fn bench_rows(&self) -> Result<Option<&[Measurement]>, CliError> {
        if let Some(rows) = self.bench.get() {
            return Ok(rows.as_deref());
        }
        let csv = self.join(CSV);
        let rows = if csv.exists() { Some(read_csv(&csv)?) } else { None };
        Ok(self.bench.get_or_init(|| rows).as_deref())
    }

    /// The bench's polygon rows (every group but the text group's, which has its own section).
    pub fn polygon_bench_rows(&self) -> Result<Vec<&Measurement>, CliError> {
        Ok(self.bench_rows()?.unwrap_or_default().iter().filter(|r| r.workload != TEXT_GROUP).collect())
    }

    /// The points of [`ResultsFolder::polygon_bench_rows`], bootstrapped once.
    pub fn bench_points(&self) -> Result<&Points, CliError> {
        if let Some(points) = self.bench_points.get() {
            return Ok(points);
        }
        let rows = self.polygon_bench_rows()?;
        Ok(self.bench_points.get_or_init(|| points(rows)))
    }

    /// The bench's peak memory records (none when it measured none).
    pub fn bench_memory(&self) -> Result<&[MemoryRecord], CliError> {
        if let Some(records) = self.bench_memory.get() {
            return Ok(records);
        }
        let records = read_memory(&self.path)?;
        Ok(self.bench_memory.get_or_init(|| records))
    }

    /// The verify summary; `None` when the folder has none.
    pub fn verify(&self) -> Result<Option<&VerifyResults>, CliError> {
        if let Some(results) = self.verify.get() {
            return Ok(results.as_ref());
        }
        let results = read(&self.path)?;
        Ok(self.verify.get_or_init(|| results).as_ref())
    }
}
