#!/usr/bin/env python3
"""A deliberately broken external clipper for harness/tests/cli.rs (protocol version 1).

It clips polygons against rectangle windows correctly (Sutherland-Hodgman, each subject ring on
its own, so its output is declared "bridged"), and segments against rectangle windows
(Liang-Barsky, boundary included), except on some requests, counted across all its restarts in
a state file: on the CRASH-th it exits, on the HANG-th it never answers, on the GARBAGE-th it
writes a line that is not JSON, on the WRONG_ID-th it answers with another request's id, on the
BAD_TIME-th it answers right but reports its own time as -5 ns, and from the LIE-th on it answers every polygon
request with the subject unclipped (with LIE it declares all four operations, so that its area
identities are checked too). 0 (or leaving the last ones out) turns a fault off.

Usage: broken_clipper.py STATE_FILE CRASH HANG GARBAGE WRONG_ID [BAD_TIME [LIE]]
"""

import fcntl
import json
import sys
import time


def next_request_number(state):
    # Workers share the counter: hold a lock across read and write, or two of them can read
    # the file while the other has just truncated it.
    with open(state, "a+") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        f.seek(0)
        text = f.read()
        n = int(text) + 1 if text else 1
        f.seek(0)
        f.truncate()
        f.write(str(n))
        return n


def clip_ring(ring, xmin, ymin, xmax, ymax):
    """One ring against the four sides of the rectangle, in turn."""
    sides = [
        (lambda p: p[0] >= xmin, lambda p, q: [xmin, p[1] + (q[1] - p[1]) * (xmin - p[0]) / (q[0] - p[0])]),
        (lambda p: p[0] <= xmax, lambda p, q: [xmax, p[1] + (q[1] - p[1]) * (xmax - p[0]) / (q[0] - p[0])]),
        (lambda p: p[1] >= ymin, lambda p, q: [p[0] + (q[0] - p[0]) * (ymin - p[1]) / (q[1] - p[1]), ymin]),
        (lambda p: p[1] <= ymax, lambda p, q: [p[0] + (q[0] - p[0]) * (ymax - p[1]) / (q[1] - p[1]), ymax]),
    ]
    for keep, cut in sides:
        out = []
        for i, q in enumerate(ring):
            p = ring[i - 1]
            if keep(q):
                if not keep(p):
                    out.append(cut(p, q))
                out.append(q)
            elif keep(p):
                out.append(cut(p, q))
        ring = out
        if not ring:
            break
    return ring


def clip(request):
    window = request["clip"][0]
    xs, ys = [p[0] for p in window], [p[1] for p in window]
    area = sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(window, window[1:] + window[:1]))
    # Under positive (negative) fill a clockwise (counter-clockwise) window covers nothing.
    if (request["fill"] == "positive" and area < 0) or (request["fill"] == "negative" and area > 0):
        return []
    rings = [clip_ring(r, min(xs), min(ys), max(xs), max(ys)) for r in request["subject"]]
    return [r for r in rings if len(r) >= 3]


def clip_segment(a, b, xmin, ymin, xmax, ymax):
    """The closed part of segment a-b inside the rectangle, as [from, to], or None."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    if dx == 0 and dy == 0:
        return None
    t0, t1 = 0.0, 1.0
    for p, q in [(-dx, a[0] - xmin), (dx, xmax - a[0]), (-dy, a[1] - ymin), (dy, ymax - a[1])]:
        if p == 0:
            if q < 0:
                return None
        elif p < 0:
            t0 = max(t0, q / p)
        else:
            t1 = min(t1, q / p)
    if t0 >= t1:
        return None
    point = lambda t: a if t == 0 else b if t == 1 else [a[0] + t * dx, a[1] + t * dy]
    return [point(t0), point(t1)]


def clip_lines(request):
    window = request["window"][0]
    xs, ys = [p[0] for p in window], [p[1] for p in window]
    pieces = []
    for i, (a, b) in enumerate(request["segments"]):
        piece = clip_segment(a, b, min(xs), min(ys), max(xs), max(ys))
        if piece:
            pieces.append({"segment": i, "from": piece[0], "to": piece[1]})
    return pieces


def main():
    state, crash, hang, garbage, wrong_id = sys.argv[1], *map(int, sys.argv[2:6])
    bad_time, lie = (list(map(int, sys.argv[6:8])) + [0, 0])[:2]
    ops = ["intersection", "union", "difference", "xor"] if lie else ["intersection"]
    print(
        json.dumps(
            {
                "protocol": 1,
                "name": "broken test clipper",
                "polygon": {
                    "ops": ops,
                    "fill_rules": ["even-odd", "non-zero", "positive", "negative"],
                    "window": "rectangle",
                    "output": "bridged",
                },
                "line": {"window": "rectangle"},
            }
        ),
        flush=True,
    )
    for line in sys.stdin:
        request = json.loads(line)
        n = next_request_number(state)
        if n == crash:
            print("broken test clipper: crashing on purpose", file=sys.stderr, flush=True)
            sys.exit(3)
        if n == hang:
            time.sleep(3600)
        if n == garbage:
            print("this is not a reply", flush=True)
            continue
        if n == wrong_id:
            print(json.dumps({"id": request["id"] + 1000, "rings": []}), flush=True)
            continue
        if n == bad_time:
            # A right answer: only its time is impossible.
            key, result = ("pieces", clip_lines(request)) if "segments" in request else ("rings", clip(request))
            print(json.dumps({"id": request["id"], key: result, "time_ns": -5}), flush=True)
            continue
        if lie and n >= lie and "subject" in request:
            print(json.dumps({"id": request["id"], "rings": request["subject"]}), flush=True)
            continue
        if "segments" in request:
            print(json.dumps({"id": request["id"], "pieces": clip_lines(request)}), flush=True)
        else:
            print(json.dumps({"id": request["id"], "rings": clip(request)}), flush=True)


if __name__ == "__main__":
    main()
