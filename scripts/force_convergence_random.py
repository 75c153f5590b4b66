#!/usr/bin/env python3
"""P1's error at the default step on seeded random crossings (theta 20-90 deg,
beta 0.01-0.05, y_w across the head, v 10-80 m/s) on each track: the runs at
4e-6 and 2e-6 s (the impact's pulse at 1e-6 s in both, sim/pulse_window.h)
against one at 0.5e-6 s. Median, 90th percentile, max per seed. With --damped
each crossing also draws contact.restitution in [0.2, 1] (after its other
four draws), and the runs at 4e-6 and 0.5e-6 s are taken
against one at 0.25e-6 s (a damped contact's pulse is stepped finer,
elastic_crossing_run.cpp). Usage:
  /usr/bin/python3 scripts/force_convergence_random.py BUILD/scenes/railjoint [count] [--damped]"""
import json
import random
import subprocess
import sys

TRACKS = {"rigid": ("scenes/forces/lumped_track.toml", ["--set", "track.model=rigid"]),
          "lumped": ("scenes/forces/lumped_track.toml", []),
          "discrete": ("scenes/forces/discrete_track.toml", [])}


def p1(binary, scene, extra, step):
    out = subprocess.run([binary, "simulate", scene, "--json", "--set", f"sim.force_time_step={step:g}"] + extra,
                         capture_output=True, text=True)
    return json.loads(out.stdout)["sim"]["forces"]["p1_N"]


def main():
    damped = "--damped" in sys.argv
    args = [a for a in sys.argv[1:] if a != "--damped"]
    binary = args[0]
    count = int(args[1]) if len(args) > 1 else 10
    reference_s, second_s = (0.25e-6, 0.5e-6) if damped else (0.5e-6, 2e-6)
    print(f"| track | seed | scenes | P1 error at 4e-6 s: median | p90 | max | at {second_s:g} s: median | max |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for track, (scene, targs) in TRACKS.items():
        for seed in (1, 2):
            rng = random.Random(seed)
            e4, e2 = [], []
            for _ in range(count):
                extra = targs + ["--set", f"joint.theta_deg={rng.uniform(20, 90):.3f}", "--set",
                                 f"joint.beta={rng.uniform(0.01, 0.05):.5f}", "--set",
                                 f"wheel.y={rng.uniform(-0.018, 0.018):.5f}", "--set",
                                 f"wheel.speed={rng.uniform(10, 80):.2f}"]
                if damped:
                    extra += ["--set", f"contact.restitution={rng.uniform(0.2, 1.0):.3f}"]
                ref = p1(binary, scene, extra, reference_s)
                e4.append(abs(p1(binary, scene, extra, 4e-6) / ref - 1))
                e2.append(abs(p1(binary, scene, extra, second_s) / ref - 1))
            e4.sort()
            e2.sort()
            n = len(e4)
            print(f"| {track} | {seed} | {n} | {e4[n // 2]:.2e} | {e4[int(0.9 * (n - 1))]:.2e} | {e4[-1]:.2e} | "
                  f"{e2[n // 2]:.2e} | {e2[-1]:.2e} |")


if __name__ == "__main__":
    main()
