#!/usr/bin/env python3
"""Clipper 1 (pyclipper) and Clipper2 (pyclipr) as clipbench external clippers, protocol version 1
(docs/PROTOCOL.md).

    python3 adapters/python/clipbench_clipper.py pyclipper|pyclipr

Both libraries take clipbench's operands as they are: any rings, read together under any of the
four fill rules. Both work on integers, so each request's coordinates go onto one integer grid:
the inputs' bounding-box centre at 0 and a power-of-two scale that maps their extent to just under
2^30 steps, as the in-process Clipper peers do (crates/clipper2-rect's IntegerGrid); the output
is moved back. Outers come out counter-clockwise and holes clockwise (positive area for outers,
y up), which is clipbench's convention. `time_ns` covers the library's clip call only.

Install: pip install pyclipper pyclipr
"""

import json
import math
import sys
import time
from importlib.metadata import version

PROTOCOL_VERSION = 1
OPS = ["intersection", "union", "difference", "xor"]
FILLS = ["even-odd", "non-zero", "positive", "negative"]
GRID_BITS = 30


class IntegerGrid:
    """A power-of-two grid centred on the inputs' box; their extent is just under 2^GRID_BITS steps."""

    def __init__(self, rings):
        xs = [x for ring in rings for x, _ in ring]
        ys = [y for ring in rings for _, y in ring]
        if not xs:
            self.ox, self.oy, self.scale = 0.0, 0.0, 1.0
            return
        self.ox = min(xs) + (max(xs) - min(xs)) / 2
        self.oy = min(ys) + (max(ys) - min(ys)) / 2
        extent = max(abs(min(xs) - self.ox), abs(max(xs) - self.ox), abs(min(ys) - self.oy), abs(max(ys) - self.oy))
        if extent == 0:
            self.scale = 1.0
            return
        exponent = GRID_BITS - 1 - math.ceil(math.log2(extent))
        self.scale = math.ldexp(1.0, min(exponent, 1023))
        while extent * self.scale >= 2.0**GRID_BITS:
            self.scale /= 2

    def to_grid(self, ring):
        return [(round((x - self.ox) * self.scale), round((y - self.oy) * self.scale)) for x, y in ring]

    def to_point(self, path):
        return [[float(x) / self.scale + self.ox, float(y) / self.scale + self.oy] for x, y in path]


def pyclipper_library():
    import pyclipper

    ops = {
        "intersection": pyclipper.CT_INTERSECTION,
        "union": pyclipper.CT_UNION,
        "difference": pyclipper.CT_DIFFERENCE,
        "xor": pyclipper.CT_XOR,
    }
    fills = {
        "even-odd": pyclipper.PFT_EVENODD,
        "non-zero": pyclipper.PFT_NONZERO,
        "positive": pyclipper.PFT_POSITIVE,
        "negative": pyclipper.PFT_NEGATIVE,
    }

    def run(op, fill, subject, clip):
        c = pyclipper.Pyclipper()
        # pyclipper refuses an empty list of paths; an empty operand is simply not added.
        if subject:
            c.AddPaths(subject, pyclipper.PT_SUBJECT, True)
        if clip:
            c.AddPaths(clip, pyclipper.PT_CLIP, True)
        return c.Execute(ops[op], fills[fill], fills[fill])

    name = f"pyclipper {version('pyclipper')} (Clipper 1 6.4.2; all four fill rules, on an integer grid of about extent x 2^-30)"
    return name, run


def pyclipr_library():
    import numpy as np
    import pyclipr

    ops = {
        "intersection": pyclipr.Intersection,
        "union": pyclipr.Union,
        "difference": pyclipr.Difference,
        "xor": pyclipr.Xor,
    }
    fills = {
        "even-odd": pyclipr.FillRule.EvenOdd,
        "non-zero": pyclipr.FillRule.NonZero,
        "positive": pyclipr.FillRule.Positive,
        "negative": pyclipr.FillRule.Negative,
    }

    def run(op, fill, subject, clip):
        c = pyclipr.Clipper()
        c.scaleFactor = 1  # the coordinates are on the grid already
        if subject:
            c.addPaths([np.asarray(r, dtype=np.float64) for r in subject], pyclipr.Subject)
        if clip:
            c.addPaths([np.asarray(r, dtype=np.float64) for r in clip], pyclipr.Clip)
        return c.execute(ops[op], fills[fill])

    name = f"pyclipr {version('pyclipr')} (Clipper2 {pyclipr.clipperVersion}; all four fill rules, on an integer grid of about extent x 2^-30)"
    return name, run


LIBRARIES = {"pyclipper": pyclipper_library, "pyclipr": pyclipr_library}


def answer(run, request):
    op, fill = request["op"], request["fill"]
    if op not in OPS or fill not in FILLS:
        raise ValueError(f"unknown operation or fill rule: {op!r}, {fill!r}")
    grid = IntegerGrid(request["subject"] + request["clip"])
    subject = [grid.to_grid(r) for r in request["subject"]]
    clip = [grid.to_grid(r) for r in request["clip"]]
    start = time.perf_counter_ns()
    paths = run(op, fill, subject, clip)
    elapsed = time.perf_counter_ns() - start
    rings = [grid.to_point(path) for path in paths if len(path) >= 3]
    return {"rings": rings, "time_ns": elapsed}


def main():
    if len(sys.argv) != 2 or sys.argv[1] not in LIBRARIES:
        sys.exit(f"usage: clipbench_clipper.py {'|'.join(LIBRARIES)}")
    name, run = LIBRARIES[sys.argv[1]]()
    handshake = {
        "protocol": PROTOCOL_VERSION,
        "name": name,
        "polygon": {"ops": OPS, "fill_rules": FILLS, "window": "any", "output": "conventional"},
    }
    print(json.dumps(handshake), flush=True)
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        reply = {"id": request["id"]}
        try:
            reply.update(answer(run, request))
        except Exception as e:  # the library's errors become error replies: the harness counts them
            reply["error"] = f"{type(e).__name__}: {e}"
        # Python writes floats shortest-round-trip, so coordinates cross exactly.
        sys.stdout.write(json.dumps(reply) + "\n")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
