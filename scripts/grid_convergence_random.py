#!/usr/bin/env python3
"""The discrete track's grid error on seeded random crossings: P1, P2, the
rail seat's static force and its P2 force at track.nodes_per_bay = 8, 16 and
32, each against the Richardson extrapolation of 16 and 32 (the grid's error
falls as 1 / nodes^2: X = X32 + (X32 - X16) / 3). Each crossing draws theta
20-90 deg, beta 0.01-0.05, y_w across the head, v 20-80 m/s, and runs on the
four rails in turn (continuous or a free hinge, Euler or Timoshenko). The
step falls with the grid as the rail's stiffest mode asks (1 / nodes^2): the
default 4e-6 s at 8 nodes a bay, 1e-6 s at 16, 2.5e-7 s at 32, or the bound
the program states where a Timoshenko rail's is lower; the step's own error
at 4e-6 s is 6e-6 of P1 (docs/forces.md), far below the grid's. Prints one
table per seed (median, 90th percentile, max of |X_n / X - 1|, of the plain
change |X8 / X32 - 1|, the observed order log2 |X8 - X16| / |X16 - X32|, and
the CPU time per run: the runs go one at a time). Usage:
  /usr/bin/python3 scripts/grid_convergence_random.py BUILD/scenes/railjoint SEED [count]"""
import json
import math
import random
import re
import resource
import subprocess
import sys

SCENE = "scenes/forces/discrete_track.toml"
GRIDS = {8: 4e-6, 16: 1e-6, 32: 2.5e-7}
QUANTITIES = ("p1_N", "p2_N", "rail_seat_static_N", "p2_rail_seat_N")
RAILS = (("continuous", "euler"), ("hinge", "euler"), ("continuous", "timoshenko"), ("hinge", "timoshenko"))


def run(binary, extra, nodes, step):
    while True:
        args = [binary, "simulate", SCENE, "--json", "--set", f"track.nodes_per_bay={nodes}", "--set",
                f"sim.force_time_step={step:.6g}"] + extra
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        out = subprocess.run(args, capture_output=True, text=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu_s = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
        if out.returncode == 0 or out.stdout.strip().startswith("{"):
            sim = json.loads(out.stdout)["sim"]
            forces = sim["forces"]
            return {"step": step, "cpu_s": cpu_s, "verdict": sim["verdict"],
                    **{q: forces[q] for q in QUANTITIES}}
        bound = re.search(r"1 / omega = ([0-9.e+-]+) s", out.stderr)
        if not bound:
            raise RuntimeError(" ".join(args) + "\n" + out.stderr)
        step = 0.95 * float(bound.group(1))


def crossing(rng, index):
    joint, beam = RAILS[index % len(RAILS)]
    extra = ["--set", f"joint.theta_deg={rng.uniform(20, 90):.3f}", "--set", f"joint.beta={rng.uniform(0.01, 0.05):.5f}",
             "--set", f"wheel.y={rng.uniform(-0.018, 0.018):.5f}", "--set", f"wheel.speed={rng.uniform(20, 80):.2f}",
             "--set", f"track.beam={beam}"]
    if joint == "hinge":
        extra += ["--set", "track.joint_bending_stiffness=0"]
    return {"rail": f"{joint} {beam}", "extra": extra}


def quantiles(values):
    v = sorted(values)
    return v[len(v) // 2], v[int(0.9 * (len(v) - 1))], v[-1]


def main():
    binary, seed = sys.argv[1], int(sys.argv[2])
    count = int(sys.argv[3]) if len(sys.argv) > 3 else 12
    rng = random.Random(seed)
    cases = [crossing(rng, i) for i in range(count)]
    jobs = [(c, n) for c in cases for n in GRIDS]
    for case, nodes in jobs:
        case[nodes] = run(binary, case["extra"], nodes, GRIDS[nodes])
    with open(f"grid_convergence_seed{seed}.json", "w") as f:
        json.dump(cases, f, indent=1)
    print(f"seed {seed}: {count} crossings; verdicts "
          f"{sorted(set(c[n]['verdict'] for c in cases for n in GRIDS))}")
    print("| quantity | 8 nodes: median | p90 | max | 16 nodes: median | max | 8 vs 32: median | max | "
          "order: median | min |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for q in QUANTITIES:
        e8, e16, plain, order = [], [], [], []
        for c in cases:
            x8, x16, x32 = c[8][q], c[16][q], c[32][q]
            exact = x32 + (x32 - x16) / 3.0
            e8.append(abs(x8 / exact - 1))
            e16.append(abs(x16 / exact - 1))
            plain.append(abs(x8 / x32 - 1))
            if x16 != x32 and x8 != x16:
                order.append(math.log2(abs(x8 - x16) / abs(x16 - x32)))
        m8, p8, x8 = quantiles(e8)
        m16, _, x16 = quantiles(e16)
        mp, _, xp = quantiles(plain)
        print(f"| {q} | {m8:.1e} | {p8:.1e} | {x8:.1e} | {m16:.1e} | {x16:.1e} | {mp:.1e} | {xp:.1e} | "
              f"{quantiles(order)[0]:.2f} | {min(order):.2f} |")
    for rail in sorted(set(c["rail"] for c in cases)):
        sub = [c for c in cases if c["rail"] == rail]
        worst = {q: max(abs(c[8][q] / (c[32][q] + (c[32][q] - c[16][q]) / 3.0) - 1) for c in sub) for q in QUANTITIES}
        print(f"  {rail} ({len(sub)}): max at 8 nodes " + ", ".join(f"{q} {worst[q]:.1e}" for q in QUANTITIES))
    for n in GRIDS:
        w = quantiles([c[n]["cpu_s"] for c in cases])
        print(f"  {n} nodes a bay (step {GRIDS[n]:g} s): CPU time per run median {w[0]:.2f} s, max {w[2]:.2f} s")


if __name__ == "__main__":
    main()
