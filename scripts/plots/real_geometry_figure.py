#!/usr/bin/python3
"""Real wheel and rail geometry beside the thesis's, from `railjoint sweep scenes/sweeps/real_geometry_map.toml`.

Usage: real_geometry_figure.py RESULTS_CSV PNG
Three maps of the exact kinematic jump over (theta, y_w) relative to the
square joint's (theta = 90 deg, same geometry and y_w): the thesis's thin disc
on a flat head; a 1:40 conical tread 70 mm wide on the 60E1 head; the same
tread on a flat head. A fourth panel: where on the head the wheel strikes
(the lateral position of the struck point, `analytic.governing_y_m`: A, or B
on a landing) over theta, at y_w = 0, beside -conicity x 300 mm (60E1's
central radius).
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import LogNorm  # noqa: E402
import numpy as np  # noqa: E402

from figure_fit import save_checked  # noqa: E402
from map_cells import cell_edges  # noqa: E402

PANELS = [  # (rail profile, conicity, width): title
    (("flat", 0.0, 0.0), "thesis: thin disc, flat head"),
    (("60E1", 0.025, 0.07), "1:40 cone, 70 mm, on 60E1"),
    (("flat", 0.025, 0.07), "1:40 cone, 70 mm, on a flat head"),
]


def key(r):
    return (r["joint.rail_profile"], float(r["wheel.conicity"]), float(r["wheel.width"]))


def main():
    with open(sys.argv[1], newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["analytic.exact_Ns"]]
    needed = ("joint.rail_profile", "wheel.conicity", "wheel.width", "joint.theta_deg", "wheel.y")
    absent = [column for column in needed if rows and column not in rows[0]]
    if absent:
        sys.exit(f"real_geometry_figure.py: {sys.argv[1]} has no column {', '.join(absent)}: the figure tells the "
                 "geometries apart by them; give each as an axis (one value is enough)")
    # The panels of the geometries the sweep holds (a sweep of one profile draws one).
    panels = [(geometry, title) for geometry, title in PANELS if any(key(r) == geometry for r in rows)]
    if not panels:
        found = sorted({key(r) for r in rows})
        sys.exit(f"real_geometry_figure.py: {sys.argv[1]} holds none of the figure's geometries "
                 f"{[g for g, _ in PANELS]} (rail profile, conicity, width); it holds {found}")
    ratios = {}
    for geometry, _ in panels:
        cases = [r for r in rows if key(r) == geometry]
        square = {r["wheel.y"]: float(r["analytic.exact_Ns"]) for r in cases if float(r["joint.theta_deg"]) == 90.0}
        thetas = sorted({float(r["joint.theta_deg"]) for r in cases})
        ys = sorted({float(r["wheel.y"]) for r in cases})
        ratio = np.full((len(ys), len(thetas)), np.nan)
        for r in cases:
            ratio[ys.index(float(r["wheel.y"])), thetas.index(float(r["joint.theta_deg"]))] = (
                float(r["analytic.exact_Ns"]) / square[r["wheel.y"]])
        ratios[geometry] = (thetas, ys, ratio, cases)
    top = max(np.nanmax(ratio) for _, _, ratio, _ in ratios.values())
    norm = LogNorm(vmin=1.0, vmax=top)
    fig, axes = plt.subplots(1, len(panels) + 1, figsize=(3.75 * (len(panels) + 1), 3.9), squeeze=False,
                             constrained_layout=True)
    axes = axes[0]
    mesh = None
    for ax, (geometry, title) in zip(axes, panels):
        thetas, ys, ratio, cases = ratios[geometry]
        mesh = ax.pcolormesh(cell_edges(thetas, 1.25), cell_edges(np.array(ys) * 1e3, 0.5), ratio, shading="flat",
                             cmap="viridis", norm=norm)
        levels = [1.05, 1.1, 1.25, 1.5, 2.0, 3.0]
        if len(ys) > 1 and len(thetas) > 1:  # a contour needs a grid, not a line
            contours = ax.contour(thetas, np.array(ys) * 1e3, ratio, levels=levels, colors="white", linewidths=0.5)
            ax.clabel(contours, fontsize=6, fmt="%.2f")
        ax.set_title(f"{title}: up to {np.nanmax(ratio):.2f}x", fontsize=8)
        ax.set_xlabel("junction angle theta [deg]")
    axes[0].set_ylabel("wheel position y_w [mm]")
    bar = fig.colorbar(mesh, ax=axes[:len(panels)].tolist(), label="exact jump / square joint's", shrink=0.95, location="left",
                       pad=0.06)
    ticks = [t for t in (1, 1.25, 1.5, 2, 3) if t <= top]
    bar.set_ticks(ticks)
    bar.set_ticklabels([f"{t:g}" for t in ticks])

    # Where the wheel strikes: contact A's lateral position at y_w = 0.
    ax = axes[len(panels)]
    for geometry, title, colour in ((PANELS[1][0], "cone on 60E1", "C1"),
                                    (PANELS[2][0], "cone on flat head", "C2")):
        if geometry not in ratios:
            continue
        cases = sorted((r for r in ratios[geometry][3] if float(r["wheel.y"]) == 0.0),
                       key=lambda r: float(r["joint.theta_deg"]))
        theta = [float(r["joint.theta_deg"]) for r in cases]
        y_a = [float(r["analytic.governing_y_m"]) * 1e3 for r in cases]
        two = [float(r["joint.theta_deg"]) for r in cases if r["analytic.scenario"] == "2"]
        ax.plot(theta, y_a, color=colour, label=title)
        if two:
            ax.axvspan(min(two), max(two), color=colour, alpha=0.08)
    ax.axhline(-0.025 * 300.0, color="grey", lw=0.8, ls="--", label="-conicity x 300 mm = -7.5 mm")
    ax.set_xlabel("junction angle theta [deg]")
    ax.set_ylabel("lateral position of the struck point [mm]")
    ax.set_title("where it strikes (y_w = 0; shade: scenario 2)", fontsize=8)
    ax.legend(fontsize=6, loc="lower right")
    fig.suptitle("Vertical momentum jump relative to the square joint's, R = 475 mm, beta = 0.03, v = 50 m/s "
                 f"({len(rows)} analytic cases)", fontsize=9)
    save_checked(fig, sys.argv[2], dpi=80)


if __name__ == "__main__":
    main()
