#!/usr/bin/python3
"""Thesis figures 3.7, 4.3, 4.5, 4.6, 4.7 and 4.8 with simulated points over
the analytic curves.

Usage: validation_figures.py FIGURE_DIR SCENE [SCENE...]
Reads the CSVs `railjoint validate` writes into FIGURE_DIR (SCENE: the
fig.-4.5 scenes) and writes fig3_7.png, fig4_3.png, ... fig4_8.png there.
"""
import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figure_fit import save_checked  # noqa: E402


TEXT_COLUMNS = ("scenario", "series", "form")
BOUND = 1e-4  # validate's bound on |simulated - exact| / exact


def power(x):
    """1e-04 -> '1e-4'."""
    mantissa, exponent = f"{x:.0e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    # An empty cell is a value that does not apply (outputs.md): NaN, which matplotlib leaves undrawn.
    return {k: [r[k] if k in TEXT_COLUMNS else float(r[k]) if r[k] != "" else math.nan for r in rows]
            for k in rows[0]} if rows else {}


def rows_where(table, **conditions):
    """Indices of the rows whose columns equal the given values."""
    n = len(next(iter(table.values())))
    return [i for i in range(n) if all(table[k][i] == v for k, v in conditions.items())]


def column(table, name, indices, scale=1.0):
    return [scale * table[name][i] for i in indices]


def thin_in_time(times, t0, t1, points):
    """Indices of samples in [t0, t1], at most one per (t1 - t0) / points:
    refined steps are far denser than coarse ones, circles would pile up."""
    keep, next_t = [], t0
    for i, t in enumerate(times):
        if t0 <= t <= t1 and t >= next_t:
            keep.append(i)
            next_t = t + (t1 - t0) / points
    return keep


def save(fig, path, grid_axes=()):
    for ax in grid_axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    save_checked(fig, path, dpi=90)


def sweep_figure():
    """The jump against a swept parameter (top) and Bullet's error against the exact form (bottom)."""
    fig, (ax, err) = plt.subplots(2, 1, figsize=(7, 7), sharex=True, gridspec_kw={"height_ratios": [2, 1]})
    return fig, ax, err


def plot_simulated(ax, err, sim, rows, x, colour, label, unit):
    ax.plot(column(sim, x, rows), column(sim, "sim_Ns", rows), "o", mfc="none", color=colour)
    err.plot(column(sim, x, rows), column(sim, "error_exact", rows, 1 / unit), "o-", mfc="none", color=colour,
             label=label)


def error_unit(sim):
    """The power of ten the errors are plotted in: the largest |error| reads 1 to 10 in it."""
    largest = max((abs(e) for e in sim["error_exact"] if math.isfinite(e)), default=0.0)
    return 10.0 ** math.floor(math.log10(largest)) if largest > 0 else 1.0, largest


def exact_curves(ax, x, analytic, idx, colour, label, same):
    """The exact jump of the 1 mm disc as simulated and of the thin disc: one
    solid line when the CSV's two columns are equal, else solid and dashed."""
    ax.plot(x, column(analytic, "exact_simulated_wheel_Ns", idx), color=colour,
            label=f"{label}, exact (thin disc = 1 mm disc)" if same else f"{label}, 1 mm disc exact")
    if not same:
        ax.plot(x, column(analytic, "exact_thin_disc_Ns", idx), color=colour, lw=1, ls="--",
                label=f"{label}, thin disc exact")


def exact_note(analytic):
    """(same, text): whether the exact jumps of the simulated 1 mm disc and
    the thin disc are equal in the CSV, and what the solid/dashed lines are."""
    diff = max(abs(a - b) for a, b in zip(analytic["exact_simulated_wheel_Ns"], analytic["exact_thin_disc_Ns"]))
    if diff == 0.0:
        return True, "solid: its exact jump, equal to the thin disc's at y_w at every point"
    return False, f"solid: its exact jump; dashed: the thin disc's at y_w (up to {diff:.3g} N s apart)"


def finish_sweep_figure(fig, ax, err, title, xlabel, path, unit, largest):
    """Impulse panel over the simulated points' relative error, on a scale that shows it (figs. 4.6, 4.7)."""
    ax.set_ylabel("vertical impulse [N s]")
    ax.set_title(title, fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    err.axhline(0, color="k", lw=0.5)
    exponent = round(math.log10(unit))
    err.set_ylabel(f"(Bullet - exact) / exact\n[1e{exponent}]" if exponent else "(Bullet - exact) / exact")
    err.set_xlabel(xlabel)
    err.grid(alpha=0.3)
    # The legend in a row or two above the points, clear of them.
    low, high = err.dataLim.y0, err.dataLim.y1
    span = max(high - min(low, 0.0), 1e-12)
    bottom, top = min(low, 0.0) - 0.1 * span, high + 0.7 * span
    err.set_ylim(bottom, top)
    if BOUND / unit < top:
        err.axhline(BOUND / unit, color="firebrick", ls="-.", lw=0.8, label=f"validate's bound {power(BOUND)}")
        where = "dash-dotted"
    else:
        where = "far off this scale"
    err.set_title(f"relative error of the circles: |error| <= {largest:.2g} everywhere "
                  f"(validate's bound: {power(BOUND)}, {where})", fontsize=8)
    labels = err.get_legend_handles_labels()[1]
    err.legend(fontsize=7, loc="upper center", ncol=3 if max(map(len, labels)) < 20 else 2)
    save(fig, path)


def jump_sweep_figure(directory, name, x, series, title, xlabel, dotted=None):
    """Figs. 4.6 and 4.7: the jump against the swept column x, from NAME_analytic.csv and NAME_sim.csv, into
    NAME.png. Each series is (the rows' column values, colour, label): the analytic `dotted` column (if any)
    dotted, the exact curves, the simulated points and their error. `title` has {note} where exact_note's
    text goes."""
    analytic = read(directory / f"{name}_analytic.csv")
    sim = read(directory / f"{name}_sim.csv")
    fig, ax, err = sweep_figure()
    same, note = exact_note(analytic)
    unit, largest = error_unit(sim)
    for conditions, colour, label in series:
        idx = rows_where(analytic, **conditions)
        xs = column(analytic, x, idx)
        if dotted:
            ax.plot(xs, column(analytic, dotted, idx), color=colour, lw=1, ls=":")
        exact_curves(ax, xs, analytic, idx, colour, label, same)
        plot_simulated(ax, err, sim, rows_where(sim, **conditions), x, colour, label, unit)
    finish_sweep_figure(fig, ax, err, title.format(note=note), xlabel, directory / f"{name}.png", unit, largest)


def figure_4_5(directory, scenes):
    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for colour, scene in zip(colours, scenes):
        analytic = read(directory / f"{scene}_analytic.csv")
        sim = read(directory / f"{scene}_sim.csv")
        # scenes/report/outputs.md: t = 0 at the predicted impact, z absolute; this figure keeps
        # t = x / v (0 above the V bottom) and z from the centre height there (the incoming slope's
        # line at x = 0), as the thesis's fig. 4.5 does.
        v = (analytic["x_m"][-1] - analytic["x_m"][0]) / (analytic["t_s"][-1] - analytic["t_s"][0])
        last = max(i for i, t in enumerate(analytic["t_s"]) if t < 0)
        slope = (analytic["z_exact_m"][last] - analytic["z_exact_m"][0]) / (analytic["x_m"][last] - analytic["x_m"][0])
        z_bottom = analytic["z_exact_m"][0] - slope * analytic["x_m"][0]
        for table, zs in ((analytic, ("z_exact_m", "z_linear_m")), (sim, ("z_m",))):
            table["t_s"] = [x / v for x in table["x_m"]]
            for name in zs:
                table[name] = [z - z_bottom for z in table[name]]
        keep = thin_in_time(sim["t_s"], min(analytic["t_s"]), max(analytic["t_s"]), 80)

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
    save(fig, directory / "fig4_5.png", grid_axes=axes)


def figure_4_6(directory):
    series = [({"theta_deg": theta}, colour, f"theta = {theta:.0f} deg")
              for colour, theta in zip(plt.rcParams["axes.prop_cycle"].by_key()["color"], (30.0, 45.0, 60.0))]
    jump_sweep_figure(directory, "fig4_6", "beta_rad", series,
                      "Thesis fig. 4.6: y_w = 15 mm, M = 750 kg, R = 475 mm, v = 50 m/s. Circles: Bullet, a disc\n"
                      "1 mm wide reaching outward from y_w (its inner face, at y_w = 15 mm, governs);\n"
                      "{note}; dotted: thesis as printed, thin disc",
                      "dip angle beta [rad]", dotted="thesis_thin_disc_Ns")


def figure_3_7(directory):
    analytic = read(directory / "fig3_7_analytic.csv")
    sim = read(directory / "fig3_7_sim.csv")
    z_impact = analytic["z_exact_m"][0]  # outputs.md: z absolute; this figure's is from the impact (flat approach)
    for table, zs in ((analytic, ("z_exact_m", "z_linear_m")), (sim, ("z_m",))):
        for name in zs:
            table[name] = [z - z_impact for z in table[name]]
    jumps = read(directory / "fig3_7_jump.csv")
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    ms = [1e3 * t for t in analytic["t_s"]]
    keep = thin_in_time(sim["t_s"], min(sim["t_s"]), max(sim["t_s"]), 60)
    sim_ms = [1e3 * sim["t_s"][i] for i in keep]
    axes[0].plot(ms, [1e3 * z for z in analytic["z_exact_m"]], color="C0", label="exact kinematic (pivot about the edge)")
    axes[0].plot(ms, [1e3 * z for z in analytic["z_linear_m"]], color="C1", ls=":", label="thesis, linearised")
    axes[0].plot(sim_ms, [1e3 * sim["z_m"][i] for i in keep], "o", ms=3, mfc="none", color="k", label="Bullet")
    axes[1].plot(ms, analytic["zdot_exact_m_per_s"], color="C0")
    axes[1].plot(ms, analytic["zdot_linear_m_per_s"], color="C1", ls=":")
    axes[1].plot(sim_ms, [sim["zdot_m_per_s"][i] for i in keep], "o", ms=3, mfc="none", color="k")
    axes[2].plot(ms, analytic["momentum_exact_Ns"], color="C0")
    axes[2].plot(sim_ms, [sim["momentum_Ns"][i] for i in keep], "o", ms=3, mfc="none", color="k")
    styles = {"exact": ("C0", "exact, v held"), "thesis": ("C1", "thesis as printed"),
              "small_angle": ("C2", "R >> u0 (small angle)"), "simulated": ("k", "Bullet")}
    for i, form in enumerate(jumps["form"]):
        colour, label = styles[form]
        t = 1e3 * jumps["time_s"][i] + 0.15 * (i - 1.5)  # side by side: all happen at t = 0
        axes[3].vlines(t, 0, jumps["jump_Ns"][i], color=colour, lw=3, label=f"{label}: {jumps['jump_Ns'][i]:.0f} N s")
    axes[0].set_ylabel("centre height z [mm]\n(0 at the impact)")
    axes[1].set_ylabel("vertical velocity [m/s]")
    axes[2].set_ylabel("vertical momentum [N s]")
    axes[3].set_ylabel("vertical impulse [N s]")
    axes[3].set_xlabel("time [ms]  (0: two-point contact)")
    axes[0].legend(fontsize=8)
    axes[3].legend(fontsize=8, loc="upper right")
    axes[0].set_title("Thesis fig. 3.7: a step up u0 = 0.3 m, R = 1 m, M = 750 kg, v = 50 m/s. Lines analytic, circles Bullet.\n"
                             "The simulated wheel is pressed on by a 100 kN preload, less than the pivot needs: it leaves the\n"
                             "kinematic arc right after the jump (inertia), and the run ends 2 ms after the impact.", fontsize=8)
    save(fig, directory / "fig3_7.png", grid_axes=axes)


def figure_4_3(directory):
    analytic = read(directory / "fig4_3_analytic.csv")
    fig, ax = plt.subplots(figsize=(6, 4))
    for theta in (30.0, 45.0, 60.0):
        idx = rows_where(analytic, theta_deg=theta)
        ax.plot(column(analytic, "beta_rad", idx), column(analytic, "y_t_m", idx, 1e3), label=f"theta = {theta:.0f} deg")
    ax.axhline(20, color="0.4", ls="--", lw=0.8)
    ax.text(0.001, 20.4, "rail-head half width b_t = 20 mm", fontsize=7, color="0.3")
    ax.plot([0.03], [15], "k*", ms=9, label="validation point (beta 0.03, y_w 15 mm)")
    ax.set_xlabel("dip angle beta [rad]")
    ax.set_ylabel("transition value y_t [mm]")
    ax.set_ylim(0, 30)
    ax.set_title("Thesis fig. 4.3: y_t = R sin(beta/2) tan(theta), R = 475 mm (analytic).\n"
                        "Below y_t: scenario 1; above: scenario 2. Checked in Bullet by the stability\n"
                        "study's cases 1 nm either side of y_t.", fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, directory / "fig4_3.png")


def figure_4_7(directory):
    series = [({"series": name, "theta_deg": theta}, colour,
               "scenario 1 (y_w = 2 mm), any theta" if name == "scenario 1" else f"scenario 2, theta = {theta:.0f} deg")
              for name, theta, colour in (("scenario 1", 30.0, "k"), ("scenario 2", 30.0, "C0"),
                                          ("scenario 2", 45.0, "C1"), ("scenario 2", 60.0, "C2"))]
    jump_sweep_figure(directory, "fig4_7", "speed_m_per_s", series,
                      "Thesis fig. 4.7: beta = 0.03, M = 750 kg, R = 475 mm; scenario 2 at y_w = 15 mm.\n"
                      "Circles: Bullet, a disc 1 mm wide reaching outward from y_w (its inner face governs);\n"
                      "{note}. The jump is linear in v in both scenarios.",
                      "train speed v [m/s]")


def figure_4_8(directory):
    analytic = read(directory / "fig4_8_analytic.csv")
    sim = read(directory / "fig4_8_sim.csv")
    thetas = (30.0, 45.0, 60.0, 90.0)
    fig, axes = plt.subplots(1, len(thetas), figsize=(14, 4.4), sharey=True)
    for ax, theta in zip(axes, thetas):
        idx = rows_where(analytic, theta_deg=theta)
        b_t = 1e3 * analytic["half_width_m"][idx[0]]
        y_t = 1e3 * analytic["y_t_m"][idx[0]]
        # Scenario bands across the rail head, as the thesis shades them.
        ax.axhspan(-min(y_t, b_t), min(y_t, b_t), color="0.75", zorder=0, label="scenario 1 band")
        if y_t < b_t:
            ax.axhspan(y_t, b_t, color="0.9", zorder=0, label="scenario 2 band")
            ax.axhspan(-b_t, -y_t, color="0.9", zorder=0)
        cut_x = 0.0 if theta == 90.0 else b_t / math.tan(math.radians(theta))
        ax.plot([-cut_x, cut_x], [-b_t, b_t], color="0.2", lw=1.5, label="cut x = y cot(theta)")
        ax.plot(column(analytic, "A_x_m", idx, 1e3), column(analytic, "A_y_m", idx, 1e3), color="C3", label="A (struck), analytic")
        ax.plot(column(analytic, "B_x_m", idx, 1e3), column(analytic, "B_y_m", idx, 1e3), color="C0", label="B (left), analytic")
        ax.plot(column(analytic, "wheel_x_m", idx, 1e3), column(analytic, "y_w_m", idx, 1e3), color="C2", ls="--",
                label="wheel centre, analytic")
        sidx = [i for i in rows_where(sim, theta_deg=theta) if sim["impact_found"][i] == 1.0]
        ax.plot(column(sim, "struck_x_m", sidx, 1e3), column(sim, "struck_y_m", sidx, 1e3), "o", mfc="none", color="C3",
                label="struck, Bullet")
        ax.plot(column(sim, "left_x_m", sidx, 1e3), column(sim, "left_y_m", sidx, 1e3), "s", mfc="none", color="C0",
                label="left, Bullet")
        ax.plot(column(sim, "wheel_x_m", sidx, 1e3), column(sim, "y_w_m", sidx, 1e3), "x", color="C2",
                label="wheel centre, Bullet")
        ax.set_xlim(-45, 45)
        ax.set_ylim(-b_t - 1, b_t + 1)
        ax.set_xlabel("x along the track [mm]")
        ax.set_title(f"theta = {theta:.0f} deg" + (f", y_t = {y_t:.2f} mm" if y_t < 1e3 else ", no scenario 2"), fontsize=9)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("y across the rail head [mm]")
    axes[-1].legend(fontsize=6.5, loc="lower right")
    fig.suptitle("Thesis fig. 4.8: contact points at two-point contact, top view, beta = 0.03, R = 475 mm, "
                 "b_t = 20 mm; analytic: the thin disc at y_w.\n" + contact_offsets(analytic, sim), fontsize=9)
    save(fig, directory / "fig4_8.png")


def contact_offsets(analytic, sim):
    """Where Bullet's contact points lie across the rail, relative to y_w, from the CSV: the
    struck point of a scenario-2 strike (y_w beyond y_t) and every other point, in mm."""
    y_t = {theta: y for theta, y in zip(analytic["theta_deg"], analytic["y_t_m"])}
    found = [i for i, f in enumerate(sim["impact_found"]) if f == 1.0]
    strikes = [i for i in found if sim["y_w_m"][i] > y_t[sim["theta_deg"][i]]]
    struck = [1e3 * (sim["struck_y_m"][i] - sim["y_w_m"][i]) for i in strikes]
    others = [1e3 * (sim["left_y_m"][i] - sim["y_w_m"][i]) for i in found] + \
             [1e3 * (sim["struck_y_m"][i] - sim["y_w_m"][i]) for i in found if i not in strikes]

    def span(d):
        return f"{min(d):+.2f} mm" if max(d) - min(d) < 0.005 else f"{min(d):+.2f} .. {max(d):+.2f} mm"

    y_w = sorted({1e3 * sim["y_w_m"][i] for i in found})
    text = (f"Bullet: a disc 1 mm wide reaching outward from y_w = {y_w[0]:g} .. {y_w[-1]:g} mm (its inner face, "
            "at y_w, governs). Its points, y - y_w:\n")
    if struck:
        text += f"struck point of a scenario-2 strike (y_w > y_t) {span(struck)}, on the inner face as A; "
    return text + f"all other points {span(others)}, within the disc's 1 mm width"


def main():
    directory = Path(sys.argv[1])
    figure_3_7(directory)
    figure_4_3(directory)
    figure_4_5(directory, sys.argv[2:])
    figure_4_6(directory)
    figure_4_7(directory)
    figure_4_8(directory)


if __name__ == "__main__":
    main()
