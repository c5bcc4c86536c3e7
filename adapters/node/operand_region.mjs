// An operand's region under a fill rule, as a valid jsts (Multi)Polygon, for the libraries that
// take valid polygons only (polygon-clipping, polyclip-ts, jsts). The same construction as the
// shapely adapter (adapters/shapely/README.md), with jsts doing the geometry:
//   1. the rings' lines are noded together (a unary union of the line work);
//   2. the noded lines are polygonized into faces;
//   3. a face is kept when the fill rule accepts the winding number of the input rings around a
//      point inside it (counter-clockwise loops count +1; the crossing rule in floating point);
//   4. the kept faces, unioned, are a valid polygon.

import 'jsts/org/locationtech/jts/monkey.js';
import GeometryFactory from 'jsts/org/locationtech/jts/geom/GeometryFactory.js';
import Coordinate from 'jsts/org/locationtech/jts/geom/Coordinate.js';
import UnaryUnionOp from 'jsts/org/locationtech/jts/operation/union/UnaryUnionOp.js';
import Polygonizer from 'jsts/org/locationtech/jts/operation/polygonize/Polygonizer.js';
import InteriorPointArea from 'jsts/org/locationtech/jts/algorithm/InteriorPointArea.js';
import JTSVersion from 'jsts/org/locationtech/jts/JTSVersion.js';

export const JSTS_VERSION = `${JTSVersion.MAJOR}.${JTSVersion.MINOR}.${JTSVersion.PATCH}`;

let factory = null;

/** The one geometry factory (floating precision). */
export function jstsFactory() {
  factory ??= new GeometryFactory();
  return factory;
}

const coordinates = (ring) => [...ring, ring[0]].map(([x, y]) => new Coordinate(x, y));

/** Winding number of the rings around (px, py): the crossing rule, counter-clockwise +1. */
function windingNumber(rings, px, py) {
  let w = 0;
  for (const ring of rings) {
    for (let i = 0, j = ring.length - 1; i < ring.length; j = i++) {
      const [ax, ay] = ring[j];
      const [bx, by] = ring[i];
      const cross = (bx - ax) * (py - ay) - (px - ax) * (by - ay);
      if (ay <= py && by > py && cross > 0) w += 1;
      else if (ay > py && by <= py && cross < 0) w -= 1;
    }
  }
  return w;
}

const INSIDE = {
  'even-odd': (w) => w % 2 !== 0,
  'non-zero': (w) => w !== 0,
  positive: (w) => w > 0,
  negative: (w) => w < 0,
};

/** The region `rings` cover under `fill`, as a valid jsts polygonal geometry (empty when none). */
export function regionOf(rings, fill) {
  const f = jstsFactory();
  const inside = INSIDE[fill];
  if (!inside) throw new Error(`unknown fill rule '${fill}'`);
  if (rings.length === 0) return f.createPolygon();
  const lines = f.createMultiLineString(rings.map((r) => f.createLineString(coordinates(r))));
  const noded = UnaryUnionOp.union(lines);
  const polygonizer = new Polygonizer();
  polygonizer.add(noded);
  const kept = [];
  for (const face of polygonizer.getPolygons().toArray()) {
    const p = InteriorPointArea.getInteriorPoint(face);
    if (p !== null && inside(windingNumber(rings, p.x, p.y))) kept.push(face);
  }
  if (kept.length === 0) return f.createPolygon();
  return UnaryUnionOp.union(f.createMultiPolygon(kept));
}

/** jsts's boolean operation, as a user calls it (Geometry methods: JTS's classic overlay with its snapping fallback). */
export function jstsOverlay(op, a, b) {
  switch (op) {
    case 'intersection':
      return a.intersection(b);
    case 'union':
      return a.union(b);
    case 'difference':
      return a.difference(b);
    case 'xor':
      return a.symDifference(b);
    default:
      throw new Error(`unknown operation '${op}'`);
  }
}

const ringPoints = (ring) => ring.getCoordinates().slice(0, -1).map((c) => [c.x, c.y]);

/** The polygons of a jsts result as shells and holes (points without the closing one); points and lines dropped. */
export function polygonalRings(geometry) {
  const out = [];
  const visit = (g) => {
    if (g.isEmpty()) return;
    const type = g.getGeometryType();
    if (type === 'Polygon') {
      const shell = g.getExteriorRing();
      const holes = [];
      for (let i = 0; i < g.getNumInteriorRing(); i++) holes.push(ringPoints(g.getInteriorRingN(i)));
      out.push({ shell: ringPoints(shell), holes });
    } else if (type === 'MultiPolygon' || type === 'GeometryCollection') {
      for (let i = 0; i < g.getNumGeometries(); i++) visit(g.getGeometryN(i));
    }
  };
  visit(geometry);
  return out;
}
