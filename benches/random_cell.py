#!/usr/bin/env python3
"""A random cell of N points for the scaling table of benches/README.md (points 5, 20, 80).

The cell: the IRB 1400 at the origin, a floor, four pillars around the robot and a table in
front (the bench cells' kinds); N joint points drawn with a fixed seed (the same cell for the
same N) in ranges where the arm works above the table, each kept only when gen-rapid accepts it
(a point inside a box or out of reach is dropped and another drawn), so the cell plans.

    python3 benches/random_cell.py --points 20 > benches/random/random-20.yaml
"""

import argparse
import os
import random
import subprocess
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

HEAD = """# Random bench cell (benches/random_cell.py, seed {seed}, {n} points).
module: BenchRandom
robot:
  urdf: {urdf}
  base: [0, 0, 0]
obstacles:
  - {{ name: floor, box: {{ min: [-2000, -2000, -50], max: [2000, 2000, 0] }} }}
  - {{ name: p1, box: {{ min: [900, -700, 0], max: [1100, -500, 1500] }} }}
  - {{ name: p2, box: {{ min: [900, 500, 0], max: [1100, 700, 1500] }} }}
  - {{ name: p3, box: {{ min: [-700, 900, 0], max: [-500, 1100, 1500] }} }}
  - {{ name: p4, box: {{ min: [-700, -1100, 0], max: [-500, -900, 1500] }} }}
  - {{ name: table, box: {{ min: [600, -350, 0], max: [1200, 350, 550] }} }}
points:
"""

TAIL = "planner: { method: extensile, grid: 1.0, clearance: 10 }\n"


def cell_text(seed, points, urdf):
    lines = [HEAD.format(seed=seed, n=len(points), urdf=urdf)]
    for i, j in enumerate(points):
        axes = ", ".join(f"{v:.1f}" for v in j)
        lines.append(f"  - {{ name: P{i + 1}, joints: [{axes}] }}\n")
    return "".join(lines) + TAIL


def plans(binary, text):
    """gen-rapid's exit status and stderr on the cell `text` (written in benches/random, where
    the random cells are kept, so the URDF path resolves)."""
    folder = ROOT / "benches" / "random"
    folder.mkdir(exist_ok=True)
    with tempfile.NamedTemporaryFile("w", suffix=".yaml", dir=folder, delete=False) as f:
        f.write(text)
        path = f.name
    try:
        r = subprocess.run([binary, path, "-q", "-o", os.devnull], capture_output=True, text=True)
        return r.returncode, r.stderr
    finally:
        os.unlink(path)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--binary", default=str(ROOT / "target/release/gen-rapid"))
    ap.add_argument("--points", type=int, default=20)
    ap.add_argument("--seed", type=int, default=31)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    draw = lambda: [rng.uniform(-150, 150), rng.uniform(-20, 50), rng.uniform(-40, 40),
                    rng.uniform(-90, 90), rng.uniform(10, 90), rng.uniform(-90, 90)]
    urdf = "../../robots/irb1400.urdf"
    points = []
    while len(points) < args.points:
        p = draw()
        # Kept when the cell up to it plans (the new point usable and reachable from the last).
        tail = points[-1:] + [p] if points else [p, p]
        rc, _ = plans(args.binary, cell_text(args.seed, tail, urdf))
        if rc == 0:
            points.append(p)
    print(cell_text(args.seed, points, urdf), end="")


if __name__ == "__main__":
    main()
