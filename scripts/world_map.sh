#!/bin/sh
# Rebuilds testdata/world/countries-{110m,50m,10m}.txt from the npm packages world-atlas (Natural
# Earth admin-0 countries as TopoJSON) and topojson-client, pinned below, installed in a temporary
# folder. Needs node and npm. The conversion is scripts/world_map.mjs; the format
# testdata/world/FORMAT.md.
#
#   scripts/world_map.sh
set -eu
root="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
npm init -y >/dev/null
npm install --save-exact --no-audit --no-fund world-atlas@2.0.2 topojson-client@3.1.0 >/dev/null
node "$root/scripts/world_map.mjs" "$work/node_modules/world-atlas" "$root/testdata/world"
cp "$work/node_modules/world-atlas/LICENSE" "$root/testdata/world/LICENSE-world-atlas"
