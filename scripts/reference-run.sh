#!/usr/bin/env bash
# One reference run of everything clipbench measures, at one git revision, into one results
# folder: `clipbench reproduce all --full`, the full `clipbench bench`, `clipbench verify` of every
# registered clipper of every kind (polygon, line, curve, text), with --with-peers the atlas
# (scripts/atlas.sh all), then `clipbench report`. It takes hours, with the atlas days. Every .meta.json it leaves names the revision it prints, and REPORT.md states it.
#
#   scripts/reference-run.sh [--out DIR] [--with-peers] [--quick]
#
#   --out DIR     the results folder (default: results)
#   --with-peers  also run the external clippers of adapters/clippers.toml in bench and verify,
#                 and the atlas into DIR/atlas; this script installs nothing:
#                 scripts/setup-peers.sh installs and builds them
#   --quick       a smoke run in minutes, to try the script: reproduce with 3 repetitions per
#                 point, bench --quick, verify on 3 cases per workload (the atlas's verify and
#                 referee too)
#
# It refuses a work tree with changes (tracked or untracked files outside DIR): the revision must
# name the code that measured. It stops at the first step that fails, except for verify finding
# this project's clippers wrong (exit 1): that is a result, and the run goes on to report it.
set -euo pipefail
cd "$(dirname "$0")/.."

say() { echo "reference-run: $*"; }
fail() { echo "reference-run: $*" >&2; exit 2; }

out=results
peers=()
quick=false
while [ $# -gt 0 ]; do
  case "$1" in
    --out) [ $# -ge 2 ] || fail "--out needs a folder"; out="$2"; shift 2 ;;
    --with-peers) peers=(--clippers adapters/clippers.toml); shift ;;
    --quick) quick=true; shift ;;
    -h | --help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) fail "unknown argument '$1' (valid: --out DIR, --with-peers, --quick)" ;;
  esac
done

# The work tree must be the commit: any change outside the results folder is refused.
root=$(pwd -P)
out_abs=$(realpath -m "$out")
exclude=()
case "$out_abs/" in
  "$root/"*) [ "$out_abs" != "$root" ] || fail "--out must not be the repository's root"
             exclude=(":(exclude)${out_abs#"$root"/}") ;;
esac
changes=$(git status --porcelain --untracked-files=all -- . "${exclude[@]}")
if [ -n "$changes" ]; then
  echo "$changes" >&2
  fail "the work tree has changes (above): commit or stash them, so the revision names what is measured"
fi
if $quick && [ "$out_abs" = "$root/results" ]; then
  fail "--quick is a smoke run: give it an --out folder other than results/, which holds the reference run"
fi
revision=$(git rev-parse HEAD)
say "revision $revision"
say "results into $out_abs"
if [ ${#peers[@]} -eq 0 ]; then
  say "external clippers left out (scripts/setup-peers.sh installs them; then add --with-peers)"
fi

cargo build --release -p clipbench
clipbench="${CARGO_TARGET_DIR:-target}/release/clipbench"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
started="$scratch/started"
touch "$started"

if [ ${#peers[@]} -gt 0 ]; then
  # Every external clipper started once (its handshake checked) before hours of measuring.
  say "checking the external clippers of adapters/clippers.toml start (scripts/setup-peers.sh sets them up)"
  status=0
  "$clipbench" verify "${peers[@]}" --clipper vatti --workload star --cases 1 --out "$scratch/preflight" \
    >/dev/null || status=$?
  [ "$status" -le 1 ] || fail "an external clipper does not start (above): run scripts/setup-peers.sh"
fi

if $quick; then
  reproduce=(--repetitions 3)
  bench=(--quick)
  verify=(--cases 3)
else
  reproduce=(--full)
  bench=()
  verify=()
fi

say "clipbench reproduce all ${reproduce[*]}"
"$clipbench" reproduce all "${reproduce[@]}" --out "$out"
say "clipbench bench ${bench[*]} ${peers[*]}"
# --resume: a run of this script stopped during the bench takes up the groups it finished.
"$clipbench" bench --resume "${bench[@]}" "${peers[@]}" --out "$out"
say "clipbench verify ${verify[*]} ${peers[*]}"
verify_status=0
"$clipbench" verify "${verify[@]}" "${peers[@]}" --results "$out" || verify_status=$?
[ "$verify_status" -le 1 ] || fail "verify stopped (exit $verify_status)"
[ -f "$out/verify.meta.json" ] && [ "$out/verify.meta.json" -nt "$started" ] || fail "verify wrote no results"
if [ ${#peers[@]} -gt 0 ]; then
  # The atlas: every external clipper judged and timed stage by stage into $out/atlas, which the
  # report reads. Days at the atlas's case counts (the JavaScript libraries are slow on the
  # large workloads); a stage left unfinished is missing from the atlas, and its command in
  # $out/atlas/COMMANDS.md finishes it.
  if $quick; then atlas_cases=(3 3); else atlas_cases=(200 2000); fi
  say "scripts/atlas.sh --out $out/atlas all ${atlas_cases[*]}"
  CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-target}" scripts/atlas.sh --out "$out/atlas" all "${atlas_cases[@]}"
fi
say "clipbench report"
"$clipbench" report --out "$out"

# Every sidecar in the folder is this run's and names this revision.
stale=$(find "$out" -maxdepth 1 -name '*.meta.json' ! -newer "$started")
[ -z "$stale" ] || fail "sidecars this run did not write, from an earlier run: $stale"
others=$(grep -L "\"git_revision\": \"$revision\"" "$out"/*.meta.json || true)
[ -z "$others" ] || fail "sidecars naming another revision than $revision: $others"
say "every .meta.json in $out names $revision; REPORT.md: $out/REPORT.md"
if [ "$verify_status" -eq 1 ]; then
  say "verify found this project's clippers failing the oracle: see REPORT.md's \"Where the clippers disagree with the oracle\""
fi
