#!/usr/bin/env node
// The JavaScript clippers people install from npm, behind clipbench's external clipper protocol,
// version 1 (docs/PROTOCOL.md). One program serves each library by name:
//
//   node adapters/node/clipbench_node.mjs martinez|polygon-clipping|polyclip-ts|polybooljs|jsts|clipper-lib
//
// How each library reads clipbench's operands (rings read together under a fill rule) is in
// README.md beside this file; in short, clipper-lib takes all four fill rules natively,
// martinez and polybooljs read the rings as they come under even-odd (their parity rule), and
// polygon-clipping, polyclip-ts and jsts take valid polygons, so each operand's region is built
// first by jsts (operand_region.mjs). `time_ns` covers the library's boolean operation only: not
// JSON, not the conversion of coordinates, not the region building.

import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { createInterface } from 'node:readline';

import { regionOf, jstsFactory, jstsOverlay, polygonalRings, JSTS_VERSION } from './operand_region.mjs';

const require = createRequire(import.meta.url);
const PROTOCOL_VERSION = 1;
const ALL_OPS = ['intersection', 'union', 'difference', 'xor'];
const ALL_FILLS = ['even-odd', 'non-zero', 'positive', 'negative'];

/** The installed version of an npm package (some do not export their package.json). */
function versionOf(name) {
  return JSON.parse(readFileSync(new URL(`./node_modules/${name}/package.json`, import.meta.url), 'utf8')).version;
}

/** Counter-clockwise loops wind +1 (y up): positive shoelace area. */
function signedArea(ring) {
  let a = 0;
  for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
    a += (ring[j][0] - ring[i][0]) * (ring[j][1] + ring[i][1]);
  }
  return a / 2;
}

/** A ring without its closing point, turned to the way asked (outers counter-clockwise). */
function openRing(ring, counterClockwise) {
  const points = ring.slice();
  if (points.length > 1) {
    const [a, b] = [points[0], points[points.length - 1]];
    if (a[0] === b[0] && a[1] === b[1]) points.pop();
  }
  return (signedArea(points) > 0) === counterClockwise ? points : points.reverse();
}

/** Rings of a GeoJSON MultiPolygon's coordinates: each polygon's first ring counter-clockwise, the rest clockwise. */
function ringsOfMultiPolygon(polygons, out) {
  for (const polygon of polygons) {
    polygon.forEach((ring, k) => {
      const open = openRing(ring, k === 0);
      if (open.length >= 3) out.push(open.map(([x, y]) => [x, y]));
    });
  }
  return out;
}

const closed = (ring) => [...ring, ring[0]];

/** The GeoJSON MultiPolygon coordinates of a region built by jsts. */
function multiPolygonOf(region) {
  return polygonalRings(region).map(({ shell, holes }) => [shell, ...holes]);
}

// The libraries. Each has its handshake's name, ops and fill rules, a `prepare` that turns one
// request's operands into the library's input (not timed), `run` (timed) and `rings` (not timed).
const LIBRARIES = {
  martinez: async () => {
    // Its CommonJS build fails at run time (a bundled default import), so the ES module it ships is used.
    const martinez = await import('martinez-polygon-clipping');
    const call = { intersection: martinez.intersection, union: martinez.union, difference: martinez.diff, xor: martinez.xor };
    return {
      name: `martinez-polygon-clipping ${versionOf('martinez-polygon-clipping')} (rings read as given, even-odd)`,
      fills: ['even-odd'],
      // Every ring of an operand in one polygon: martinez flips in/out at each edge of it (parity).
      prepare: (rings) => (rings.length ? [rings.map(closed)] : []),
      run: (op, a, b) => call[op](a, b),
      rings: (result) => ringsOfMultiPolygon(result ? (typeof result[0]?.[0]?.[0] === 'number' ? [result] : result) : [], []),
    };
  },
  'polygon-clipping': () => {
    const pc = require('polygon-clipping');
    return {
      name: `polygon-clipping ${versionOf('polygon-clipping')} (operands as valid polygons built by jsts ${JSTS_VERSION})`,
      fills: ALL_FILLS,
      prepare: (rings, fill) => multiPolygonOf(regionOf(rings, fill)),
      run: (op, a, b) => pc[op](a, b),
      rings: (result) => ringsOfMultiPolygon(result, []),
    };
  },
  'polyclip-ts': () => {
    const pc = require('polyclip-ts');
    return {
      name: `polyclip-ts ${versionOf('polyclip-ts')} (operands as valid polygons built by jsts ${JSTS_VERSION})`,
      fills: ALL_FILLS,
      prepare: (rings, fill) => multiPolygonOf(regionOf(rings, fill)),
      run: (op, a, b) => pc[op](a, b),
      rings: (result) => ringsOfMultiPolygon(result, []),
    };
  },
  polybooljs: () => {
    const PolyBool = require('polybooljs');
    const call = { intersection: PolyBool.intersect, union: PolyBool.union, difference: PolyBool.difference, xor: PolyBool.xor };
    return {
      name: `polybooljs ${versionOf('polybooljs')} (rings read as given, even-odd; default epsilon)`,
      fills: ['even-odd'],
      prepare: (rings) => ({ regions: rings, inverted: false }),
      run: (op, a, b) => call[op].call(PolyBool, a, b),
      // Its regions nest by even-odd; its GeoJSON writer sorts them into outers and holes.
      rings: (result) => {
        const g = PolyBool.polygonToGeoJSON(result);
        return ringsOfMultiPolygon(g.type === 'Polygon' ? [g.coordinates] : g.coordinates, []);
      },
    };
  },
  jsts: () => ({
    name: `jsts ${versionOf('jsts')} (JTS ${JSTS_VERSION} classic overlay, SnapIfNeededOverlayOp; operands as valid polygons built by jsts)`,
    fills: ALL_FILLS,
    prepare: (rings, fill) => regionOf(rings, fill),
    run: (op, a, b) => jstsOverlay(op, a, b),
    rings: (result) => ringsOfMultiPolygon(multiPolygonOf(result), []),
  }),
  'clipper-lib': () => {
    const ClipperLib = require('clipper-lib');
    const clipType = {
      intersection: ClipperLib.ClipType.ctIntersection,
      union: ClipperLib.ClipType.ctUnion,
      difference: ClipperLib.ClipType.ctDifference,
      xor: ClipperLib.ClipType.ctXor,
    };
    const fillType = {
      'even-odd': ClipperLib.PolyFillType.pftEvenOdd,
      'non-zero': ClipperLib.PolyFillType.pftNonZero,
      positive: ClipperLib.PolyFillType.pftPositive,
      negative: ClipperLib.PolyFillType.pftNegative,
    };
    return {
      name: `clipper-lib ${versionOf('clipper-lib')} (Clipper 1 in JavaScript; all four fill rules, on an integer grid of about extent x 2^-30)`,
      fills: ALL_FILLS,
      prepareBoth: (subject, clip) => {
        const grid = IntegerGrid.fitting([...subject, ...clip]);
        const paths = (rings) => rings.map((ring) => ring.map((p) => grid.toGrid(p)));
        return { grid, a: paths(subject), b: paths(clip) };
      },
      run: (op, a, b, fill) => {
        const c = new ClipperLib.Clipper();
        c.AddPaths(a, ClipperLib.PolyType.ptSubject, true);
        c.AddPaths(b, ClipperLib.PolyType.ptClip, true);
        const solution = [];
        c.Execute(clipType[op], solution, fillType[fill], fillType[fill]);
        return solution;
      },
      // Clipper 1 writes outers with positive area and holes negative: counter-clockwise, y up.
      rings: (solution, grid) => solution.map((path) => path.map((q) => grid.toPoint(q))).filter((r) => r.length >= 3),
    };
  },
};

/** A power-of-two integer grid centred on the inputs' box, their extent just under 2^30 steps (as crates/clipper2-rect's IntegerGrid). */
class IntegerGrid {
  static BITS = 30;

  static fitting(rings) {
    let [minX, minY, maxX, maxY] = [Infinity, Infinity, -Infinity, -Infinity];
    for (const ring of rings) {
      for (const [x, y] of ring) {
        minX = Math.min(minX, x);
        maxX = Math.max(maxX, x);
        minY = Math.min(minY, y);
        maxY = Math.max(maxY, y);
      }
    }
    if (minX > maxX) return new IntegerGrid(0, 0, 1);
    const [ox, oy] = [minX + (maxX - minX) / 2, minY + (maxY - minY) / 2];
    const extent = Math.max(Math.abs(minX - ox), Math.abs(maxX - ox), Math.abs(minY - oy), Math.abs(maxY - oy));
    if (extent === 0) return new IntegerGrid(ox, oy, 1);
    let scale = 2 ** (IntegerGrid.BITS - 1 - Math.ceil(Math.log2(extent)));
    while (extent * scale >= 2 ** IntegerGrid.BITS) scale /= 2;
    if (!Number.isFinite(scale)) scale = 2 ** 1023;
    return new IntegerGrid(ox, oy, scale);
  }

  constructor(ox, oy, scale) {
    Object.assign(this, { ox, oy, scale });
  }

  toGrid([x, y]) {
    return { X: Math.round((x - this.ox) * this.scale), Y: Math.round((y - this.oy) * this.scale) };
  }

  toPoint({ X, Y }) {
    return [X / this.scale + this.ox, Y / this.scale + this.oy];
  }
}

function handshake(library) {
  return {
    protocol: PROTOCOL_VERSION,
    name: library.name,
    polygon: { ops: ALL_OPS, fill_rules: library.fills, window: 'any', output: 'conventional' },
  };
}

/** One request answered: the rings and the library's own time, or the error it raised. */
function answer(library, request) {
  const { op, fill, subject, clip } = request;
  if (!ALL_OPS.includes(op)) throw new Error(`unknown operation '${op}'`);
  if (!library.fills.includes(fill)) throw new Error(`fill rule '${fill}' is not supported (${library.fills.join(', ')})`);
  let a, b, grid;
  if (library.prepareBoth) {
    ({ a, b, grid } = library.prepareBoth(subject, clip));
  } else {
    // A failure here is the reader's (jsts building a region), not the library's: say so.
    try {
      a = library.prepare(subject, fill);
      b = library.prepare(clip, fill);
    } catch (e) {
      throw new Error(`reading the operands failed, before ${library.name.split(' ')[0]} ran: ${e?.name ?? 'Error'}: ${e?.message ?? e}`);
    }
  }
  const start = process.hrtime.bigint();
  const result = library.run(op, a, b, fill);
  const timeNs = Number(process.hrtime.bigint() - start);
  return { rings: library.rings(result, grid), time_ns: timeNs };
}

async function main() {
  const which = process.argv[2];
  const make = LIBRARIES[which];
  if (!make) {
    process.stderr.write(`usage: clipbench_node.mjs ${Object.keys(LIBRARIES).join('|')}\n`);
    process.exit(2);
  }
  jstsFactory(); // loads jsts now, so the first request is not slowed by it
  const library = await make();
  // The harness closing its end early is the end of the run, not an error.
  process.stdout.on('error', () => process.exit(0));
  process.stdout.write(JSON.stringify(handshake(library)) + '\n');
  const input = createInterface({ input: process.stdin, crlfDelay: Infinity });
  input.on('line', (line) => {
    if (!line.trim()) return;
    const request = JSON.parse(line);
    let reply;
    try {
      reply = { id: request.id, ...answer(library, request) };
    } catch (e) {
      // A library's exception becomes an error reply: the harness counts it as that case's failure.
      reply = { id: request.id, error: `${e?.name ?? 'Error'}: ${e?.message ?? e}` };
    }
    // JSON.stringify writes numbers shortest-round-trip, so coordinates cross exactly.
    process.stdout.write(JSON.stringify(reply) + '\n');
  });
}

main();
