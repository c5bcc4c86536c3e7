#!/usr/bin/env python3
"""shapely 2 (GEOS) as a clipbench external clipper, protocol version 1 (docs/PROTOCOL.md).

Reads one JSON request per line on stdin, writes one JSON reply per line on stdout. GEOS takes
only valid polygons, so each operand's region under the requested fill rule is built first:
the rings' lines are noded together (shapely.union_all), polygonized into faces, and a face is
kept when the fill rule accepts the winding number of the input rings around a point inside it
(shapely.point_on_surface; counter-clockwise loops count +1). The kept faces, unioned, are a
valid polygon; GEOS then runs the boolean operation on the two regions. Output polygons are
oriented with outers counter-clockwise and holes clockwise, as clipbench expects.

Install: pip install shapely   (shapely 2 brings numpy and its own GEOS)
Use:     clipbench verify --external shapely='python3 adapters/shapely/clipbench_shapely.py'
"""

import json
import sys
import time

import numpy as np
import shapely
from shapely.geometry.polygon import orient

PROTOCOL_VERSION = 1
# Points classified against all edges at once, in blocks of this many (bounds the memory).
POINT_BLOCK = 256


def winding_numbers(rings, xs, ys):
    """Winding number of the rings around each point (xs[i], ys[i]): the crossing rule."""
    edges = []
    for ring in rings:
        r = np.asarray(ring, dtype=float)
        edges.append(np.hstack([r, np.roll(r, -1, axis=0)]))
    e = np.vstack(edges)
    ax, ay, bx, by = e[:, 0], e[:, 1], e[:, 2], e[:, 3]
    result = np.zeros(len(xs), dtype=np.int64)
    for start in range(0, len(xs), POINT_BLOCK):
        px = xs[start : start + POINT_BLOCK, None]
        py = ys[start : start + POINT_BLOCK, None]
        cross = (bx - ax) * (py - ay) - (px - ax) * (by - ay)
        up = (ay <= py) & (by > py) & (cross > 0)
        down = (ay > py) & (by <= py) & (cross < 0)
        result[start : start + POINT_BLOCK] = up.sum(axis=1) - down.sum(axis=1)
    return result


def inside(w, fill):
    if fill == "even-odd":
        return (w % 2) != 0
    if fill == "non-zero":
        return w != 0
    if fill == "positive":
        return w > 0
    if fill == "negative":
        return w < 0
    raise ValueError(f"unknown fill rule {fill!r}")


def region(rings, fill):
    """The region the rings cover under the fill rule, as a valid (multi)polygon."""
    if not rings:
        return shapely.Polygon()
    lines = shapely.MultiLineString([ring + [ring[0]] for ring in rings])
    noded = shapely.union_all(lines)
    faces = shapely.get_parts(shapely.polygonize(shapely.get_parts(noded)))
    if len(faces) == 0:
        return shapely.Polygon()
    points = shapely.point_on_surface(faces)
    w = winding_numbers(rings, shapely.get_x(points), shapely.get_y(points))
    kept = faces[inside(w, fill)]
    return shapely.union_all(kept) if len(kept) else shapely.Polygon()


OPS = {
    "intersection": shapely.intersection,
    "union": shapely.union,
    "difference": shapely.difference,
    "xor": shapely.symmetric_difference,
}


def rings_of(geometry, out):
    """Every polygon ring of a result, outers counter-clockwise, holes clockwise; the rest dropped."""
    if geometry.is_empty:
        return
    if geometry.geom_type == "Polygon":
        p = orient(geometry, sign=1.0)
        for ring in [p.exterior, *p.interiors]:
            coords = [[x, y] for x, y in ring.coords[:-1]]
            if len(coords) >= 3:
                out.append(coords)
    elif geometry.geom_type in ("MultiPolygon", "GeometryCollection"):
        for part in geometry.geoms:
            rings_of(part, out)


def clip(request):
    fill = request["fill"]
    a, b = region(request["subject"], fill), region(request["clip"], fill)
    out = []
    rings_of(OPS[request["op"]](a, b), out)
    return out


def main():
    handshake = {
        "protocol": PROTOCOL_VERSION,
        "name": f"shapely {shapely.__version__} (GEOS {shapely.geos_version_string})",
        "polygon": {
            "ops": list(OPS),
            "fill_rules": ["even-odd", "non-zero", "positive", "negative"],
            "window": "any",
            "output": "conventional",
        },
    }
    print(json.dumps(handshake), flush=True)
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        reply = {"id": request["id"]}
        try:
            start = time.perf_counter_ns()
            reply["rings"] = clip(request)
            reply["time_ns"] = time.perf_counter_ns() - start
        except Exception as e:  # GEOS errors become error replies: the harness counts them as failures
            reply["error"] = f"{type(e).__name__}: {e}"
        # Python writes floats shortest-round-trip, so coordinates cross exactly.
        sys.stdout.write(json.dumps(reply) + "\n")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
