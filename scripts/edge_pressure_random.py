#!/usr/bin/env python3
"""Does the solved elastic edge pressure (JSON max_edge_pressure_Pa: the mean
over L x L at a rail end's cut edge) move with the grid? Seeded random
crossings of table6_1_solved (theta 20-90 deg, gap 1-10 mm, load 50-250 kN,
the wheel 0-15 mm off the head's centre line, elastic), each at 64 x 48,
128 x 96 and 256 x 192 cells and 40 steps: per grid pair, median / p90 /
max of the relative change of the edge pressure and of the largest cell,
and of the step's wheel position (the edge pressure's, and the
largest cell's). Usage:
/usr/bin/python3 scripts/edge_pressure_random.py BUILD/scenes/railjoint [count] [seed] [--rows]"""
import csv
import json
import os
import random
import subprocess
import sys
import tempfile

GRIDS = [(64, 48), (128, 96), (256, 192)]


def scene(rng):
    return [f"joint.theta_deg={rng.uniform(20, 90):.2f}", f"joint.gap={rng.uniform(1e-3, 10e-3):.5f}",
            f"contact_patch.normal_force={rng.uniform(50e3, 250e3):.0f}", f"wheel.y={rng.uniform(0, 15e-3):.5f}",
            "contact_patch.steps=40"]


def run(binary, keys, grid):
    sets = [a for k in keys + [f"contact_patch.cells_x={grid[0]}", f"contact_patch.cells_y={grid[1]}"] for a in ("--set", k)]
    with tempfile.TemporaryDirectory() as folder:
        steps_csv = os.path.join(folder, "steps.csv")
        p = subprocess.run([binary, "pressure", "scenes/pressure/table6_1_solved.toml", "--json", "--csv", steps_csv, *sets],
                           capture_output=True, text=True)
        if p.returncode not in (0, 1) or not p.stdout:
            return None
        result = json.loads(p.stdout)
        # The largest cell's step (the step "at the max" before the edge pressure chose it).
        rows = list(csv.DictReader(open(steps_csv)))
        top = max(range(len(rows)), key=lambda k: float(rows[k]["max_pressure_Pa"]))
        result["x_wheel_at_max_cell_m"] = float(rows[top]["x_wheel_m"])
        return result


def stats(values):
    v = sorted(values)
    return "median %.4f  p90 %.4f  max %.4f  (n %d)" % (v[len(v) // 2], v[min(len(v) - 1, int(0.9 * len(v)))], v[-1], len(v))


def main():
    binary = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 20
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    rng = random.Random(seed)
    changes = {pair: {"edge": [], "cell": [], "step_mm": [], "cell_step_mm": []} for pair in ((0, 1), (1, 2))}
    for n in range(count):
        keys = scene(rng)
        results = [run(binary, keys, g) for g in GRIDS]
        if any(r is None or r.get("max_edge_pressure_Pa") is None for r in results):
            print("skipped (refused, or no elastic edge):", " ".join(keys))
            continue
        if "--rows" in sys.argv:
            print(" ".join(keys), " ".join("%.1f MPa at %.2f mm" % (r["max_edge_pressure_Pa"] * 1e-6,
                                                                   r["x_wheel_at_max_pressure_m"] * 1e3) for r in results))
        for a, b in changes:
            ra, rb = results[a], results[b]
            changes[(a, b)]["edge"].append(abs(ra["max_edge_pressure_Pa"] / rb["max_edge_pressure_Pa"] - 1))
            changes[(a, b)]["cell"].append(abs(ra["max_cell_pressure_Pa"] / rb["max_cell_pressure_Pa"] - 1))
            changes[(a, b)]["step_mm"].append(1e3 * abs(ra["x_wheel_at_max_pressure_m"] - rb["x_wheel_at_max_pressure_m"]))
            # Mirror steps tie (a symmetric joint): the nearer of the two.
            cell_a, cell_b = ra["x_wheel_at_max_cell_m"], rb["x_wheel_at_max_cell_m"]
            changes[(a, b)]["cell_step_mm"].append(1e3 * min(abs(cell_a - cell_b), abs(cell_a + cell_b)))
    for (a, b), c in changes.items():
        print("%dx%d against %dx%d" % (*GRIDS[a], *GRIDS[b]))
        for what, values in c.items():
            if values:
                print("  %-8s %s" % (what, stats(values)))


if __name__ == "__main__":
    main()
