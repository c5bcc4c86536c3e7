//! `clipbench compare` end to end: a bench run compared with itself reports no change and exits
//! 0; a run with one clipper slowed (by the test-only environment variable) reports the
//! regression and exits 1.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The test-only variable that makes one clipper wait before every call (bench/slowed.rs).
const SLOW: &str = "CLIPBENCH_TEST_ONLY_SLOW_CLIPPER";

fn clipbench(args: &[&str], env: Option<(&str, &str)>) -> Output {
    let mut command = Command::new(env!("CARGO_BIN_EXE_clipbench"));
    command.args(args).env_remove(SLOW);
    if let Some((k, v)) = env {
        command.env(k, v);
    }
    command.output().expect("the clipbench binary runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// A fresh folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("compare").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A small bench of vatti against Clipper2 into `out`, with `slow` set when given.
fn bench(out: &Path, slow: Option<&str>) {
    let args = [
        "bench",
        "--quick",
        "--workload",
        "star",
        "--op",
        "intersection",
        "--clipper",
        "vatti",
        "--rounds",
        "3",
        "--out",
        out.to_str().unwrap(),
    ];
    let o = clipbench(&args, slow.map(|s| (SLOW, s)));
    assert!(o.status.success(), "{}\n{}", text(&o.stdout), text(&o.stderr));
}

#[test]
fn a_run_compared_with_itself_shows_no_change_and_exits_zero() {
    let dir = scratch("self");
    let run = dir.join("run");
    bench(&run, None);
    let o = clipbench(&["compare", run.to_str().unwrap(), run.to_str().unwrap()], None);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{out}\n{}", text(&o.stderr));
    assert!(out.contains("points compared") && out.contains(": 0 regressions, 0 improvements"), "{out}");
    assert!(out.contains("No change beyond the noise."), "{out}");
}

#[test]
fn a_slowed_clipper_is_reported_as_a_regression_and_fails_the_gate() {
    let dir = scratch("slowed");
    let (before, after) = (dir.join("before"), dir.join("after"));
    bench(&before, None);
    // Half a millisecond per call: many times vatti's own time on these small stars.
    bench(&after, Some("vatti:500"));
    let meta = std::fs::read_to_string(after.join("bench.meta.json")).unwrap();
    assert!(meta.contains("TEST ONLY"), "a slowed run says so: {meta}");
    let o = clipbench(&["compare", before.to_str().unwrap(), after.to_str().unwrap()], None);
    let out = text(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{out}\n{}", text(&o.stderr));
    let regressions: Vec<&str> = out.lines().filter(|l| l.contains("**regression**")).collect();
    assert!(!regressions.is_empty() && regressions.iter().all(|l| l.contains("| vatti |")), "{out}");
    // A looser gate than the slow-down lets it pass, still flagged.
    let o =
        clipbench(&["compare", before.to_str().unwrap(), after.to_str().unwrap(), "--max-regression", "100000"], None);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stdout));
    assert!(text(&o.stdout).contains("regression (under the gate)"), "{}", text(&o.stdout));
}
