#!/usr/bin/python3
"""Thesis figures 5.2, 5.3, 5.4, 6.1, 6.2, 6.3, 6.5 and 6.6 of the local
contact-pressure model, and the maxima against the junction angle.

Usage: pressure_figures.py FIGURE_DIR
Reads the CSVs `railjoint pressure --out FIGURE_DIR` writes there and writes
fig5_2.png ... fig6_6.png and theta_sweep.png. Units as the thesis plots
them (mm, MPa), but time in ms and rates in 1e6 MPa/s (table 6.1's 5.877e6 MPa/s
reads 5.877), so no axis needs an offset.
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figure_fit import save_checked  # noqa: E402

TEXT_COLUMNS = ("series", "figure", "label", "key", "value")


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return [{k: (v if k in TEXT_COLUMNS else float(v)) for k, v in row.items()} for row in rows]


def traversal(rows, series, theta=None):
    picked = [r for r in rows if r["series"] == series and (theta is None or abs(r["theta_deg"] - theta) < 1e-9)]
    return {k: [r[k] for r in picked] for k in picked[0]} if picked else None


def save(fig, path):
    fig.tight_layout()
    save_checked(fig, path, dpi=80)


def ms(times_s):
    return [1e3 * t for t in times_s]


RATE = 1e-12  # Pa/s -> 1e6 MPa/s
RATE_UNIT = "1e6 MPa/s"


STYLES = {30.0: ("red", "solid"), 45.0: ("green", "dotted"), 60.0: ("blue", "dashdot"), 90.0: ("black", "dashed"),
          20.0: ("green", "dotted"), 10.0: ("blue", "dashdot"), 5.0: ("black", "dashed")}


def two_panels(xs, top_ys, top_label, bottom_ys, bottom_label, xlabel, title, path):
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    top.plot(xs, top_ys, "k")
    top.set_ylabel(top_label)
    bottom.plot(xs, bottom_ys, "k")
    bottom.set_ylabel(bottom_label)
    bottom.set_xlabel(xlabel)
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    top.set_title(title, fontsize=9)
    save(fig, path)


def outlines(ax, rows, figure, label_points=False):
    labels = []
    for row in rows:
        if row["figure"] == figure and row["label"] not in labels:
            labels.append(row["label"])
    colours = ["red", "green", "blue", "orange", "purple"]
    for i, label in enumerate(labels):
        xs = [1e3 * r["x_m"] for r in rows if r["figure"] == figure and r["label"] == label]
        ys = [1e3 * r["y_m"] for r in rows if r["figure"] == figure and r["label"] == label]
        if label == "gap":
            ax.fill(xs, ys, facecolor="0.3", edgecolor="black", alpha=0.6, label="end-post gap")
        else:
            colour = colours[(i - 1) % len(colours)]
            ax.fill(xs, ys, facecolor=colour, edgecolor=colour, alpha=0.3,
                    label=f"point {label}" if label_points else label)
    ax.set_aspect("equal")
    ax.invert_yaxis()  # the thesis draws y downwards
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper right")


def main(directory):
    meta = {r["key"]: r["value"] for r in read(directory / "pressure_meta.csv")}
    theta = float(meta["theta_deg"])
    shape = meta["shape"]
    trav = read(directory / "pressure_traversals.csv")
    shapes = read(directory / "pressure_outlines.csv")
    points = read(directory / "pressure_points.csv")
    sweep = read(directory / "pressure_theta_sweep.csv")
    scene = traversal(trav, "scene")
    caption = (f"{shape}, a = {1e3 * float(meta['length_m']):g} mm, b = {1e3 * float(meta['width_m']):g} mm, "
               f"g = {1e3 * float(meta['gap_m']):g} mm")

    fig, ax = plt.subplots(figsize=(7, 4))
    outlines(ax, shapes, "fig5_2")
    ax.set_title(f"Fig. 5.2: four positions of the patch\n({caption}, theta = {theta:g} deg)", fontsize=9)
    save(fig, directory / "fig5_2.png")

    x_mm = [1e3 * x for x in scene["x_front_m"]]
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(x_mm, scene["relative_active_area"], "k", label="active contact area A_i")
    ax.plot(x_mm, scene["relative_reduction_area"], "k--", label="reduction area R_i")
    ax.plot(x_mm, [a + r for a, r in zip(scene["relative_active_area"], scene["relative_reduction_area"])], "k-.",
            label="total contact area A_0")
    ax.set_xlabel("position of the patch's front x_front [mm]")
    ax.set_ylabel("relative area [-]")
    ax.set_title(f"Fig. 5.3: areas relative to A_0\n({caption}, theta = {theta:g} deg)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, directory / "fig5_3.png")

    two_panels(x_mm, [1e-6 * p for p in scene["pressure_Pa"]], "uniform contact pressure P [MPa]",
               scene["relative_pressure"], "P_i / P_0 [-]", "position of the patch's front x_front [mm]",
               f"Fig. 5.4: absolute and relative uniform pressure\n({caption}, theta = {theta:g} deg)",
               directory / "fig5_4.png")

    def family(angles, column, scale, ylabel, title, path, absolute=False):
        fig, ax = plt.subplots(figsize=(7, 4))
        for angle in angles:
            t = traversal(trav, "angle", angle)
            colour, style = STYLES[angle]
            ys = [scale * (abs(y) if absolute else y) for y in t[column]]
            ax.plot(ms(t["t_s"]), ys, color=colour, linestyle=style, label=f"theta = {angle:g} deg")
        ax.set_xlabel("time [ms]")
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=9)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        save(fig, directory / path)

    family([30.0, 45.0, 60.0, 90.0], "relative_pressure", 1.0, "rel. contact pressure P_i/P_0 [-]",
           f"Fig. 6.1: relative uniform pressure\n({caption})", "fig6_1.png")
    family([30.0, 45.0, 60.0, 90.0], "rate_Pa_per_s", RATE, f"|dP/dt| [{RATE_UNIT}]",
           f"Fig. 6.2: rate of change of the uniform pressure\n({caption}, exact derivative)", "fig6_2.png", True)
    family([30.0, 20.0, 10.0, 5.0], "rate_Pa_per_s", RATE, f"|dP/dt| [{RATE_UNIT}]",
           f"Fig. 6.5: rate of change for small junction angles\n({caption})", "fig6_5.png", True)
    family([30.0, 20.0, 10.0, 5.0], "pressure_Pa", 1e-6, "uniform contact pressure P [MPa]",
           f"Fig. 6.6: uniform pressure for small junction angles\n({caption})", "fig6_6.png")

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6.5), gridspec_kw={"height_ratios": [3, 2]})
    top.plot(ms(scene["t_s"]), [RATE * abs(r) for r in scene["rate_Pa_per_s"]], "k")
    for p in points:
        top.plot(1e3 * p["t_s"], RATE * abs(p["rate_Pa_per_s"]), "o", color="red")
        top.annotate(f"{int(p['number'])}", (1e3 * p["t_s"], RATE * abs(p["rate_Pa_per_s"])),
                     textcoords="offset points", xytext=(4, 6), color="red")
        top.axvline(1e3 * p["t_s"], color="gray", ls="--", lw=0.7)
    top.set_xlabel("time [ms]")
    top.set_ylabel(f"|dP/dt| [{RATE_UNIT}]")
    top.set_title(f"Fig. 6.3: rate of change at theta = {theta:g} deg with the five points of interest", fontsize=9)
    top.grid(alpha=0.3)
    outlines(bottom, shapes, "fig6_3", label_points=True)
    bottom.set_title("the patch at the five points (fig. 6.4)", fontsize=9)
    save(fig, directory / "fig6_3.png")

    two_panels([r["theta_deg"] for r in sweep], [r["max_relative_pressure"] for r in sweep], "max P/P_0 [-]",
               [RATE * r["max_rate_Pa_per_s"] for r in sweep], f"max |dP/dt| [{RATE_UNIT}]",
               "junction angle theta [deg]",
               f"Maxima during the crossing, theta = 1-90 deg, 100 angles\n({caption})", directory / "theta_sweep.png")


if __name__ == "__main__":
    main(Path(sys.argv[1]))
