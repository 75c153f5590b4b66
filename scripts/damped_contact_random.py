#!/usr/bin/env python3
"""Damped force runs (contact.restitution drawn in [0.2, 0.9]) on seeded random
scenes, per group (lumped track; discrete Euler and Timoshenko rail, each
continuous and a free hinge): the energy balance's surplus over its scale,
P1 and P2 against a reference run 16 times finer than the default step
(2.5e-7 s, every step), the runs at the default step, 1/2 and 1/4 of it, and
the count of suspect runs. Draws as the energy studies of docs/forces.md:
theta 30-90 deg, beta 0.01-0.04, y_w -10..15 mm, v 10-80 m/s, pad 1e8-5e8,
ballast 2e7-1e8 N/m, then e. Usage:
  /usr/bin/python3 scripts/damped_contact_random.py BINARY SEED COUNT OUT.jsonl [REFERENCE_BINARY]
REFERENCE_BINARY (default BINARY) makes the reference runs, or an earlier
OUT.jsonl of the same seed and count lends its. Tables: --summary OUT.jsonl [...]."""
import json
import random
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

GROUPS = {"lumped": ("scenes/forces/lumped_track.toml", []),
          "euler continuous": ("scenes/forces/discrete_track.toml", []),
          "euler free hinge": ("scenes/forces/discrete_track.toml", ["--set", "track.joint_bending_stiffness=0"]),
          "timoshenko continuous": ("scenes/forces/discrete_track.toml", ["--set", "track.beam=timoshenko"]),
          "timoshenko free hinge": ("scenes/forces/discrete_track.toml",
                                    ["--set", "track.beam=timoshenko", "--set", "track.joint_bending_stiffness=0"])}
STEPS = (4e-6, 2e-6, 1e-6)
REFERENCE_STEP = 2.5e-7


def run(binary, scene, extra, step):
    out = subprocess.run([binary, "simulate", scene, "--json", "--set", f"sim.force_time_step={step:g}"] + extra,
                         capture_output=True, text=True)
    try:
        d = json.loads(out.stdout)
    except json.JSONDecodeError:
        return {"error": out.stderr[-300:]}
    f = d["sim"]["forces"]
    return {"verdict": d["sim"]["verdict"], "reason": d["sim"]["verdict_reason"], "p1": f["p1_N"], "p2": f["p2_N"],
            "surplus": f["energy_surplus_J"] / f["energy_scale_J"], "flights": f["flights"]}


def scenes(seed, count):
    rng = random.Random(seed)
    out = []
    for group, (scene, gargs) in GROUPS.items():
        for i in range(count):
            draw = {"theta": rng.uniform(30, 90), "beta": rng.uniform(0.01, 0.04), "y": rng.uniform(-0.010, 0.015),
                    "v": rng.uniform(10, 80), "pad": rng.uniform(1e8, 5e8), "ballast": rng.uniform(2e7, 1e8),
                    "e": rng.uniform(0.2, 0.9)}
            extra = gargs + ["--set", f"joint.theta_deg={draw['theta']:.3f}", "--set", f"joint.beta={draw['beta']:.5f}",
                             "--set", f"wheel.y={draw['y']:.5f}", "--set", f"wheel.speed={draw['v']:.2f}",
                             "--set", f"track.pad_stiffness={draw['pad']:.4g}",
                             "--set", f"track.ballast_stiffness={draw['ballast']:.4g}",
                             "--set", f"contact.restitution={draw['e']:.3f}"]
            out.append((group, i, scene, extra, draw))
    return out


def measure(binary, reference_binary, seed, count, path):
    todo = scenes(seed, count)
    references = None
    if reference_binary.endswith(".jsonl"):  # the reference runs of an earlier measurement of the same scenes
        references = {(r["group"], r["i"]): r["reference"] for r in map(json.loads, open(reference_binary))}

    def one(item):
        group, i, scene, extra, draw = item
        row = {"seed": seed, "group": group, "i": i, "draw": draw}
        row["steps"] = {f"{s:g}": run(binary, scene, extra, s) for s in STEPS}
        row["reference"] = (references[(group, i)] if references is not None
                            else run(reference_binary, scene, extra, REFERENCE_STEP))
        return row

    with ThreadPoolExecutor(max_workers=2) as pool, open(path, "w") as out:
        for row in pool.map(one, todo):
            out.write(json.dumps(row) + "\n")
            out.flush()


def stats(values):
    v = sorted(values)
    if not v:
        return "-"
    n = len(v)
    return f"{v[n // 2]:.1e} / {v[int(0.9 * (n - 1))]:.1e} / {v[-1]:.1e}"


def summary(paths):
    rows = [json.loads(line) for p in paths for line in open(p)]
    print("| group | runs | surplus / scale at 4e-6 s | P1 error at 4e-6 s | P2 error at 4e-6 s | "
          "P1 moves 4e-6 -> 1e-6 s | suspect at 4e-6 / 2e-6 / 1e-6 / ref |")
    print("|---|---:|---|---|---|---|---|")
    for group in GROUPS:
        g = [r for r in rows if r["group"] == group]
        d = [r for r in g if "p1" in r["reference"] and "p1" in r["steps"]["4e-06"]]
        sur = [max(0.0, r["steps"]["4e-06"]["surplus"]) for r in d]
        p1 = [abs(r["steps"]["4e-06"]["p1"] / r["reference"]["p1"] - 1) for r in d]
        p2 = [abs(r["steps"]["4e-06"]["p2"] / r["reference"]["p2"] - 1) for r in d
              if r["steps"]["4e-06"]["p2"] and r["reference"]["p2"]]
        moves = [max(abs(r["steps"][s]["p1"] / r["steps"]["1e-06"]["p1"] - 1) for s in ("4e-06", "2e-06")) for r in d]
        suspect = [sum(1 for r in g if r["steps"][s].get("verdict") != "ok") for s in ("4e-06", "2e-06", "1e-06")]
        suspect.append(sum(1 for r in g if r["reference"].get("verdict") != "ok"))
        print(f"| {group} | {len(g)} | {stats(sur)} | {stats(p1)} | {stats(p2)} | {stats(moves)} | "
              f"{' / '.join(map(str, suspect))} |")


if __name__ == "__main__":
    if sys.argv[1] == "--summary":
        summary(sys.argv[2:])
    else:
        binary, seed, count, path = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
        measure(binary, sys.argv[5] if len(sys.argv) > 5 else binary, seed, count, path)
