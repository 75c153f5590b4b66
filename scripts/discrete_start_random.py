#!/usr/bin/env python3
"""Does a discrete-track force run's P1 / P2 move with where it starts? Seeded
random scenes on scenes/forces/discrete_track.toml (speed 20-80 m/s; continuous
rail, 1e6 N m/rad joint bars or a free hinge; no dip or a cosine dip of
0.05-0.3 m; flat head under a thin disc or 60E1 under a 1:40 cone), plus
`hinges` free hinges at 60-80 m/s (the hardest case: docs/forces.md), each
run from sim.approach_distance 1.64 m (the default lead) and 3.28 m:
|P(1.64) / P(3.28) - 1| median, p90, max per seed, and the slowest case.
Usage: /usr/bin/python3 scripts/discrete_start_random.py BUILD/scenes/railjoint [count] [hinges] [seeds]"""
import json
import random
import subprocess
import sys
import time

SCENE = "scenes/forces/discrete_track.toml"
STARTS_M = (1.64, 3.28)


def forces(binary, keys, start_m):
    args = [binary, "simulate", SCENE, "--json", "--set", f"sim.approach_distance={start_m:g}"]
    for k in keys:
        args += ["--set", k]
    t0 = time.time()
    out = subprocess.run(args, capture_output=True, text=True)
    wall = time.time() - t0
    if out.returncode != 0:
        raise RuntimeError(" ".join(args) + "\n" + out.stderr)
    f = json.loads(out.stdout)["sim"]["forces"]
    return f["p1_N"], f["p2_N"], wall


def scene(rng, free_hinge_fast=False):
    keys = []
    if free_hinge_fast:
        keys.append("track.joint_bending_stiffness=0")
        v = rng.uniform(60, 80)
    else:
        joint = rng.choice(["continuous", "bars", "hinge"])
        if joint == "bars":
            keys.append("track.joint_bending_stiffness=1e6")
        elif joint == "hinge":
            keys.append("track.joint_bending_stiffness=0")
        v = rng.uniform(20, 80)
    keys.append(f"wheel.speed={v:.1f}")
    if rng.random() < 0.5:
        keys += ["joint.dip_shape=cosine", f"joint.dip_length={rng.uniform(0.05, 0.3):.2f}"]
    if rng.random() < 0.5:
        keys += ["joint.rail_profile=60E1", "joint.half_width=0.036", "wheel.conicity=0.025", "wheel.width=0.07"]
    return keys


def quantiles(xs):
    xs = sorted(xs)
    n = len(xs)
    return xs[n // 2], xs[int(0.9 * (n - 1))], xs[-1]


def main():
    binary = sys.argv[1]
    count = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    hinges = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    seeds = [int(s) for s in sys.argv[4].split(",")] if len(sys.argv) > 4 else [1, 2]
    rows = []
    for seed in seeds:
        rng = random.Random(seed)
        d1, d2, walls = [], [], []
        worst = None
        for i in range(count + hinges):
            keys = scene(rng, free_hinge_fast=i >= count)
            (a1, a2, wa), (b1, b2, wb) = (forces(binary, keys, s) for s in STARTS_M)
            e1, e2 = abs(a1 / b1 - 1), abs(a2 / b2 - 1)
            d1.append(e1)
            d2.append(e2)
            walls.append(wa)
            print(f"seed {seed} #{i} {' '.join(keys)}: P1 {a1 / 1e3:.3f} / {b1 / 1e3:.3f} kN ({e1:.1e}), "
                  f"P2 {a2 / 1e3:.3f} / {b2 / 1e3:.3f} kN ({e2:.1e}), {wa:.2f} s / {wb:.2f} s", flush=True)
            if worst is None or max(e1, e2) > worst[0]:
                worst = (max(e1, e2), keys)
        rows.append((seed, len(d1), quantiles(d1), quantiles(d2), sum(walls), worst))
    print("| seed | scenes | P1 median | p90 | max | P2 median | p90 | max | wall of the 1.64 m runs [s] |")
    print("|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for seed, n, q1, q2, wall, worst in rows:
        print(f"| {seed} | {n} | {q1[0]:.1e} | {q1[1]:.1e} | {q1[2]:.1e} | {q2[0]:.1e} | {q2[1]:.1e} | {q2[2]:.1e} | {wall:.1f} |")
    for seed, n, q1, q2, wall, worst in rows:
        print(f"seed {seed} largest ({worst[0]:.1e}): {' '.join(worst[1])}")


if __name__ == "__main__":
    main()
