#!/usr/bin/python3
"""P1 and P2 against speed on real wheels and rails (issue 37, docs/forces.md).

Runs `railjoint simulate --json` on the lumped and the discrete track for the
thesis's flat head under a thin disc, 60E1 under a 1:40 cone and 60E1 under a
1:20 cone, square joint, and draws P1 (solid) and P2 (dashed) against the
train's speed, one panel per track. A run that cannot vouch for its result
(exit 1) is drawn as an open circle and listed; a P2 picked across a flight
is drawn with a cross. Writes the figure and the numbers as CSV.

    /usr/bin/python3 scripts/plots/real_forces_speed_figure.py \
        --railjoint build/scenes/railjoint --out docs/figures/real_forces_speed.png
"""

import argparse
import csv
import json
import subprocess
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

GEOMETRIES = {
    "flat head, thin disc": ["joint.half_width=0.036"],
    "60E1, 1:40 cone": ["joint.rail_profile=60E1", "joint.half_width=0.036", "wheel.conicity=0.025",
                        "wheel.width=0.07"],
    "60E1, 1:20 cone": ["joint.rail_profile=60E1", "joint.half_width=0.036", "wheel.conicity=0.05",
                        "wheel.width=0.07"],
}
TRACKS = ("lumped", "discrete")


def run(railjoint, repo, track, overrides, speed_m_per_s):
    """One force run: (p1_N, p2_N or None, vouched, p2 across a flight)."""
    args = [railjoint, "simulate", str(repo / "scenes" / "forces" / f"{track}_track.toml"), "--json",
            "--set", "joint.theta_deg=90", "--set", f"wheel.speed={speed_m_per_s}",
            # 30 ms after the impact: P2's window on the slowest runs (the table's script, real_geometry_forces_table.sh).
            "--set", "sim.run_out_time=0.03"]
    for o in overrides:
        args += ["--set", o]
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode not in (0, 1):
        sys.exit(f"real_forces_speed_figure: {' '.join(args)} exited {done.returncode}: {done.stderr.strip()}")
    forces = json.loads(done.stdout)["sim"]["forces"]
    p2 = forces["p2_N"]
    return float(forces["p1_N"]), (float(p2) if p2 is not None else None), done.returncode == 0, bool(
        forces.get("p2_across_flight", False))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--railjoint", default="build/scenes/railjoint", help="the railjoint executable")
    parser.add_argument("--out", required=True, help="the figure (PNG); the numbers go beside it as .csv")
    parser.add_argument("--speeds", default="10,20,30,40,50,60,70,80", help="train speeds [m/s], comma-separated")
    args = parser.parse_args()
    repo = Path(__file__).resolve().parents[2]
    speeds = [float(s) for s in args.speeds.split(",")]
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)

    rows = []
    for track in TRACKS:
        for name, overrides in GEOMETRIES.items():
            for v in speeds:
                p1, p2, vouched, across = run(args.railjoint, repo, track, overrides, v)
                rows.append({"track": track, "geometry": name, "speed_m_per_s": v, "p1_N": p1,
                             "p2_N": "" if p2 is None else p2, "vouched": int(vouched), "p2_across_flight": int(across)})
                print(f"{track:8s} {name:22s} {v:5.1f} m/s  P1 {p1 / 1e3:7.1f} kN  P2 "
                      f"{'-' if p2 is None else f'{p2 / 1e3:7.1f} kN'}{'' if vouched else '  (not vouched for)'}",
                      file=sys.stderr)
    with open(out.with_suffix(".csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)

    fig, axes = plt.subplots(1, len(TRACKS), figsize=(10, 4), sharey=True)
    colours = dict(zip(GEOMETRIES, ("tab:grey", "tab:blue", "tab:red")))
    for ax, track in zip(axes, TRACKS):
        for name in GEOMETRIES:
            mine = [r for r in rows if r["track"] == track and r["geometry"] == name]
            v = [r["speed_m_per_s"] for r in mine]
            ax.plot(v, [r["p1_N"] / 1e3 for r in mine], "-o", color=colours[name], ms=3, label=f"{name}: P1")
            with_p2 = [r for r in mine if r["p2_N"] != ""]
            ax.plot([r["speed_m_per_s"] for r in with_p2], [r["p2_N"] / 1e3 for r in with_p2], "--", color=colours[name],
                    label=f"{name}: P2")
            for r in with_p2:
                if r["p2_across_flight"]:
                    ax.plot(r["speed_m_per_s"], r["p2_N"] / 1e3, "x", color=colours[name], ms=6)
            for r in mine:
                if not r["vouched"]:
                    ax.plot(r["speed_m_per_s"], r["p1_N"] / 1e3, "o", mfc="none", mec="black", ms=8)
        ax.set_title(f"{track} track, square joint")
        ax.set_xlabel("train speed v [m/s]")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("force [kN]")
    axes[-1].legend(fontsize=7, loc="upper left")
    fig.text(0.5, 0.005, "x: P2 picked across a flight; open circle: the run did not vouch for its result",
             ha="center", fontsize=7)
    fig.tight_layout(rect=(0, 0.03, 1, 1))
    fig.savefig(out, dpi=110)
    print(f"wrote {out} and {out.with_suffix('.csv')}", file=sys.stderr)


if __name__ == "__main__":
    main()
