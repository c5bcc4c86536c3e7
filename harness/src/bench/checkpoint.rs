//! The groups a `bench` run has finished, kept in its output folder as it goes, so a run that
//! stops part way (a session's end, a killed process) is taken up with `--resume` at the first
//! group it did not finish. A group's ratios are times measured together in one stretch, with
//! Clipper2 timed in it, so a finished group is a whole result; a group cut short is measured again.

use std::fs;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::plan::Group;
use crate::cli_error::CliError;
use crate::measure::raw::Measurement;
use crate::results_files::bench::MemoryRecord;

/// The folder, inside the bench's output folder, holding one file per finished group.
pub const FOLDER: &str = "bench-groups-done";

/// What one finished group measured, and under which run it was measured.
#[derive(Debug, Serialize, Deserialize)]
pub struct FinishedGroup {
    /// The run's revision and settings ([`Checkpoint::new`]): a group is taken up only by a
    /// run with the same.
    pub run: String,
    /// The group's own description (workload, cases, sizes, operations).
    pub group: String,
    pub rows: Vec<Measurement>,
    pub memory: Vec<MemoryRecord>,
    pub notes: Vec<String>,
    /// Whether a peak-memory probe failed in this group.
    pub memory_unavailable: bool,
}

/// Where a run keeps its finished groups, and whether it takes up those of an earlier run.
pub struct Checkpoint {
    dir: PathBuf,
    run: String,
    resume: bool,
}

impl Checkpoint {
    /// The checkpoint of a run described by `run` (its revision and settings) writing into `out`.
    /// Without `resume` an earlier run's finished groups are removed first.
    pub fn new(out: &Path, run: String, resume: bool) -> Result<Checkpoint, CliError> {
        let dir = out.join(FOLDER);
        if !resume && dir.exists() {
            fs::remove_dir_all(&dir).map_err(|e| CliError::failed(format!("removing {}: {e}", dir.display())))?;
        }
        Ok(Checkpoint { dir, run, resume })
    }

    /// The run's revision and settings, as each finished group records them.
    pub fn run(&self) -> &str {
        &self.run
    }

    fn file(&self, group: &Group) -> PathBuf {
        self.dir.join(format!("{}.json", group.label))
    }

    /// `group` as an earlier run with the same revision and settings finished it; `None` when
    /// not resuming, when no run finished it, or when the one that did differs.
    pub fn finished(&self, group: &Group) -> Result<Option<FinishedGroup>, CliError> {
        let file = self.file(group);
        if !self.resume || !file.exists() {
            return Ok(None);
        }
        let text =
            fs::read_to_string(&file).map_err(|e| CliError::failed(format!("reading {}: {e}", file.display())))?;
        let saved: FinishedGroup =
            serde_json::from_str(&text).map_err(|e| CliError::failed(format!("reading {}: {e}", file.display())))?;
        Ok((saved.run == self.run && saved.group == group.describe()).then_some(saved))
    }

    /// Keeps what `group` measured (written whole, then renamed, so a stop mid-write leaves no
    /// half file).
    pub fn finish(&self, group: &Group, done: FinishedGroup) -> Result<(), CliError> {
        let fail = |e: std::io::Error| CliError::failed(format!("writing {}: {e}", self.dir.display()));
        fs::create_dir_all(&self.dir).map_err(fail)?;
        let file = self.file(group);
        let partial = file.with_extension("json.partial");
        let text = serde_json::to_string(&done).map_err(|e| CliError::failed(e.to_string()))?;
        fs::write(&partial, text).map_err(fail)?;
        fs::rename(&partial, &file).map_err(fail)
    }

    /// The run finished: its groups are in bench.csv now.
    pub fn remove(self) -> Result<(), CliError> {
        if self.dir.exists() {
            fs::remove_dir_all(&self.dir)
                .map_err(|e| CliError::failed(format!("removing {}: {e}", self.dir.display())))?;
        }
        Ok(())
    }
}

/// A finished `group` of one row timed at `time_ns`, for tests.
#[cfg(test)]
pub fn finished_for_test(run: &str, group: &Group, time_ns: f64) -> FinishedGroup {
    let row = Measurement {
        workload: group.label.to_owned(),
        case: "0".to_owned(),
        clipper: "vatti".to_owned(),
        phase: "clip".to_owned(),
        size: group.sizes[0],
        op: "intersection".to_owned(),
        fill_rule: "even-odd".to_owned(),
        repetition: 0,
        iterations: 1,
        time_ns,
        correct: Some(true),
    };
    FinishedGroup {
        run: run.to_owned(),
        group: group.describe(),
        rows: vec![row],
        memory: Vec::new(),
        notes: vec!["a note".to_owned()],
        memory_unavailable: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::plan::groups;

    #[test]
    fn a_finished_group_is_taken_up_only_by_a_resumed_run_of_the_same_revision_and_options() {
        let dir = std::env::temp_dir().join(format!("clipbench-checkpoint-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let all = groups(true);
        let (star, other) = (&all[0], &all[1]);
        let first = Checkpoint::new(dir.as_path(), "revision a".to_owned(), false).unwrap();
        first.finish(star, finished_for_test("revision a", star, 12345.0)).unwrap();
        let again = Checkpoint::new(dir.as_path(), "revision a".to_owned(), true).unwrap();
        let taken = again.finished(star).unwrap().expect("the finished group");
        assert_eq!((taken.rows[0].time_ns, taken.notes.clone()), (12345.0, vec!["a note".to_owned()]));
        assert!(again.finished(other).unwrap().is_none(), "a group no run finished");
        let changed = Checkpoint::new(dir.as_path(), "revision b".to_owned(), true).unwrap();
        assert!(changed.finished(star).unwrap().is_none(), "another revision's group");
        // A fresh run (no --resume) drops what an earlier one kept; a finished run removes its own.
        let fresh = Checkpoint::new(dir.as_path(), "revision a".to_owned(), false).unwrap();
        assert!(!dir.as_path().join(FOLDER).exists());
        fresh.finish(star, finished_for_test("revision a", star, 1.0)).unwrap();
        fresh.remove().unwrap();
        assert!(!dir.as_path().join(FOLDER).exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
