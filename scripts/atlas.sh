#!/usr/bin/env bash
# The atlas's raw material: every external clipper of adapters/clippers.toml judged and timed by
# clipbench, into results/atlas/ (one file per stage and workload, each with the command that made
# it in results/atlas/COMMANDS.md). Run scripts/setup-peers.sh first.
#
#   scripts/atlas.sh [--out DIR] verify [CASES]   oracle failures per workload (default 200 cases; the atlas wants 2000)
#   scripts/atlas.sh [--out DIR] conformance      Clipper2's Polygons.txt and geo's boolean-op fixtures
#   scripts/atlas.sh [--out DIR] hostile          crashes, hangs and refusals on the fixed hostile set (testdata/hostile)
#   scripts/atlas.sh [--out DIR] bench            speed and peak memory against Clipper2, small and large sizes
#   scripts/atlas.sh [--out DIR] referee [CASES]  CGAL's exact result areas against the oracle's (default 2000 cases)
#   scripts/atlas.sh [--out DIR] all [VERIFY_CASES [REFEREE_CASES]]
#                                                 every stage, quickest first (scripts/reference-run.sh
#                                                 --with-peers runs it into its results folder)
#
# --out DIR: the atlas folder (default results/atlas; `clipbench report --out R` reads R/atlas).
# A stage run by workload gives the same rows as one run over all of them; the split keeps each
# workload's file even when a later one is stopped. Verify runs vatti and Clipper2 beside the
# external clippers, for reference.
set -euo pipefail
cd "$(dirname "$0")/.."
out=results/atlas
if [ "${1:-}" = --out ]; then
  [ $# -ge 2 ] || { echo "atlas.sh: --out needs a folder" >&2; exit 2; }
  out="$2"
  shift 2
fi
mkdir -p "$out"
clipbench="${CARGO_TARGET_DIR:-target}/release/clipbench"
cargo build --release -p clipbench --quiet
clippers=(--clippers adapters/clippers.toml)
# Every polygon workload (clip-testkit's POLYGON_WORKLOADS; a test in harness/tests/reference_run.rs checks it).
workloads=(vatti-t3 star star-far holes multi grid spiky-box many-subjects near-coincident scribble-rect scribble large
  comb nested concentric spiral windows corrosion lines-net checkerboard not-overlap wind-mill maps)

# run FILE COMMAND...: runs the command (nice), its output into FILE, the command line into COMMANDS.md.
run() {
  local file="$1"
  shift
  echo "atlas: $* > $file"
  printf -- '- `%s > %s`\n' "$*" "$file" >>"$out/COMMANDS.md"
  nice -n 10 "$@" >"$file" 2>&1 || true
}

stage="${1:-}"
case "$stage" in
  verify)
    cases="${2:-200}"
    dir="$out/verify-$cases"
    mkdir -p "$dir"
    for w in "${workloads[@]}"; do
      run "$dir/$w.txt" "$clipbench" verify "${clippers[@]}" --clipper vatti --clipper clipper2 --workload "$w" \
        --cases "$cases" --max-records 2 --out "$dir/failures" --json "$dir/$w.json"
    done
    ;;
  conformance)
    for suite in clipper2-polygons geo-booleanop; do
      run "$out/conformance-$suite.txt" "$clipbench" conformance "$suite" "${clippers[@]}" --clipper vatti \
        --clipper clipper2 --json "$out/conformance-$suite.json"
    done
    ;;
  hostile)
    run "$out/hostile.txt" "$clipbench" hostile "${clippers[@]}" --clipper vatti --clipper clipper2 \
      --json "$out/hostile.json"
    ;;
  bench)
    run "$out/bench.txt" "$clipbench" bench "${clippers[@]}" --clipper clipper2 --quick --rounds 7 \
      --workload star --workload large-smooth --out "$out/bench"
    ;;
  referee)
    cases="${2:-2000}"
    mkdir -p "$out/referee-$cases"
    for w in "${workloads[@]}"; do
      run "$out/referee-$cases/$w.txt" "$clipbench" referee --referee cgal \
        --external cgal=adapters/cgal/build/clipbench-cgal --workload "$w" --cases "$cases" \
        --json "$out/referee-$cases/$w.json"
    done
    ;;
  all)
    self=(bash "$0" --out "$out")
    "${self[@]}" conformance
    "${self[@]}" hostile
    "${self[@]}" bench
    "${self[@]}" referee "${3:-2000}"
    "${self[@]}" verify "${2:-200}"
    ;;
  *)
    sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2
    exit 2
    ;;
esac
