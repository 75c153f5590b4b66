#!/usr/bin/python3
"""Thesis figures 4.5 and 4.6 with simulated points over the analytic curves.

Usage: validation_figures.py FIGURE_DIR SCENE [SCENE...]
Reads the CSVs `railjoint validate` writes into FIGURE_DIR and writes
fig4_5.png and fig4_6.png there.
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) if k != "scenario" else r[k] for r in rows] for k in rows[0]} if rows else {}


def thin(values, every):
    return values[::every]


def figure_4_5(directory, scenes):
    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for colour, scene in zip(colours, scenes):
        analytic = read(directory / f"{scene}_analytic.csv")
        sim = read(directory / f"{scene}_sim.csv")
        t0, t1 = min(analytic["t_s"]), max(analytic["t_s"])
        keep, next_t = [], t0
        for i, t in enumerate(sim["t_s"]):  # one point per 1/80 of the window: refined steps are denser
            if t0 <= t <= t1 and t >= next_t:
                keep.append(i)
                next_t = t + (t1 - t0) / 80

        ms = lambda ts: [1e3 * t for t in ts]  # noqa: E731
        axes[0].plot(ms(analytic["t_s"]), [1e3 * z for z in analytic["z_exact_m"]], color=colour, label=f"{scene} exact")
        axes[0].plot(ms(analytic["t_s"]), [1e3 * z for z in analytic["z_linear_m"]], color=colour, ls=":", lw=1)
        axes[0].plot([1e3 * sim["t_s"][i] for i in keep], [1e3 * sim["z_m"][i] for i in keep], "o", ms=3,
                     mfc="none", color=colour)
        axes[1].plot(ms(analytic["t_s"]), analytic["zdot_exact_m_per_s"], color=colour)
        axes[1].plot(ms(analytic["t_s"]), analytic["zdot_linear_m_per_s"], color=colour, ls=":", lw=1)
        axes[1].plot([1e3 * sim["t_s"][i] for i in keep], [sim["zdot_m_per_s"][i] for i in keep], "o", ms=3,
                     mfc="none", color=colour)
        axes[2].plot(ms(analytic["t_s"]), analytic["momentum_exact_Ns"], color=colour)
        axes[2].plot([1e3 * sim["t_s"][i] for i in keep], [sim["momentum_Ns"][i] for i in keep], "o", ms=3,
                     mfc="none", color=colour)
    axes[0].set_ylabel("centre height z [mm]\n(0 at the V bottom)")
    axes[1].set_ylabel("vertical velocity [m/s]")
    axes[2].set_ylabel("vertical momentum [N s]")
    axes[2].set_xlabel("time t = x_w / v [ms]  (0: wheel centre above the V bottom)")
    axes[0].legend(fontsize=8)
    axes[0].set_title("Thesis fig. 4.5: lines analytic (solid exact kinematic, dotted thesis linearised), circles Bullet\n"
                      "beta = 0.03, y_w = 15 mm (s2) / 2 mm (s1), 1 mm wide disc, R = 475 mm, v = 50 m/s.\n"
                      "After a scenario-2 impact the simulated wheel flies off the corner (inertia; the kinematic\n"
                      "path pivots about it): the curves part there by design.", fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(directory / "fig4_5.png", dpi=90)


def figure_4_6(directory):
    analytic = read(directory / "fig4_6_analytic.csv")
    sim = read(directory / "fig4_6_sim.csv")
    fig, (ax, err) = plt.subplots(2, 1, figsize=(7, 7), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for colour, theta in zip(colours, (30.0, 45.0, 60.0)):
        idx = [i for i, t in enumerate(analytic["theta_deg"]) if t == theta]
        beta = [analytic["beta_rad"][i] for i in idx]
        ax.plot(beta, [analytic["exact_thin_disc_Ns"][i] for i in idx], color=colour, lw=1, ls="--",
                label=f"theta = {theta:.0f} deg, thin disc exact")
        ax.plot(beta, [analytic["thesis_thin_disc_Ns"][i] for i in idx], color=colour, lw=1, ls=":")
        ax.plot(beta, [analytic["exact_simulated_wheel_Ns"][i] for i in idx], color=colour,
                label=f"theta = {theta:.0f} deg, 1 mm disc exact")
        sidx = [i for i, t in enumerate(sim["theta_deg"]) if t == theta]
        ax.plot([sim["beta_rad"][i] for i in sidx], [sim["sim_Ns"][i] for i in sidx], "o", mfc="none", color=colour)
        err.plot([sim["beta_rad"][i] for i in sidx], [100 * sim["error_exact"][i] for i in sidx], "o-", color=colour,
                 mfc="none", label=f"theta = {theta:.0f} deg")
    ax.set_ylabel("vertical impulse [N s]")
    ax.set_title("Thesis fig. 4.6: y_w = 15 mm, M = 750 kg, R = 475 mm, v = 50 m/s. Circles: Bullet, a disc of\n"
                 "1 mm width (its inner face at 14.5 mm governs); solid: exact for that disc; dashed: exact,\n"
                 "thin disc at 15 mm; dotted: thesis as printed, thin disc", fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    err.axhspan(-0.5, 0.5, color="0.9", label="0.5 % bound")
    err.axhline(0, color="k", lw=0.5)
    err.set_ylabel("Bullet vs exact [%]")
    err.set_xlabel("dip angle beta [rad]")
    err.grid(alpha=0.3)
    err.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(directory / "fig4_6.png", dpi=90)


def main():
    directory = Path(sys.argv[1])
    figure_4_5(directory, sys.argv[2:])
    figure_4_6(directory)


if __name__ == "__main__":
    main()
