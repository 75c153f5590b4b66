#!/usr/bin/python3
"""The thesis's design question as a map, from `railjoint sweep scenes/sweeps/design_map.toml`.

Usage: design_map_figure.py RESULTS_CSV PNG
One panel per dip angle beta: the exact kinematic jump over (theta, y_w)
relative to the square joint's (theta = 90 deg, same beta and y_w), the
scenario boundary y_t = R sin(beta/2) tan(theta) (scenario 1 below it: the
square joint's jump), and the simulated points whose jump differs from the
exact one of the wheel as simulated by more than 1e-4, or which could not
vouch for their jump (suspect).
"""
import csv
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402
from matplotlib.ticker import NullFormatter  # noqa: E402
import numpy as np  # noqa: E402

from figure_fit import save_checked  # noqa: E402
from map_cells import cell_edges  # noqa: E402

SMALL, LARGE = 1e-4, 5e-4  # |error| classes marked on the map


def main():
    with open(sys.argv[1], newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["analytic.exact_Ns"]]
    # An analytic-only sweep (run = ["analytic"]) has no simulated columns: the map without its marks.
    simulated = any(r.get("simulate.error_exact") for r in rows)
    # A sweep without a beta axis (or a wheel.y axis) has the base scene's value: one panel (or row).
    beta_of = lambda r: r.get("joint.beta", "")  # noqa: E731
    y_of = lambda r: r.get("wheel.y", "")  # noqa: E731
    by_beta = defaultdict(list)
    for r in rows:
        by_beta[beta_of(r)].append(r)
    betas = sorted(by_beta, key=lambda b: float(b) if b else 0.0)
    # One colour scale for every panel (log: the ratio runs from 1 to several).
    square_of = {(beta_of(r), y_of(r)): float(r["analytic.exact_Ns"]) for r in rows
                 if float(r["joint.theta_deg"]) == 90.0}
    missing = sorted({(beta_of(r), y_of(r)) for r in rows} - set(square_of))
    if missing:
        sys.exit(f"design_map_figure.py: {sys.argv[1]} has no square joint (joint.theta_deg = 90) at beta, y_w = "
                 f"{missing[0][0]}, {missing[0][1]} ({len(missing)} such pairs): every jump is drawn relative to it; "
                 "put 90 in the theta_deg axis")
    top = max(float(r["analytic.exact_Ns"]) / square_of[(beta_of(r), y_of(r))] for r in rows)
    norm = LogNorm(vmin=1.0, vmax=max(top, 1.0 + 1e-9))
    # At least 8 inches wide: the title's two lines fit over one panel too.
    fig, axes = plt.subplots(1, len(betas), figsize=(max(3.6 * len(betas) + 1.2, 8.0), 3.8), sharey=True,
                             squeeze=False, constrained_layout=True)
    mesh = None
    for ax, beta in zip(axes[0], betas):
        cases = by_beta[beta]
        thetas = sorted({float(r["joint.theta_deg"]) for r in cases})
        ys = sorted({float(y_of(r) or 0.0) for r in cases})
        square = {float(y_of(r) or 0.0): float(r["analytic.exact_Ns"]) for r in cases
                  if float(r["joint.theta_deg"]) == 90.0}
        ratio = np.full((len(ys), len(thetas)), np.nan)
        y_t = {}
        for r in cases:
            theta, y = float(r["joint.theta_deg"]), float(y_of(r) or 0.0)
            ratio[ys.index(y), thetas.index(theta)] = float(r["analytic.exact_Ns"]) / square[y]
            # Empty at theta = 90 deg: a square joint has no transition value (scenario 1 everywhere).
            y_t[theta] = float(r["analytic.y_t_m"]) if r["analytic.y_t_m"] else float("inf")
        y_edges = cell_edges(np.array(ys) * 1e3, 0.5)
        mesh = ax.pcolormesh(cell_edges(thetas, 1.25), y_edges, ratio, shading="flat", cmap="viridis", norm=norm)
        boundary = [min(y_t[t], 0.02) * 1e3 for t in thetas]
        ax.plot(thetas, boundary, color="white", lw=1.4, label="y_t (scenario 1 below)")
        levels = [1.1, 1.25, 1.5, 2.0, 3.0, 4.0, 5.0]
        if len(ys) > 1 and len(thetas) > 1:  # a contour needs a grid, not a line
            contours = ax.contour(thetas, np.array(ys) * 1e3, ratio, levels=levels, colors="white", linewidths=0.5,
                                  alpha=0.7)
            ax.clabel(contours, fontsize=6, fmt="%.2f")
        marks = {"small": ([], []), "large": ([], []), "suspect": ([], [])}
        worst = 0.0
        for r in cases:
            if not r.get("simulate.error_exact"):
                continue
            error = abs(float(r["simulate.error_exact"]))
            point = (float(r["joint.theta_deg"]), float(y_of(r) or 0.0) * 1e3)
            worst = max(worst, error)
            kind = "suspect" if r["verdict"] == "suspect" else "large" if error > LARGE else "small" if error > SMALL else None
            if kind:
                marks[kind][0].append(point[0])
                marks[kind][1].append(point[1])
        if simulated:
            ax.scatter(*marks["small"], s=5, color="orange", lw=0, label=f"sim |error| {SMALL:g}-{LARGE:g}")
            ax.scatter(*marks["large"], s=14, color="red", lw=0, label=f"sim |error| > {LARGE:g}")
            ax.scatter(*marks["suspect"], s=12, marker="x", color="magenta", lw=0.7, label="sim suspect")
        beta_text = f"beta = {float(beta):g} rad" if beta else "beta of the base scene"
        ax.set_title(f"{beta_text}: largest sim |error| {100 * worst:.2g} %" if simulated else
                     f"{beta_text} (analytic only)", fontsize=8)
        ax.set_xlabel("junction angle theta [deg]")
        ax.set_ylim(*((min(0.0, ys[0] * 1e3), ys[-1] * 1e3) if len(ys) > 1 else (y_edges[0], y_edges[-1])))
    axes[0][0].set_ylabel("wheel position y_w [mm]")
    axes[0][0].legend(fontsize=6, loc="upper left", framealpha=0.8)
    bar = fig.colorbar(mesh, ax=axes[0].tolist(), label="exact jump / square joint's (theta = 90 deg)", shrink=0.95)
    ticks = [t for t in (1, 1.25, 1.5, 2, 3, 4, 5) if t <= top]
    bar.set_ticks(ticks)
    bar.set_ticklabels([f"{t:g}" for t in ticks])
    bar.ax.yaxis.set_minor_formatter(NullFormatter())  # a small range labelled its minor ticks 1.8x10^0, ...
    fig.suptitle("Vertical momentum jump relative to the square joint's\n(thin disc, R = 475 mm, v = 50 m/s; "
                 f"{len(rows)} cases{', each also simulated' if simulated else ', analytic only'})", fontsize=9)
    save_checked(fig, sys.argv[2], dpi=80)


if __name__ == "__main__":
    main()
