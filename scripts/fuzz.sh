#!/bin/sh
# Coverage-guided fuzzing of every clipper and reader (fuzz/, cargo-fuzz with libFuzzer on the
# nightly toolchain). Every target is built first, however long that takes on a fresh clone; then
# each runs for MINUTES (default 5) of fuzzing, two at a time (the machine has two cores), reading
# its checked-in corpus fuzz/corpus/<target>/ and adding what it finds to fuzz/corpus-raw/<target>/
# (not checked in). Prints executions, coverage and crashes per target; crashing inputs land in
# fuzz/artifacts/<target>/. The fuzzers run as the built binaries, not through `cargo fuzz run`,
# whose own build step would otherwise count against the minutes (on a fresh clone it rebuilt the
# crates inside them and the report said "no statistics").
#
#   scripts/fuzz.sh [MINUTES] [TARGET...]   fuzz (all targets unless some are named)
#   scripts/fuzz.sh --merge [TARGET...]     minimise corpus + corpus-raw into fuzz/corpus/<target>/
#
# A crash: `cargo run -p clip-fuzz-checks --example show -- TARGET FILE [OUT.svg]` shows the case;
# once fixed, copy it to fuzz/regressions/TARGET/NAME with a named test in
# crates/fuzz-checks/tests/regressions.rs (the stable `cargo test` replays all of them).
set -eu
cd "$(dirname "$0")/../fuzz"

all_targets="vatti window_clippers line_clippers readers"

if ! cargo +nightly --version >/dev/null 2>&1; then
    echo "fuzz.sh: installing the nightly toolchain (cargo-fuzz needs it)"
    rustup toolchain install nightly --profile minimal
fi
if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "fuzz.sh: installing cargo-fuzz"
    cargo install cargo-fuzz
fi

# Safe Rust throughout (unsafe_code is forbidden), so no sanitizer: several times the speed.
fuzz="cargo +nightly fuzz"
sanitizer="--sanitizer none"

if [ "${1:-}" = "--merge" ]; then
    shift
    for t in ${*:-$all_targets}; do
        mkdir -p "corpus/$t" "corpus-raw/$t"
        cp -n corpus-raw/"$t"/* "corpus/$t/" 2>/dev/null || true
        # Set-cover merge: the smallest set of inputs that keeps every feature (smaller than -merge=1).
        $fuzz cmin $sanitizer "$t" "corpus/$t" -- -max_len=4096 -timeout=10 -set_cover_merge=1 >"${TMPDIR:-/tmp}/fuzz-cmin-$t.log" 2>&1 \
            || { echo "fuzz.sh: cmin of $t failed, see ${TMPDIR:-/tmp}/fuzz-cmin-$t.log" >&2; exit 1; }
        echo "$t: $(ls "corpus/$t" | wc -l) corpus files, $(du -sb "corpus/$t" | cut -f1) bytes"
    done
    exit 0
fi

minutes="${1:-5}"
[ $# -gt 0 ] && shift
targets="${*:-$all_targets}"
seconds=$((minutes * 60))
logs="${TMPDIR:-/tmp}/clipbench-fuzz.$$"
mkdir -p "$logs"

echo "fuzz.sh: building the targets (untimed; see $logs/build.log)"
# `cargo fuzz build` takes one target or all of them.
set -- $targets
if [ $# -eq 1 ]; then build_what="$1"; else build_what=""; fi
$fuzz build $sanitizer $build_what >"$logs/build.log" 2>&1 || { cat "$logs/build.log" >&2; exit 1; }
# Where cargo-fuzz put them: target/<host triple>/release/ (or under CARGO_TARGET_DIR).
triple=$(rustc +nightly -vV | sed -n 's/^host: //p')
bin="${CARGO_TARGET_DIR:-target}/$triple/release"
for t in $targets; do
    [ -x "$bin/$t" ] || { echo "fuzz.sh: the build left no $bin/$t" >&2; exit 1; }
done

run() {
    t="$1"
    mkdir -p "corpus-raw/$t" "corpus/$t" "artifacts/$t"
    dict=""
    [ -f "dicts/$t.dict" ] && dict="-dict=dicts/$t.dict"
    # -fork=1 with -ignore_*: keep fuzzing after a crash, so one run reports all it finds.
    # -timeout and -max_len are the hang guard: a run longer than 10 s is reported as a timeout.
    # The outer timeout only guards against a fuzzer that does not stop at -max_total_time.
    timeout $((seconds + 120)) nice -n 10 "$bin/$t" -artifact_prefix="artifacts/$t/" \
        -max_len=4096 -timeout=10 $dict -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
        -max_total_time="$seconds" "corpus-raw/$t" "corpus/$t" >"$logs/$t.log" 2>&1 || true
}

report() {
    t="$1"
    # libFuzzer's fork mode prints "#EXECS: cov: C ft: F corp: N exec/s: E oom/timeout/crash: O/T/C time: S"
    # about once a minute.
    last=$(grep -E '^#[0-9]+: cov:' "$logs/$t.log" | tail -n 1)
    if [ -z "$last" ]; then
        echo "$t: no statistics (see $logs/$t.log)"
        return
    fi
    execs=$(echo "$last" | sed -E 's/^#([0-9]+):.*/\1/')
    cov=$(echo "$last" | sed -E 's/.* cov: ([0-9]+).*/\1/')
    faults=$(echo "$last" | sed -E 's/.*oom\/timeout\/crash: ([0-9\/]+).*/\1/')
    secs=$(echo "$last" | sed -E 's/.* time: ([0-9]+)s.*/\1/')
    # The statistics line can predate the last crash: count the crashing inputs written instead
    # (crash-*; libFuzzer also writes timeout-* and slow-unit-* there, counted above).
    crashes=$(find "artifacts/$t" -type f -name 'crash-*' -newer "$logs/start" 2>/dev/null | wc -l)
    echo "$t: $execs executions in ${secs}s, coverage $cov, oom/timeout $(echo "$faults" | cut -d/ -f1-2), crashes $crashes"
    if [ "$crashes" -gt 0 ]; then
        echo "  new crashing inputs in fuzz/artifacts/$t/"
    fi
}

echo "fuzz.sh: $minutes minute(s) per target, two at a time; logs in $logs"
touch "$logs/start"
set -- $targets
while [ $# -gt 0 ]; do
    first="$1"; shift
    if [ $# -gt 0 ]; then
        second="$1"; shift
        run "$first" & run "$second" & wait
        report "$first"; report "$second"
    else
        run "$first"
        report "$first"
    fi
done
