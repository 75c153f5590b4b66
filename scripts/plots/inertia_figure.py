#!/usr/bin/python3
"""Figures of `railjoint study inertia`: where the kinematic model stops holding.

Usage: inertia_figure.py DIR [README_PNG]
Reads inertia_sweep.csv, inertia_thresholds.csv and inertia_peaks.csv from DIR
and writes inertia_sweep.png, inertia_liftoff.png and inertia_p1.png there;
with README_PNG also the one-page summary figure (kept small for the README).
"""
import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figure_fit import save_checked  # noqa: E402

MASS_KG = 750.0
RADIUS_M = 0.475


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    out = []
    for r in rows:
        row = {}
        for k, v in r.items():
            try:
                row[k] = float(v)
            except ValueError:
                row[k] = v
        out.append(row)
    return out


def scenario_one(row):
    return row["scenario"] in ("1", 1.0)


def select(rows, **conditions):
    return [r for r in rows if all(r[k] == v for k, v in conditions.items())]


def jump_panel(ax, sweep, theta, speeds, legend=True):
    """Jumps over y_w divided by M v: the kinematic jump is one curve for all speeds."""
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    rows = select(sweep, theta_deg=theta)
    first = True
    for colour, v in zip(colours, speeds):
        pts = sorted(select(rows, speed_m_per_s=v), key=lambda r: r["y_w_m"])
        if not pts:
            continue
        mm = [1e3 * r["y_w_m"] for r in pts]
        norm = MASS_KG * v
        if first:
            ax.plot(mm, [r["kinematic_jump_Ns"] / norm for r in pts], color="black", lw=2,
                    label="kinematic jump (glued wheel)")
            first = False
        ax.plot(mm, [r["first_jump_Ns"] / norm for r in pts], "o", ms=3.5, mfc="none", color=colour,
                label=f"jump at the joint, {v:.0f} m/s")
        ax.plot(mm, [r["total_impulse_Ns"] / norm for r in pts], "-", lw=1.2, color=colour,
                label=f"total of all impacts, {v:.0f} m/s")
        landing = [(m, r["landing_jump_Ns"] / norm) for m, r in zip(mm, pts) if r["landing_jump_Ns"] > 0]
        if landing:
            ax.plot(*zip(*landing), "x", ms=4, color=colour)
    # From zero, with head room: a panel whose curves are all flat (theta =
    # 90 deg, scenario 1 everywhere) would otherwise end exactly at them.
    ax.set_ylim(0.0, 1.15 * max(max(line.get_ydata(), default=0.0) for line in ax.get_lines()))
    ax.axvline(0, color="grey", lw=0.5)
    ax.set_xlabel("lateral position y_w [mm]  (< 0: step-down side)")
    ax.set_ylabel("vertical impulse / (M v)")
    ax.set_title(f"theta = {theta:.0f} deg", fontsize=9)
    ax.grid(alpha=0.3)
    if legend:
        ax.legend(fontsize=6.5, loc="upper left")


def liftoff_map(ax, sweep, theta):
    rows = select(sweep, theta_deg=theta)
    for r in rows:
        y, v = 1e3 * r["y_w_m"], r["speed_m_per_s"]
        if scenario_one(r):
            ax.plot(y, v, ".", color="0.75", ms=3)
        elif r["liftoff"] > 0:
            ax.plot(y, v, "o", color="tab:red", ms=4)
        else:
            ax.plot(y, v, "o", mfc="none", color="tab:blue", ms=4)
        pred = r["predicted_clearance_m"]
        if not scenario_one(r) and not math.isnan(pred) and (pred > 2e-6) != (r["liftoff"] > 0):
            ax.plot(y, v, "s", mfc="none", color="black", ms=7)
    ax.set_xlabel("y_w [mm]")
    ax.set_ylabel("v [m/s]")
    ax.set_title(f"theta = {theta:.0f} deg", fontsize=9)
    ax.grid(alpha=0.3)


def threshold_panel(ax, thresholds):
    """Model v_c(W) = sqrt(W R cos^3 phi / M) and the simulated brackets."""
    loads = [1e3 * 10 ** (k / 40) for k in range(40 * 2, 40 * 4 + 1)]  # 100 kN .. 10 MN
    for phi, label, style in ((0.04133, "pivot at A / step-down corner (phi = 0.0413 rad)", "-"),
                              (0.015, "entry kink (phi = beta/2)", "--")):
        ax.plot([w / 1e3 for w in loads], [math.sqrt(w * RADIUS_M * math.cos(phi) ** 3 / MASS_KG) for w in loads],
                style, color="black", lw=1, label=f"model: {label}")
    markers = {"scenario2": ("o", "tab:red", "simulated: scenario-2 pivot"),
               "step_down": ("s", "tab:blue", "simulated: step-down pivot"),
               "entry_kink": ("^", "tab:green", "simulated: entry kink (flat approach)")}
    used = set()
    for t in thresholds:
        key = next(k for k in markers if t["case"].startswith(k))
        marker, colour, label = markers[key]
        lo, hi = t["sim_below_m_per_s"], t["sim_above_m_per_s"]
        if math.isnan(lo) or math.isnan(hi):
            continue
        ax.errorbar([t["static_load_N"] / 1e3], [0.5 * (lo + hi)], yerr=[[0.5 * (hi - lo)], [0.5 * (hi - lo)]],
                    fmt=marker, color=colour, ms=5, mfc="none", label=None if key in used else label)
        used.add(key)
    ax.axhspan(10, 50, color="0.9", zorder=0)
    ax.text(120, 46, "thesis speed range", fontsize=7, color="0.4")
    ax.set_xscale("log")
    ax.set_xlabel("static contact force W = wheel load + M g [kN]")
    ax.set_ylabel("lift-off speed v_c [m/s]")
    ax.axvline(119.8575, color="grey", lw=0.7, ls=":")
    ax.text(125, 3, "112.5 kN + M g", fontsize=7, color="0.4", rotation=90)
    ax.set_ylim(0, 60)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=6.5, loc="upper left")


def peak_panel(ax, peaks):
    s1 = [p for p in peaks if p["scenario"] == 1.0]
    s2 = [p for p in peaks if p["scenario"] == 2.0]
    ax.plot([p["speed_m_per_s"] for p in s1], [p["p1_rigid_track_N"] / 1e6 for p in s1], "-", color="black",
            label="P1 = P0 + beta v sqrt(k M) (both scenarios)")
    ax.plot([p["speed_m_per_s"] for p in s1], [p["peak_force_N"] / 1e6 for p in s1], "o", mfc="none",
            color="tab:red", label="simulated peak, scenario 1 (theta 45, y_w 2 mm)")
    if s2:
        ax.plot([p["speed_m_per_s"] for p in s2], [p["p1_from_jump_N"] / 1e6 for p in s2], "--", color="tab:blue",
                label="P0 + (Delta p / M) sqrt(k M), scenario 2 (edge strike)")
        ax.plot([p["speed_m_per_s"] for p in s2], [p["peak_force_N"] / 1e6 for p in s2], "s", mfc="none",
                color="tab:blue", label="simulated peak, scenario 2 (theta 30, y_w 15 mm)")
    if s1:
        ax.axhline(s1[0]["static_load_N"] / 1e6, color="grey", lw=0.7, ls=":")
        ax.text(s1[0]["speed_m_per_s"], s1[0]["static_load_N"] / 1e6 * 1.15, "static load P0", fontsize=7,
                color="0.4")
        ax.set_title(f"compliant contact, k = {s1[0]['stiffness_N_per_m']:.3g} N/m (linearised Hertz at P0)",
                     fontsize=9)
    ax.set_xlabel("v [m/s]")
    ax.set_ylabel("vertical contact force [MN]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=6.5, loc="upper left")


def main():
    directory = Path(sys.argv[1])
    readme = Path(sys.argv[2]) if len(sys.argv) > 2 else None
    sweep = read(directory / "inertia_sweep.csv")
    thresholds = read(directory / "inertia_thresholds.csv")
    peaks = read(directory / "inertia_peaks.csv")
    thetas = sorted({r["theta_deg"] for r in sweep})
    speeds = sorted({r["speed_m_per_s"] for r in sweep})
    shown = [v for v in speeds if v in (10.0, 30.0, 50.0)] or speeds[:3]

    fig, axes = plt.subplots(len(thetas), 1, figsize=(8, 3.2 * len(thetas)), squeeze=False)
    for ax, theta in zip(axes[:, 0], thetas):
        jump_panel(ax, sweep, theta, shown, legend=theta == thetas[0])
    fig.suptitle("Inertial simulation (weight + 112.5 kN) against the kinematic jump; x: landing jump after a flight",
                 fontsize=9)
    fig.tight_layout()
    save_checked(fig, directory / "inertia_sweep.png", dpi=90)

    fig, axes = plt.subplots(1, len(thetas) + 1, figsize=(4 * (len(thetas) + 1), 4), squeeze=False)
    for ax, theta in zip(axes[0, :-1], thetas):
        liftoff_map(ax, sweep, theta)
    threshold_panel(axes[0, -1], thresholds)
    fig.suptitle("Lift-off: red = simulated flight, open blue = none, grey = scenario 1 (no convex corner);\n"
                 "square = simulation and pivot+ballistic model disagree on a flight above 2 um", fontsize=9)
    fig.tight_layout()
    save_checked(fig, directory / "inertia_liftoff.png", dpi=90)

    fig, ax = plt.subplots(figsize=(6, 4))
    peak_panel(ax, peaks)
    fig.tight_layout()
    save_checked(fig, directory / "inertia_p1.png", dpi=90)

    if readme is None:
        return
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    jump_panel(axes[0, 0], sweep, 30.0 if 30.0 in thetas else thetas[0], shown)
    axes[0, 0].set_title("(a) theta = 30 deg: the jump at the joint is the kinematic one; after a scenario-2 strike\n"
                         "the wheel flies and lands again (x), on the step-down side it lands before pivoting",
                         fontsize=8)
    ax = axes[0, 1]
    rows = select(sweep, theta_deg=30.0 if 30.0 in thetas else thetas[0])
    for colour, v in zip(plt.rcParams["axes.prop_cycle"].by_key()["color"], shown):
        pts = sorted(select(rows, speed_m_per_s=v), key=lambda r: r["y_w_m"])
        ax.plot([1e3 * r["y_w_m"] for r in pts], [1e3 * r["max_deviation_m"] for r in pts], "o-", ms=3, color=colour,
                label=f"simulated, {v:.0f} m/s")
        ax.plot([1e3 * r["y_w_m"] for r in pts],
                [1e3 * r["predicted_clearance_m"] if not math.isnan(r["predicted_clearance_m"]) else float("nan")
                 for r in pts], "--", color=colour, lw=1, label=f"pivot model + ballistic flight, {v:.0f} m/s")
    ax.set_yscale("log")
    ax.set_ylim(1e-4, 20)
    ax.axhline(2e-3, color="grey", lw=0.7, ls=":")
    ax.text(-17, 2.4e-3, "2 um: detection", fontsize=7, color="0.4")
    ax.set_xlabel("lateral position y_w [mm]")
    ax.set_ylabel("largest height above the kinematic path [mm]")
    ax.set_title("(b) theta = 30 deg: how far the wheel leaves the kinematic path\n"
                 "(scenario 1 |y_w| < y_t = 4.1 mm: glued; beyond: flights up to 5 mm)", fontsize=8)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=6.5, loc="lower right")
    threshold_panel(axes[1, 0], thresholds)
    axes[1, 0].set_title("(c) why: the load holds the wheel on a corner only up to v_c = sqrt(W R cos^3 phi / M),\n"
                         "8.7 m/s under 112.5 kN; the thesis's 10-50 m/s needs 0.4-3.2 MN", fontsize=8)
    peak_panel(axes[1, 1], peaks)
    axes[1, 1].set_title("(d) a compliant contact turns the jump into a finite force: peak vs Jenkins's P1\n"
                         f"(rigid track; linearised Hertz k = {peaks[0]['stiffness_N_per_m']:.3g} N/m)" if peaks else
                         "(d) compliant contact", fontsize=8)
    fig.suptitle("Where the kinematic model stops holding: a wheel loaded as in service (weight + 112.5 kN) "
                 "is not glued to the rail", fontsize=10)
    fig.tight_layout()
    save_checked(fig, readme, dpi=72)


if __name__ == "__main__":
    main()
