#!/usr/bin/python3
"""The solved contact's pressure at its peak step, from `railjoint pressure --map`.

Usage: pressure_map_figure.py PNG MAP_CSV[=TITLE] [MAP_CSV[=TITLE] ...] [--yield-pressure PA]
One panel per map (columns x_m, y_m, surface, rail, gap_m, pressure_Pa): the
pressure in GPa over the grid that followed the wheel, the end-post gap
(no surface: rail = -1) grey, each rail end's cut face (the edge between a
rail end's cells and the gap's) blue, the peak marked. With
--yield-pressure, a map whose peak is that cap (a run with
contact_patch.yield_pressure) has its cells at the cap (the plastic zone of
an elastic-perfectly plastic interface) outlined in cyan, and its plastic
area in the title. Each panel has its own colour scale.
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from figure_fit import save_checked  # noqa: E402
from map_cells import cell_edges  # noqa: E402


def read_map(path):
    """(x [mm], y [mm], rail, pressure [GPa]) as nx x ny grids, x along the rows."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"{path}: no rows (expected the CSV of railjoint pressure --map)")
    xs = sorted({float(r["x_m"]) for r in rows})
    ys = sorted({float(r["y_m"]) for r in rows})
    rail = np.zeros((len(xs), len(ys)))
    pressure = np.zeros((len(xs), len(ys)))
    x_index = {x: i for i, x in enumerate(xs)}
    y_index = {y: j for j, y in enumerate(ys)}
    for r in rows:
        i, j = x_index[float(r["x_m"])], y_index[float(r["y_m"])]
        rail[i, j] = int(r["rail"])
        pressure[i, j] = float(r["pressure_Pa"]) / 1e9
    return np.array(xs) * 1e3, np.array(ys) * 1e3, rail, pressure


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("png")
    parser.add_argument("maps", nargs="+", help="MAP_CSV or MAP_CSV=panel title")
    parser.add_argument("--yield-pressure", type=float, help="the cap [Pa]: outline the cells at it")
    args = parser.parse_args()
    panels = []
    for spec in args.maps:
        path, _, title = spec.partition("=")
        panels.append((read_map(path), title or path))
    fig, axes = plt.subplots(1, len(panels), figsize=(4.6 * len(panels), 3.9), squeeze=False,
                             constrained_layout=True)
    gap_colour = matplotlib.colors.ListedColormap(["0.75"])
    for ax, ((x, y, rail, pressure), title) in zip(axes[0], panels):
        xe, ye = cell_edges(x, 0.5), cell_edges(y, 0.5)
        mesh = ax.pcolormesh(xe, ye, pressure.T, shading="flat", cmap="inferno", vmin=0.0, vmax=pressure.max())
        ax.pcolormesh(xe, ye, np.ma.masked_where(rail.T != -1, np.ones_like(rail.T)), shading="flat",
                      cmap=gap_colour)
        # The cut faces: where a rail end's cells meet the gap's (level -0.5
        # between -1 and 0 is the incoming end's face, 0.5 between -1 and 1
        # the outgoing one's; with a closed gap, the one line between 0 and 1).
        ax.contour(x, y, rail.T, levels=[-0.5, 0.5], colors="#1f5fff", linewidths=1.6)
        cap_GPa = args.yield_pressure / 1e9 if args.yield_pressure else None
        if cap_GPa and abs(pressure.max() - cap_GPa) <= 1e-9 * cap_GPa:
            at_cap = pressure >= cap_GPa * (1 - 1e-9)
            ax.contour(x, y, at_cap.T.astype(float), levels=[0.5], colors="cyan", linewidths=0.9)
            cell_mm2 = (x[1] - x[0]) * (y[1] - y[0])
            ax.set_title(f"{title}\nat the cap {cap_GPa:.2f} GPa (cyan): {at_cap.sum() * cell_mm2:.1f} mm^2",
                         fontsize=9)
        else:
            i, j = np.unravel_index(np.argmax(pressure), pressure.shape)
            ax.plot(x[i], y[j], marker="x", color="cyan", ms=7, mew=1.5)
            ax.set_title(f"{title}\npeak {pressure.max():.2f} GPa (x)", fontsize=9)
        ax.set_xlabel("x along the rail [mm]")
        ax.set_aspect("equal")
        # The part of the grid where there is contact, and a margin.
        ic, jc = np.nonzero(pressure > 0)
        margin = 3.0
        ax.set_xlim(x[ic.min()] - margin, x[ic.max()] + margin)
        ax.set_ylim(y[jc.min()] - margin, y[jc.max()] + margin)
        fig.colorbar(mesh, ax=ax, shrink=0.85, label="pressure [GPa]")
    axes[0][0].set_ylabel("y across the head [mm]")
    save_checked(fig, args.png, dpi=90)


if __name__ == "__main__":
    main()
