//! scripts/fuzz.sh with a stand-in toolchain: it builds every target before the fuzzing minutes
//! start, and fuzzes with the built binaries, so no build runs inside the time it reports on.

use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::process::Command;

/// A fresh folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fuzz-script").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn executable(path: &Path, text: &str) {
    std::fs::write(path, text).unwrap();
    std::fs::set_permissions(path, std::fs::Permissions::from_mode(0o755)).unwrap();
}

/// A `cargo` that logs every call to `$FAKE_LOG`. Its `fuzz build` writes a stand-in fuzzer per
/// target, which logs that it ran and prints a libFuzzer statistics line (line_clippers's counts
/// a timeout and writes its input, as libFuzzer does); its `fuzz run` stands
/// for cargo-fuzz's own build step on a fresh clone: it builds (logged) and prints no statistics.
const CARGO: &str = r##"#!/bin/sh
echo "cargo $*" >> "$FAKE_LOG"
case "$*" in
  *"fuzz build"*)
    dir="$CARGO_TARGET_DIR/x86_64-stand-in/release"
    mkdir -p "$dir"
    for t in vatti window_clippers line_clippers readers; do
      cat > "$dir/$t" <<STANDIN
#!/bin/sh
echo "fuzzer $t \$*" >> "\$FAKE_LOG"
if [ $t = line_clippers ]; then
  for a in "\$@"; do case "\$a" in -artifact_prefix=*) : > "\${a#-artifact_prefix=}timeout-stand-in" ;; esac; done
  echo "#1234: cov: 56 ft: 78 corp: 9 exec/s: 411 oom/timeout/crash: 0/1/0 time: 3s"
else
  echo "#1234: cov: 56 ft: 78 corp: 9 exec/s: 411 oom/timeout/crash: 0/0/0 time: 3s"
fi
STANDIN
      chmod +x "$dir/$t"
    done ;;
  *"fuzz run"*) echo "   Compiling clip-vatti (building inside the fuzzing minutes)" ;;
esac
"##;

/// A `rustc` that names the stand-in host.
const RUSTC: &str = "#!/bin/sh\necho \"rustc $*\" >> \"$FAKE_LOG\"\necho 'host: x86_64-stand-in'\n";

/// `scripts/fuzz.sh 1 readers line_clippers` on a fresh clone printed "no statistics": `cargo fuzz
/// run` rebuilt the crates inside the script's time limit (issue 28). The build comes first and
/// untimed now, and the fuzzing minutes run the built fuzzers only.
#[test]
fn fuzz_sh_builds_first_and_then_times_only_the_fuzzing() {
    let dir = scratch("stand-in");
    let bin = dir.join("bin");
    std::fs::create_dir_all(&bin).unwrap();
    executable(&bin.join("cargo"), CARGO);
    executable(&bin.join("rustc"), RUSTC);
    let log = dir.join("calls.log");
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scripts/fuzz.sh");
    let path = format!("{}:{}", bin.display(), std::env::var("PATH").unwrap_or_default());
    let o = Command::new("sh")
        .arg(&script)
        .args(["1", "readers", "line_clippers"])
        .env("PATH", path)
        .env("FAKE_LOG", &log)
        .env("CARGO_TARGET_DIR", dir.join("target"))
        .env("TMPDIR", &dir)
        .output()
        .expect("sh runs");
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{out}{}", String::from_utf8_lossy(&o.stderr));
    let timeout_input = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz/artifacts/line_clippers/timeout-stand-in");
    let _ = std::fs::remove_file(&timeout_input);
    // A timeout's input is counted as a timeout, not as a crash (the report once called the
    // load-induced timeouts of a 75-minute run "crashes 22").
    for (t, faults) in [("readers", "oom/timeout 0/0, crashes 0"), ("line_clippers", "oom/timeout 0/1, crashes 0")] {
        let line = out.lines().find(|l| l.starts_with(&format!("{t}: "))).unwrap_or_else(|| panic!("{out}"));
        assert!(line.starts_with(&format!("{t}: 1234 executions in 3s, coverage 56, {faults}")), "{line}");
    }
    // Every build before the first fuzzer starts, and the fuzzers given the run's settings.
    let calls = std::fs::read_to_string(&log).unwrap();
    let calls: Vec<&str> = calls.lines().collect();
    let first_fuzzer = calls.iter().position(|c| c.starts_with("fuzzer ")).unwrap_or_else(|| panic!("{calls:?}"));
    assert!(calls[..first_fuzzer].iter().any(|c| c.contains("fuzz build")), "{calls:?}");
    assert!(calls[first_fuzzer..].iter().all(|c| c.starts_with("fuzzer ")), "a build in the timed part: {calls:?}");
    let readers = calls.iter().find(|c| c.starts_with("fuzzer readers ")).unwrap();
    for setting in ["-max_total_time=60", "-artifact_prefix=artifacts/readers/", "corpus/readers", "-fork=1"] {
        assert!(readers.contains(setting), "{readers}");
    }
}
