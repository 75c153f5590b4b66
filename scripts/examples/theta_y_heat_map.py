#!/usr/bin/env python3
"""A grid of your own design: the junction angle theta against the wheel's
lateral position y_w, every case through the kinematic model and the Bullet
simulation (railjoint.sweep, on every core), drawn as two heat maps: the
simulated jump and its relative error against the exact form.

  PYTHONPATH=build/python /usr/bin/python3 scripts/examples/theta_y_heat_map.py [OUT.png]

Change the axes below (any scene key, a list or a range) or the base scene;
pass out="folder" to sweep() to keep results.csv and resume an interrupted run.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import railjoint  # noqa: E402

BASE = Path(__file__).resolve().parents[2] / "scenes" / "default.toml"
AXES = {
    "joint.theta_deg": {"from": 15.0, "to": 90.0, "count": 31},  # junction angle [deg], 2.5 deg apart
    "wheel.y": {"from": 0.0, "to": 0.019, "count": 39},           # y_w [m], 0.5 mm apart
}


def main(out):
    table = railjoint.sweep(BASE, AXES, run=["analytic", "simulate"], progress=True)
    print(table.attrs["summary"], end="")
    print(table["verdict"].value_counts().to_string())
    jump = table.pivot(index="wheel.y", columns="joint.theta_deg", values="simulate.jump_Ns")
    error = table.pivot(index="wheel.y", columns="joint.theta_deg", values="simulate.error_exact")
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
    extent = [jump.columns.min(), jump.columns.max(), 1e3 * jump.index.min(), 1e3 * jump.index.max()]
    shown = left.imshow(jump.values, origin="lower", aspect="auto", extent=extent, cmap="viridis")
    fig.colorbar(shown, ax=left, label="simulated jump [N s]")
    shown = right.imshow(np.log10(np.abs(error.values) + 1e-17), origin="lower", aspect="auto", extent=extent,
                         cmap="magma")
    fig.colorbar(shown, ax=right, label="log10 |relative error vs exact form|")
    for ax in (left, right):
        ax.set_xlabel("junction angle theta [deg]")
        ax.set_ylabel("wheel position y_w [mm]")
    left.set_title("Jump over (theta, y_w): beta = 0.03, v = 50 m/s, thin disc", fontsize=9)
    right.set_title(f"Bullet against the exact form: worst {np.nanmax(np.abs(error.values)):.1e}", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    print(f"figure: {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "theta_y_heat_map.png")
