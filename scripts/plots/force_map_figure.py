#!/usr/bin/python3
"""Does an inclined cut raise the forces? From `railjoint sweep scenes/sweeps/force_map.toml`.

Usage: force_map_figure.py RESULTS_CSV PNG
Three panels over (theta, y_w): P1 and P2 in kN (a Hertz contact on the lumped
track), and the exact kinematic jump, each with the square joint's value
(theta = 90 deg) for reference, the scenario boundary y_t, and the cases
whose force run could not vouch for its numbers (suspect) crossed out, and
those where the wheel flew after the impact (forces.flights > 0) ringed.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from figure_fit import save_checked  # noqa: E402
from map_cells import cell_edges  # noqa: E402


def main():
    with open(sys.argv[1], newline="") as f:
        rows = [r for r in csv.DictReader(f) if r.get("forces.p1_N")]
    thetas = sorted({float(r["joint.theta_deg"]) for r in rows})
    ys = sorted({float(r["wheel.y"]) for r in rows})
    # A sweep run = ["forces"] alone has no analytic columns: no jump panel, no y_t line.
    analytic = bool(rows) and bool(rows[0].get("analytic.exact_Ns"))
    keys = ("p1", "p2", "jump") if analytic else ("p1", "p2")
    grids = {key: np.full((len(ys), len(thetas)), np.nan) for key in keys}
    y_t = {}
    suspect = ([], [])
    flying = ([], [])  # the wheel left the rail after the impact (forces.flights)
    for r in rows:
        i, j = ys.index(float(r["wheel.y"])), thetas.index(float(r["joint.theta_deg"]))
        grids["p1"][i, j] = float(r["forces.p1_N"]) / 1e3
        grids["p2"][i, j] = float(r["forces.p2_N"]) / 1e3
        if analytic:
            grids["jump"][i, j] = float(r["analytic.exact_Ns"])
            y_t[thetas[j]] = float(r["analytic.y_t_m"]) if r["analytic.y_t_m"] else 1.0  # empty: square joint
        if int(float(r.get("forces.flights") or 0)) > 0:
            flying[0].append(thetas[j])
            flying[1].append(ys[i] * 1e3)
        if r["verdict"] != "ok":
            suspect[0].append(thetas[j])
            suspect[1].append(ys[i] * 1e3)
    square = thetas.index(90.0) if 90.0 in thetas else None
    fig, axes = plt.subplots(1, len(keys), figsize=(5 * len(keys), 4.2), sharey=True, constrained_layout=True)
    titles = {"p1": "P1 [kN]", "p2": "P2 [kN] (150 Hz low pass)", "jump": "exact kinematic jump [N s]"}
    for ax, key in zip(axes, keys):
        grid = grids[key]
        mesh = ax.pcolormesh(cell_edges(thetas, 1.25), cell_edges(np.array(ys) * 1e3, 0.5), grid, shading="flat",
                             cmap="viridis")
        if len(ys) > 1 and len(thetas) > 1:  # a contour needs a grid, not a line
            contours = ax.contour(thetas, np.array(ys) * 1e3, grid, levels=8, colors="white", linewidths=0.5,
                                  alpha=0.7)
            ax.clabel(contours, fontsize=6, fmt="%.0f")
        if analytic:
            ax.plot(thetas, [min(y_t[t], 0.02) * 1e3 for t in thetas], color="white", lw=1.4,
                    label="y_t (scenario 1 below)")
        ax.scatter(*suspect, s=14, marker="x", color="magenta", lw=0.8, label="suspect run")
        ax.scatter(*flying, s=18, marker="o", facecolors="none", edgecolors="orange", lw=0.7,
                   label="wheel flies after the impact")
        title = titles[key]
        if square is not None:
            title += f"; square joint {np.nanmin(grid[:, square]):.0f}-{np.nanmax(grid[:, square]):.0f}"
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("junction angle theta [deg]")
        if len(ys) > 1:
            ax.set_ylim(min(0.0, ys[0] * 1e3), ys[-1] * 1e3)
        fig.colorbar(mesh, ax=ax, shrink=0.9)
    axes[0].set_ylabel("wheel position y_w [mm]")
    axes[0].legend(fontsize=7, loc="upper left", framealpha=0.8)
    fig.suptitle(f"Forces on the lumped track over the cut's angle and the wheel's position ({len(rows)} force runs, "
                 "thin disc, beta = 0.03, v = 50 m/s)", fontsize=10)
    save_checked(fig, sys.argv[2], dpi=80)


if __name__ == "__main__":
    main()
