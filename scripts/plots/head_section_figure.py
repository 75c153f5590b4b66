#!/usr/bin/python3
"""The rail head and the wheel's tread across the track, from `railjoint analytic --head-section`.

Usage: head_section_figure.py PNG LABEL=CSV [LABEL=CSV ...]
One panel per CSV: the head's top, the resting wheel's tread above it and
where they touch, heights drawn 5x (a 1:40 cone would not show at 1:1),
from 6 mm below the crest.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figure_fit import save_checked  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    contact = [r for r in rows if r["contact"] == "1"][0]
    return [r for r in rows if r["contact"] == "0"], contact


def main():
    panels = [arg.rsplit("=", 1) for arg in sys.argv[2:]]
    fig, axes = plt.subplots(1, len(panels), figsize=(3.4 * len(panels), 2.9), sharey=True, squeeze=False,
                             constrained_layout=True)
    for ax, (label, path) in zip(axes[0], panels):
        rows, contact = read(path)
        y = [float(r["y_m"]) * 1e3 for r in rows]
        ax.fill_between(y, [float(r["head_z_m"]) * 1e3 for r in rows], -8.0, color="0.75", label="rail head")
        tread = [(float(r["y_m"]) * 1e3, float(r["tread_z_m"]) * 1e3) for r in rows if r["tread_z_m"]]
        ax.plot([p[0] for p in tread], [p[1] for p in tread], color="C0", lw=1.5, label="wheel tread")
        cy = float(contact["y_m"]) * 1e3
        ax.plot([cy], [float(contact["head_z_m"]) * 1e3], "o", color="C3", ms=5, label=f"contact, y = {cy:.1f} mm")
        ax.set_title(label, fontsize=8)
        ax.set_xlabel("lateral position y [mm]")
        ax.set_aspect(5.0)  # heights 5x
        ax.set_ylim(-6.0, 2.5)
        ax.legend(fontsize=6, loc="lower center")
    axes[0][0].set_ylabel("height [mm] (drawn 5x)")
    save_checked(fig, sys.argv[1], dpi=90)


if __name__ == "__main__":
    main()
