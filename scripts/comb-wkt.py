#!/usr/bin/env python3
"""Two combs and a small box as WKT, for timing `clipbench clip` on a comb (issue 32).

Each comb is one ring: a spine below y = 0 and TEETH teeth 2 wide and 4 apart rising to random
integer heights from half to all of the comb's length (4 vertices a tooth). The second comb is
the first shifted by 2, so its teeth stand in the first one's gaps, touching them; the box covers
a hundredth of the first comb's area over its teeth.

    scripts/comb-wkt.py [TEETH] [FOLDER]     (default 12500 teeth: 5*10^4 vertices a comb)
    clipbench clip --clipper vatti --op union FOLDER/comb-a.wkt FOLDER/comb-b.wkt -o out.wkt
"""
import os
import random
import sys


def comb(teeth, shift, rng):
    pts = [(shift, -2), (shift + 4 * teeth, -2), (shift + 4 * teeth, 0)]
    for i in reversed(range(teeth)):
        x = shift + 4 * i
        h = rng.randint(2 * teeth, 4 * teeth)
        pts += [(x + 2, 0), (x + 2, h), (x, h), (x, 0)]
    pts.append(pts[0])
    return "POLYGON((" + ", ".join(f"{x} {y}" for x, y in pts) + "))\n"


def main():
    teeth = int(sys.argv[1]) if len(sys.argv) > 1 else 12500
    folder = sys.argv[2] if len(sys.argv) > 2 else "."
    os.makedirs(folder, exist_ok=True)
    rng = random.Random(7)
    w = 4 * teeth
    files = {
        "comb-a.wkt": comb(teeth, 0, rng),
        "comb-b.wkt": comb(teeth, 2, rng),
        "comb-box.wkt": f"POLYGON(({w * 0.45} {w * 0.2}, {w * 0.55} {w * 0.2}, {w * 0.55} {w * 0.3}, "
        f"{w * 0.45} {w * 0.3}, {w * 0.45} {w * 0.2}))\n",
    }
    for name, text in files.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
