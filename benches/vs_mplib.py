#!/usr/bin/env python3
"""gen-rapid end to end against a sampling planner's plan-only time, cell by cell.

For every cell of benches/cells (or the cells named), in the same minutes:

- gen-rapid: the whole process (`BINARY CELL -q -o /dev/null`), wall clock around the process,
  the median of --runs;
- mplib (PyPI `mplib`, 0.2.x), RRTConnect through `Planner.plan_qpos` leg by leg from the
  first point to the last, the legs' times summed; its setup (the robot, its self-collision
  pairs, the boxes) not counted; the median of --peer-runs. The same robot (the project's
  URDF, a copy in a temporary folder, where mplib writes its SRDF), the same base pose, the
  boxes grown by the cell's clearance on every side (mplib plans to contact), the tool's
  shapes attached to tool0, the points' six axes as gen-rapid placed them (its --report),
  turned into URDF joints (axis 3 of the IRB 1400's controller is URDF joint 3 + joint 2).

Prints a Markdown table (cell, mplib ms, gen-rapid ms, the ratio) and the machine's load.
mplib samples at random: its times vary from run to run (a leg it fails within its planning
time is marked). Wall clock on a shared machine is noisy: take the figures when the load is low.

    pip install mplib pyyaml
    python3 benches/vs_mplib.py --binary target/release/gen-rapid [CELL ...]

Where mplib cannot be installed, `--recorded benches/mplib-recorded.json` takes the peer's
times from a table recorded by `--record FILE` on a machine that has it (its date, machine and
mplib version are in the file; the ratio then compares minutes that were not the same).
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def gen_rapid_ms(binary, cell, runs):
    """Median wall time of the whole process, ms."""
    times = []
    for _ in range(runs):
        t = time.perf_counter()
        subprocess.run([binary, str(cell), "-q", "-o", os.devnull], check=True)
        times.append((time.perf_counter() - t) * 1e3)
    return statistics.median(times)


def placed_points(binary, cell):
    """The cell points' six axes (controller values, deg) as gen-rapid placed them."""
    with tempfile.TemporaryDirectory() as d:
        report = Path(d) / "r.json"
        subprocess.run(
            [binary, str(cell), "-q", "-o", os.devnull, "--report", str(report)],
            check=True,
        )
        r = json.loads(report.read_text())
    return [w["joints_deg"] for w in r["waypoints"] if w["kind"] == "cell"]


def urdf_joints(axes_deg, parallelogram):
    """Controller values (deg) -> URDF joint angles (rad)."""
    q = list(axes_deg)
    if parallelogram:
        q[2] = axes_deg[2] - axes_deg[1]
    return [math.radians(v) for v in q]


def yaw_quat(yaw_deg):
    h = math.radians(yaw_deg) / 2
    return [math.cos(h), 0.0, 0.0, math.sin(h)]


def quat_z_to(v):
    """A unit quaternion [w, x, y, z] turning +z onto the direction v."""
    n = math.sqrt(sum(c * c for c in v))
    x, y, z = (c / n for c in v)
    if z < -1 + 1e-12:
        return [0.0, 1.0, 0.0, 0.0]
    # Half-way vector between +z and v.
    w, ax, ay, az = 1 + z, -y, x, 0.0
    m = math.sqrt(w * w + ax * ax + ay * ay + az * az)
    return [w / m, ax / m, ay / m, az / m]


class Peer:
    """mplib's planner on one cell (setup here, not timed)."""

    def __init__(self, cell_path, urdf_copy):
        import mplib
        from mplib.collision_detection import fcl

        cell = __import__("yaml").safe_load(Path(cell_path).read_text())
        self.planner = mplib.Planner(urdf=str(urdf_copy), move_group="tool0")
        robot = cell["robot"]
        base = robot.get("base", [0, 0, 0])
        yaw = math.radians(robot.get("yaw", 0))
        # The boxes in the robot's base frame (mplib 0.2.1 places attached shapes without the
        # base pose of `set_base_pose`, so the robot stays at the origin here).
        def to_base(p):
            x, y, z = (p[k] - base[k] for k in range(3))
            return [math.cos(yaw) * x + math.sin(yaw) * y, -math.sin(yaw) * x + math.cos(yaw) * y, z]

        c = cell.get("planner", {}).get("clearance", 10)
        world = self.planner.planning_world
        for k, ob in enumerate(cell.get("obstacles", [])):
            lo = [(v - c) / 1000 for v in ob["box"]["min"]]
            hi = [(v + c) / 1000 for v in ob["box"]["max"]]
            size = [h - l for h, l in zip(hi, lo)]
            centre = to_base([(h + l) / 2 * 1000 for h, l in zip(hi, lo)])
            shape = fcl.CollisionObject(fcl.Box(size))
            pose = mplib.Pose(p=[v / 1000 for v in centre], q=yaw_quat(-robot.get("yaw", 0)))
            world.add_object(fcl.FCLObject(f"box{k}", pose, [shape], [mplib.Pose()]))
            # As gen-rapid: the base cylinder stands on what lies below its mounting plane.
            if ob["box"]["max"][2] <= base[2]:
                world.get_allowed_collision_matrix().set_entry("link_1", f"box{k}", True)
        for k, s in enumerate((cell.get("tool") or {}).get("shapes", [])):
            if "box" in s:
                lo, hi = s["box"]["min"], s["box"]["max"]
                geom = fcl.Box([(h - l) / 1000 for h, l in zip(hi, lo)])
                pose = mplib.Pose(p=[(h + l) / 2000 for h, l in zip(hi, lo)])
            elif "cylinder" in s:
                a, b, r = s["cylinder"]["from"], s["cylinder"]["to"], s["cylinder"]["radius"]
                d = [q - p for p, q in zip(a, b)]
                length = math.sqrt(sum(v * v for v in d))
                geom = fcl.Cylinder(r / 1000, length / 1000)
                pose = mplib.Pose(p=[(p + q) / 2000 for p, q in zip(a, b)], q=quat_z_to(d))
            else:
                geom = fcl.Sphere(s["sphere"]["radius"] / 1000)
                pose = mplib.Pose(p=[v / 1000 for v in s["sphere"]["centre"]])
            self.planner.update_attached_object(geom, pose, name=f"shape{k}")
            # As gen-rapid: no self-collision test (the forearm's cylinder covers the wrist,
            # where the tool's mount sits).
            acm = world.get_allowed_collision_matrix()
            for link in self.planner.robot.get_pinocchio_model().get_link_names():
                acm.set_entry(link, f"shape{k}", True)
        self.parallelogram = True

    def plan_ms(self, points):
        """Plan-only time of the route through `points`, ms, and whether every leg planned."""
        import numpy as np

        qs = [np.array(urdf_joints(p, self.parallelogram)) for p in points]
        total, ok = 0.0, True
        for a, b in zip(qs, qs[1:]):
            t = time.perf_counter()
            result = self.planner.plan_qpos([b], a, planning_time=1)
            total += (time.perf_counter() - t) * 1e3
            ok = ok and result["status"] == "Success"
        return total, ok


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--binary", default=str(ROOT / "target/release/gen-rapid"))
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--peer-runs", type=int, default=3)
    ap.add_argument("--record", metavar="FILE", help="also write mplib's times to FILE (JSON)")
    ap.add_argument("--recorded", metavar="FILE", help="mplib's times from FILE, not mplib")
    ap.add_argument("cells", nargs="*")
    args = ap.parse_args()
    recorded = json.loads(Path(args.recorded).read_text()) if args.recorded else None
    record = {}
    cells = [Path(c) for c in args.cells] or sorted((ROOT / "benches/cells").glob("*.yaml"))
    with tempfile.TemporaryDirectory() as d:
        urdf = Path(d) / "irb1400.urdf"
        urdf.write_text((ROOT / "robots/irb1400.urdf").read_text())
        print(f"load before: {os.getloadavg()[0]:.2f}", file=sys.stderr)
        print("| cell | mplib plan (ms) | gen-rapid end to end (ms) | ratio |")
        print("|---|---|---|---|")
        for cell in cells:
            if recorded is not None:
                if cell.stem not in recorded["cells"]:
                    sys.exit(f"{args.recorded} has no time for {cell.stem}")
                o = gen_rapid_ms(args.binary, cell, args.runs)
                p = recorded["cells"][cell.stem]
                print(f"| {cell.stem} | {p:.1f} (recorded) | {o:.1f} | {o / p:.2f}x |", flush=True)
                continue
            points = placed_points(args.binary, cell)
            peer = Peer(cell, urdf)
            peer_ms, ours_ms, failed = [], [], 0
            # Interleaved, so both sides see the same minutes.
            for k in range(max(args.runs, args.peer_runs)):
                if k < args.peer_runs:
                    ms, ok = peer.plan_ms(points)
                    peer_ms.append(ms)
                    failed += not ok
                if k < args.runs:
                    ours_ms.append(gen_rapid_ms(args.binary, cell, 1))
            p, o = statistics.median(peer_ms), statistics.median(ours_ms)
            record[cell.stem] = round(p, 1)
            note = f" ({failed} of {args.peer_runs} runs with a leg failed)" if failed else ""
            print(f"| {cell.stem} | {p:.1f}{note} | {o:.1f} | {o / p:.2f}x |", flush=True)
        print(f"load after: {os.getloadavg()[0]:.2f}", file=sys.stderr)
    if args.record:
        import mplib

        table = {
            "what": "mplib RRTConnect plan-only time, ms, median of --peer-runs (benches/vs_mplib.py)",
            "mplib": getattr(mplib, "__version__", "unknown"),
            "date": time.strftime("%Y-%m-%d"),
            "machine": f"{os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f} after",
            "cells": record,
        }
        Path(args.record).write_text(json.dumps(table, indent=2) + "\n")


if __name__ == "__main__":
    main()
