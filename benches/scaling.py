#!/usr/bin/env python3
"""How the cost of a run grows: the two scaling tables of benches/README.md.

Against the grid step: `cells/trunk.yaml --grid D` for D = 2, 1, 0.5, 0.25 deg. Against the
number of points: `benches/random/random-N.yaml` (made by benches/random_cell.py) for N = 5,
20, 80 at the cell's 1 deg. Each case is the whole process (`BINARY CELL -q -o /dev/null`),
run --runs times: the median wall clock, the median CPU time (user + system of the process and
its threads) and the largest peak resident set size (through GNU time, `/usr/bin/time`).

    python3 benches/scaling.py --binary target/release/gen-rapid

Prints two Markdown tables and the machine's load before and after. Wall clock on a shared
machine is noisy: take the figures when the load is low.
"""

import argparse
import os
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
TIME = "/usr/bin/time"


def one_run(binary, args):
    """(wall s, CPU s, peak RSS KiB) of one whole process.

    The CPU time is wait4's for GNU time and what it waited for (the run; GNU time's own share is
    a fraction of a millisecond); the peak is GNU time's (`/usr/bin/time`): a child forked from
    Python itself would report Python's own resident set as its peak (Linux keeps the high-water
    mark across exec).
    """
    with tempfile.NamedTemporaryFile("r") as out:
        start = time.perf_counter()
        proc = subprocess.Popen(
            [TIME, "-f", "%M", "-o", out.name, binary, *args, "-q", "-o", os.devnull],
            stdout=subprocess.DEVNULL,
        )
        _, status, usage = os.wait4(proc.pid, 0)
        wall = time.perf_counter() - start
        proc.returncode = os.waitstatus_to_exitcode(status)
        if proc.returncode != 0:
            raise SystemExit(f"{' '.join(args)}: exit status {proc.returncode}")
        peak = int(out.read().split()[-1])
    return wall, usage.ru_utime + usage.ru_stime, peak


def measure(binary, args, runs):
    """Median wall, median CPU, largest peak over `runs` runs."""
    results = [one_run(binary, args) for _ in range(runs)]
    return (
        statistics.median(r[0] for r in results),
        statistics.median(r[1] for r in results),
        max(r[2] for r in results),
    )


def seconds(s):
    return f"{s * 1e3:.1f} ms" if s < 1.0 else f"{s:.2f} s"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--binary", default=str(ROOT / "target/release/gen-rapid"))
    ap.add_argument("--runs", type=int, default=5)
    a = ap.parse_args()
    binary = str(Path(a.binary).resolve())
    os.chdir(ROOT)
    print(f"load before: {os.getloadavg()[0]:.2f}\n")

    print("| grid | wall | CPU | peak |\n|---|---|---|---|")
    for grid in ["2", "1", "0.5", "0.25"]:
        runs = a.runs if grid != "0.25" else max(1, min(a.runs, 3))
        wall, cpu, peak = measure(binary, ["cells/trunk.yaml", "--grid", grid], runs)
        print(f"| {grid} deg | {seconds(wall)} | {seconds(cpu)} | {peak / 1024:.1f} MB |")

    print("\n| points | wall | CPU | peak |\n|---|---|---|---|")
    for n in [5, 20, 80]:
        wall, cpu, peak = measure(binary, [f"benches/random/random-{n}.yaml"], a.runs)
        print(f"| {n} | {seconds(wall)} | {seconds(cpu)} | {peak / 1024:.1f} MB |")

    print(f"\nload after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
