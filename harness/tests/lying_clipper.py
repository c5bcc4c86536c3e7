#!/usr/bin/env python3
"""A lying external clipper for harness/tests/bench.rs (protocol version 1): it answers every
polygon request at once, without looking at it, with a fixed 1000 x 1000 square (`square`) or
with no rings at all (`empty`). Fast and wrong: the bench must mark it wrong and not rank it.

Usage: lying_clipper.py square|empty
"""

import json
import sys

SQUARE = [[[0.0, 0.0], [1000.0, 0.0], [1000.0, 1000.0], [0.0, 1000.0]]]


def main():
    mode = sys.argv[1]
    if mode not in ("square", "empty"):
        sys.exit(f"lying_clipper.py: unknown mode {mode!r}")
    rings = SQUARE if mode == "square" else []
    print(
        json.dumps(
            {
                "protocol": 1,
                "name": f"lying test clipper ({mode})",
                "polygon": {
                    "ops": ["intersection", "union", "difference", "xor"],
                    "fill_rules": ["even-odd", "non-zero"],
                    "window": "any",
                    "output": "conventional",
                },
            }
        ),
        flush=True,
    )
    for line in sys.stdin:
        request = json.loads(line)
        print(json.dumps({"id": request["id"], "rings": rings}), flush=True)


if __name__ == "__main__":
    main()
