// Converts world-atlas's TopoJSON countries (Natural Earth admin-0) into clipbench's world map
// files: testdata/world/countries-{110m,50m,10m}.txt (format: testdata/world/FORMAT.md).
//
//   node scripts/world_map.mjs ATLAS_DIR OUT_DIR
//
// ATLAS_DIR is an installed world-atlas package, topojson-client beside it (scripts/world_map.sh
// installs both, pinned). Coordinates stay world-atlas's quantized integers, so every shared
// border is shared exactly and the files stay small; the reader maps q to q * scale + translate,
// the same f64 operations topojson-client makes (checked below for every vertex).
//
// world-atlas 2 is spherical (d3's convention): rings are clockwise and may cross the
// antimeridian, and Antarctica encloses the south pole. For a planar clipper each ring is made
// continuous across the antimeridian (x shifted by one turn, 360°, where it jumps), a ring that
// goes once round the pole is closed along the grid line nearest 90°S, a ring of zero area is
// dropped (50m's line round the pole, a few islets that quantization flattened), and every ring
// is reversed, so exteriors run counter-clockwise and holes clockwise (GeoJSON's RFC 7946 order).

import { createRequire } from "node:module";
import { readFileSync, writeFileSync, mkdirSync } from "node:fs";
import { join, resolve } from "node:path";

const [atlasDir, outDir] = process.argv.slice(2);
if (!atlasDir || !outDir) {
  console.error("usage: node scripts/world_map.mjs ATLAS_DIR OUT_DIR");
  process.exit(2);
}
const require = createRequire(join(resolve(atlasDir), "..", "index.js"));
const topojson = require("topojson-client");
const atlasVersion = JSON.parse(readFileSync(join(atlasDir, "package.json"), "utf8")).version;
const clientVersion = JSON.parse(readFileSync(require.resolve("topojson-client/package.json"), "utf8")).version;

/** Twice the signed area of a ring of integer points (exact: every term and sum is below 2^53). */
function twiceArea(ring) {
  let a = 0;
  for (let i = 0; i < ring.length; i++) {
    const [x0, y0] = ring[i];
    const [x1, y1] = ring[(i + 1) % ring.length];
    a += x0 * y1 - x1 * y0;
  }
  return a;
}

function convert(resolution) {
  const file = join(atlasDir, `countries-${resolution}.json`);
  const topology = JSON.parse(readFileSync(file, "utf8"));
  const { scale, translate } = topology.transform;
  const floats = topojson.feature(topology, topology.objects.countries);
  // The same arcs decoded to their integers: a unit transform still undoes the delta encoding.
  const quantized = topojson.feature(
    { ...topology, transform: { scale: [1, 1], translate: [0, 0] } },
    topology.objects.countries,
  );
  // One turn of longitude in grid units (scale[0] is 360 / turn).
  const turn = Math.round(360 / scale[0]);
  if (Math.abs(turn * scale[0] - 360) > 1e-9) throw new Error(`${file}: x scale is not a whole turn`);
  const pole = Math.ceil((-90 - translate[1]) / scale[1]);
  const stats = { empty: [], countries: 0, rings: 0, vertices: 0, shifted: 0, polar: 0, dropped: 0 };
  const lines = [
    `# Natural Earth admin-0 countries at 1:${resolution}, from world-atlas ${atlasVersion} countries-${resolution}.json`,
    `# (topojson-client ${clientVersion}), converted by scripts/world_map.sh; format: FORMAT.md.`,
    `transform ${scale[0]} ${scale[1]} ${translate[0]} ${translate[1]}`,
  ];
  quantized.features.forEach((feature, f) => {
    const exact = floats.features[f];
    const polygons = (g) => (g.type === "Polygon" ? [g.coordinates] : g.coordinates);
    const rings = [];
    polygons(feature.geometry).forEach((polygon, p) => {
      polygon.forEach((closed, r) => {
        const points = closed.slice(0, -1);
        // The reader's arithmetic gives topojson-client's coordinates exactly.
        const want = polygons(exact.geometry)[p][r];
        points.forEach(([qx, qy], i) => {
          if (qx * scale[0] + translate[0] !== want[i][0] || qy * scale[1] + translate[1] !== want[i][1]) {
            throw new Error(`${file}: ${exact.properties.name} ring ${r}: vertex ${i} does not decode exactly`);
          }
        });
        // Continuous across the antimeridian: undo each jump of more than half a turn.
        let shift = 0;
        const ring = points.map(([x, y], i) => {
          if (i > 0) {
            const dx = x + shift - (points[i - 1][0] + shift);
            if (dx > turn / 2) shift -= turn;
            else if (dx < -turn / 2) shift += turn;
          }
          return [x + shift, y];
        });
        if (ring.some(([x], i) => x !== points[i][0])) {
          stats.shifted += 1;
          // A vertex on the antimeridian given at both 180° and -180° is now one vertex twice.
          const same = (a, b) => a[0] === b[0] && a[1] === b[1];
          for (let i = ring.length - 1; i > 0; i--) if (same(ring[i], ring[i - 1])) ring.splice(i, 1);
          while (ring.length > 1 && same(ring[0], ring[ring.length - 1])) ring.pop();
        }
        // A closing edge that jumps by more than half a turn: the ring went once round the pole,
        // and `around` is the turn it made.
        const last = ring[ring.length - 1];
        const jump = ring[0][0] - last[0];
        const around = jump > turn / 2 ? -turn : jump < -turn / 2 ? turn : 0;
        if (around !== 0) {
          // On to the start one turn on, down to the pole, back across, and up to the start.
          const end = [ring[0][0] + around, ring[0][1]];
          if (last[0] !== end[0] || last[1] !== end[1]) ring.push(end);
          ring.push([end[0], pole], [ring[0][0], pole]);
        }
        if (twiceArea(ring) === 0) {
          stats.dropped += 1; // no area: 50m's line round the pole, islets quantized to a line
          return;
        }
        if (around !== 0) stats.polar += 1;
        ring.reverse();
        rings.push(ring);
      });
    });
    // Exteriors clockwise in the source, so counter-clockwise now; holes the other way.
    const id = exact.id === undefined ? "-" : exact.id;
    if (rings.length === 0) {
      stats.empty.push(exact.properties.name); // every ring quantized to no area (10m's Vatican)
      return;
    }
    lines.push(`country ${id} ${exact.properties.name}`);
    stats.countries += 1;
    for (const ring of rings) {
      const words = [ring[0][0], ring[0][1]];
      for (let i = 1; i < ring.length; i++) words.push(ring[i][0] - ring[i - 1][0], ring[i][1] - ring[i - 1][1]);
      lines.push(`ring ${words.join(" ")}`);
      stats.rings += 1;
      stats.vertices += ring.length;
    }
  });
  const out = join(outDir, `countries-${resolution}.txt`);
  writeFileSync(out, lines.join("\n") + "\n");
  console.log(
    `${out}: ${stats.countries} countries, ${stats.rings} rings, ${stats.vertices} vertices ` +
      `(${stats.shifted} rings made continuous across the antimeridian, ${stats.polar} closed at the pole, ` +
      `${stats.dropped} rings of zero area dropped` +
      (stats.empty.length ? `, leaving no ring of ${stats.empty.join(", ")}, left out)` : ")"),
  );
}

mkdirSync(outDir, { recursive: true });
for (const resolution of ["110m", "50m", "10m"]) convert(resolution);
