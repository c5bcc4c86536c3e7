#!/bin/sh
# Reproduce the papers' tables (Vatti 1992 Table 3, Wang et al. 2005 Table 4) into results/:
# raw CSV with provenance sidecars, markdown tables, SVG plots and results/REPORT.md.
# Extra arguments go to `clipbench reproduce`, e.g. `scripts/reproduce.sh --full` for the papers'
# 1000 repetitions, or `scripts/reproduce.sh vatti-table3` for one table.
set -eu
cd "$(dirname "$0")/.."
case "${1:-}" in
    vatti-table3 | wang-table4 | all) table="$1"; shift ;;
    *) table=all ;;
esac
exec cargo run --release -p clipbench -- reproduce "$table" "$@"
