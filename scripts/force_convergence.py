#!/usr/bin/env python3
"""The force run's convergence in the step: P1, P2 and the impulse of the
forces scenes on the rigid, lumped and discrete tracks, with and without the
sprung vehicle, at steps 16e-6 .. 0.25e-6 s, against a Richardson
extrapolation of the two finest (order given by --order: 1 for the old
semi-implicit Euler, 2 for velocity Verlet). From 1e-6 s down every step is
at the one step; above it the impact's pulse is stepped at 1e-6 s
(sim.refined_time_step, sim/pulse_window.h). Usage:
  /usr/bin/python3 scripts/force_convergence.py BUILD/scenes/railjoint [--order 2] > table.md
"""
import json
import subprocess
import sys

STEPS = [16e-6, 8e-6, 4e-6, 2e-6, 1e-6, 0.5e-6, 0.25e-6]
SCENES = {
    "rigid": ("scenes/forces/lumped_track.toml", ["--set", "track.model=rigid"]),
    "lumped": ("scenes/forces/lumped_track.toml", []),
    "discrete": ("scenes/forces/discrete_track.toml", []),
}
VEHICLES = {"load": [], "sprung": ["--set", "vehicle.model=sprung"]}


def run(binary, scene, extra, step):
    out = subprocess.run([binary, "simulate", scene, "--json", "--set", f"sim.force_time_step={step:g}"] + extra,
                         capture_output=True, text=True)
    if out.returncode not in (0, 1):
        return None
    try:
        sim = json.loads(out.stdout)["sim"]
    except (ValueError, KeyError):
        return None
    f = sim.get("forces", {})
    return f.get("p1_N"), f.get("p2_N"), sim.get("impulse_Ns"), f.get("energy_surplus_J")


def main():
    binary = sys.argv[1]
    order = int(sys.argv[sys.argv.index("--order") + 1]) if "--order" in sys.argv else 1
    print(f"Richardson reference of order {order} from the two finest steps; errors relative to it.\n")
    print("| track | vehicle | step [us] | P1 [N] | P1 err | P2 [N] | P2 err | impulse [N s] | impulse err | surplus [J] |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for track, (scene, targs) in SCENES.items():
        for vehicle, vargs in VEHICLES.items():
            rows = [(s, run(binary, scene, targs + vargs, s)) for s in STEPS]
            fine, finer = rows[-2][1], rows[-1][1]
            ref = [(2 ** order * b - a) / (2 ** order - 1) if a is not None and b is not None else None
                   for a, b in zip(fine[:3], finer[:3])]
            for s, r in rows:
                if r is None:
                    print(f"| {track} | {vehicle} | {s * 1e6:g} | failed | | | | | | |")
                    continue
                cells = []
                for k in range(3):
                    v, rv = r[k], ref[k]
                    if v is None:
                        cells += ["-", "-"]
                    else:
                        cells += [f"{v:.6g}", f"{(v - rv) / rv:+.2e}" if rv else "-"]
                surplus = "-" if r[3] is None else f"{r[3]:.3g}"
                print(f"| {track} | {vehicle} | {s * 1e6:g} | " + " | ".join(cells) + f" | {surplus} |")
            print(f"| {track} | {vehicle} | ref | " + " | | ".join("-" if x is None else f"{x:.7g}" for x in ref) + " | | |")


if __name__ == "__main__":
    main()
