//! Replays every checked-in fuzz input (each target's minimised corpus, every crash found and the
//! named regressions)
//! through the target's check on the stable toolchain, so CI guards them without libFuzzer.

use std::fs;
use std::path::Path;

use clip_fuzz_checks::{TARGETS, fuzz_dir};

/// The files directly in `dir` (none if it does not exist), sorted by name; pictures and notes
/// beside the crash files are not inputs.
fn inputs(dir: &Path) -> Vec<std::path::PathBuf> {
    let Ok(entries) = fs::read_dir(dir) else { return Vec::new() };
    let mut files: Vec<_> = entries
        .map(|e| e.expect("readable folder").path())
        .filter(|p| p.is_file() && !matches!(p.extension().and_then(|e| e.to_str()), Some("svg" | "md")))
        .collect();
    files.sort();
    files
}

fn replay(folder: &str) -> usize {
    let mut failures = Vec::new();
    let mut count = 0;
    for target in TARGETS {
        for file in inputs(&fuzz_dir().join(folder).join(target.name)) {
            let data = fs::read(&file).expect("readable input");
            count += 1;
            if let Err(why) = (target.check)(&data) {
                failures.push(format!("{}: {why}", file.display()));
            }
        }
    }
    assert!(failures.is_empty(), "{} of {count} inputs fail:\n{}", failures.len(), failures.join("\n"));
    count
}

#[test]
fn every_corpus_input_passes() {
    let count = replay("corpus");
    assert!(count >= TARGETS.len(), "only {count} corpus files found under {}", fuzz_dir().display());
}

#[test]
fn every_crash_found_passes_now() {
    replay("crashes");
    replay("regressions");
}
