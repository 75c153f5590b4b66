#!/usr/bin/env python3
"""Does the solved elastic crossing's grid check (JSON edge_pressure_grid_change,
edge_pressure_vouched) vouch for the right crossings? The random crossings of
edge_pressure_random.py (40 steps), each at 64 x 48 and 128 x 96 cells, and
at 256 x 192 as the reference: per grid, how many vouch, median / p90 / max
of |change|, and of the vouched values' error against the reference (two
halvings finer for 64 x 48). Usage:
/usr/bin/python3 scripts/edge_grid_check_random.py BUILD/scenes/railjoint [count] [seed]"""
import json
import random
import subprocess
import sys

from edge_pressure_random import scene

GRIDS = {"64 x 48": (64, 48), "128 x 96": (128, 96)}
REFERENCE = (256, 192)


def run(binary, keys, grid):
    sets = [a for k in keys + [f"contact_patch.cells_x={grid[0]}", f"contact_patch.cells_y={grid[1]}"] for a in ("--set", k)]
    p = subprocess.run([binary, "pressure", "scenes/pressure/table6_1_solved.toml", "--json", *sets],
                       capture_output=True, text=True)
    if p.returncode not in (0, 1) or not p.stdout:
        return None
    return json.loads(p.stdout[:p.stdout.rfind("\n}") + 2])  # a verdict's line on stderr follows


def stats(values):
    v = sorted(values)
    if not v:
        return "-"
    return "median %.2f / p90 %.2f / max %.2f %% (n %d)" % (v[len(v) // 2], v[min(len(v) - 1, int(0.9 * len(v)))], v[-1], len(v))


def main():
    binary = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 16
    rng = random.Random(int(sys.argv[3]) if len(sys.argv) > 3 else 1)
    rows = []
    for _ in range(count):
        keys = scene(rng)
        ref = run(binary, keys, REFERENCE)
        results = {name: run(binary, keys, grid) for name, grid in GRIDS.items()}
        if ref is None or ref.get("max_edge_pressure_Pa") is None or any(r is None for r in results.values()):
            print("skipped (refused, or no elastic edge):", " ".join(keys))
            continue
        rows.append((ref["max_edge_pressure_Pa"], results))
    for name in GRIDS:
        checked = [r[name] for _, r in rows if r[name]["edge_pressure_grid_change"] is not None]
        vouched = [(ref, r[name]) for ref, r in rows if r[name]["edge_pressure_vouched"]]
        print("%s: %d of %d vouched" % (name, len(vouched), len(rows)))
        print("  |change|            ", stats([100 * abs(c["edge_pressure_grid_change"]) for c in checked]))
        print("  vouched, against %d x %d" % REFERENCE, stats([100 * abs(c["max_edge_pressure_Pa"] / ref - 1) for ref, c in vouched]))
        print("  all, against %d x %d    " % REFERENCE, stats([100 * abs(r[name]["max_edge_pressure_Pa"] / ref - 1) for ref, r in rows]))


if __name__ == "__main__":
    main()
