#!/usr/bin/python3
"""Error against run time of the Bullet crossing, from `railjoint study convergence`.

Usage: convergence_figure.py OUT_DIR CSV [CSV...]
Each CSV (convergence_<scene>.csv) gives convergence_<scene>.png in OUT_DIR;
with several CSVs also convergence_all.png, one panel per scene.
"""
import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figure_fit import save_checked  # noqa: E402

# Errors at or below this count as equal (kErrorResolution, scenes/studies/pareto_front.h):
# the shaded band and its label both come from it.
RESOLUTION = 1e-8
TARGET = 5e-3  # the accuracy target, 0.5 %
FAMILIES = {
    "fixed": dict(marker="o", color="tab:blue", label="fixed step (no refinement)"),
    "adaptive": dict(marker="s", color="tab:orange", label="1e-4 s step, refined near contact"),
    "iterations": dict(marker="^", color="tab:green", label="solver iterations (1..100)"),
    "solved from": dict(marker="v", color="tab:red", label="contacts solved from 1e-8..1e-12 m"),
    "narrow phase": dict(marker="x", color="tab:gray", label="Bullet's own narrow phase (GJK/EPA)"),
    "default": dict(marker="D", color="tab:purple", label="scene settings"),
}


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for key in ("abs_rel_error", "median_cpu_s", "thesis_vs_exact", "small_angle_vs_exact", "exact_Ns"):
            r[key] = float(r[key])
        r["families"] = r["families"].split(";")
        r["on_front"] = r["on_front"] == "1"
        r["is_default"] = r["is_default"] == "1"
    return rows


def power(x):
    """1e-08 -> '1e-8'."""
    mantissa, exponent = f"{x:.0e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def short(label):
    """Point annotation: the varied number only."""
    for prefix in ("fixed ", "1e-04 -> ", "solved from "):
        if label.startswith(prefix):
            return label[len(prefix):].replace(" s", "")
    return label.replace(" iterations", " it")


def panel(ax, rows, short_title=False):
    scene = rows[0]["scene"]
    ok = [r for r in rows if math.isfinite(r["abs_rel_error"]) and math.isfinite(r["median_cpu_s"])]
    failed = [r for r in rows if not math.isfinite(r["abs_rel_error"]) and math.isfinite(r["median_cpu_s"])]
    shown = lambda e: max(e, RESOLUTION / 10)  # noqa: E731  (exact to round-off: drawn on the floor)
    errors = [shown(r["abs_rel_error"]) for r in ok]
    top = max(errors + [rows[0]["thesis_vs_exact"], rows[0]["small_angle_vs_exact"], TARGET]) * 3
    bottom = min(errors + [rows[0]["thesis_vs_exact"], rows[0]["small_angle_vs_exact"]]) / 3

    for family, style in FAMILIES.items():
        # Along the ladder: coarse to fine steps, few to many iterations.
        order = {"fixed": lambda r: -float(r["time_step_s"]), "adaptive": lambda r: -float(r["refined_time_step_s"]),
                 "iterations": lambda r: int(r["solver_iterations"]),
                 "solved from": lambda r: -float(r["contact_processing_threshold_m"]),
                 "narrow phase": lambda r: 0, "default": lambda r: 0}[family]
        members = sorted((r for r in ok if family in r["families"]), key=order)
        if not members:
            continue
        ax.plot([1e3 * r["median_cpu_s"] for r in members], [shown(r["abs_rel_error"]) for r in members],
                marker=style["marker"], color=style["color"], label=style["label"], lw=1, ms=5, mfc="none")
        # Settings that land on the same spot (e.g. 4..100 iterations) share one label.
        groups = []
        for r in members:
            for g in groups:
                if abs(math.log(r["median_cpu_s"] / g[0]["median_cpu_s"])) < 0.05 and \
                        abs(math.log(shown(r["abs_rel_error"]) / shown(g[0]["abs_rel_error"]))) < 0.05:
                    g.append(r)
                    break
            else:
                groups.append([r])
        below = family == "iterations"
        for g in groups:
            text = "/".join(short(r["label"]).replace(" it", "") for r in g) + (" it" if below else "")
            ax.annotate(text, (1e3 * g[0]["median_cpu_s"], shown(g[0]["abs_rel_error"])),
                        textcoords="offset points", xytext=(4, -9 if below else 3), fontsize=6, color=style["color"])
        lost = [r for r in failed if family in r["families"]]
        if lost:
            ax.plot([1e3 * r["median_cpu_s"] for r in lost], [top / 1.6] * len(lost), "x", color=style["color"], ms=7)
            for r in lost:
                ax.annotate(short(r["label"]), (1e3 * r["median_cpu_s"], top / 1.6), textcoords="offset points",
                            xytext=(3, -9), fontsize=6, color=style["color"])
    if failed:
        ax.plot([], [], "x", color="black", label="no impact found (drawn at the top)")

    front = sorted((r for r in ok if r["on_front"]), key=lambda r: r["median_cpu_s"])
    if front:
        ax.plot([1e3 * r["median_cpu_s"] for r in front], [shown(r["abs_rel_error"]) for r in front], color="black",
                lw=0.6, ls="-", drawstyle="steps-post", zorder=0, label="Pareto front")
    for r in ok:
        if r["is_default"]:
            ax.plot(1e3 * r["median_cpu_s"], shown(r["abs_rel_error"]), marker="*", ms=14, mfc="none",
                    color="crimson", ls="none", label="default settings")

    ref = rows[0]
    ax.axhline(ref["thesis_vs_exact"], color="gray", ls="--", lw=1,
               label=f"|thesis - exact| / exact = {ref['thesis_vs_exact']:.1e}")
    ax.axhline(ref["small_angle_vs_exact"], color="gray", ls=":", lw=1.2,
               label=f"|small angle - exact| / exact = {ref['small_angle_vs_exact']:.1e}")
    ax.axhline(TARGET, color="firebrick", ls="-.", lw=0.8,
               label=f"accuracy target {power(TARGET)} ({100 * TARGET:g} %)")
    if any(shown(r["abs_rel_error"]) <= RESOLUTION / 10 for r in ok) or bottom < RESOLUTION:
        ax.axhspan(RESOLUTION / 30, RESOLUTION, color="0.92", zorder=-1)
        ax.text(0.99, RESOLUTION / 2.5, f"below {power(RESOLUTION)}: counted as exact; "
                f"below {power(RESOLUTION / 10)}: drawn at {power(RESOLUTION / 10)}",
                transform=ax.get_yaxis_transform(), ha="right", fontsize=6, color="0.4")
    ax.set_xscale("log")
    ax.set_yscale("log")
    floor = min(bottom, RESOLUTION / 10) if bottom < RESOLUTION else bottom
    ax.set_ylim(max(floor / 3, 1e-13), top)
    ax.set_xlabel(f"CPU time per run [ms] (median of {rows[0]['repeats']} runs, one thread)")
    ax.set_ylabel("|simulated - exact| / exact  (vertical momentum jump)")
    if short_title:
        ax.set_title(f"{scene} (exact jump {ref['exact_Ns']:.1f} N s)", fontsize=9)
    else:
        ax.set_title(f"{scene}: simulated jump vs exact analytic jump ({ref['exact_Ns']:.1f} N s) against run time",
                     fontsize=9)
    ax.grid(alpha=0.3, which="both", lw=0.4)
    ax.legend(fontsize=6.5, loc="best")


def main():
    out_dir = Path(sys.argv[1])
    tables = [read(p) for p in sys.argv[2:]]
    for rows in tables:
        if not rows:
            continue
        fig, ax = plt.subplots(figsize=(8, 5.5))
        panel(ax, rows)
        fig.tight_layout()
        save_checked(fig, out_dir / f"convergence_{rows[0]['scene']}.png", dpi=90)
    tables = [t for t in tables if t]
    if len(tables) > 1:
        fig, axes = plt.subplots(1, len(tables), figsize=(6.5 * len(tables), 5.5))
        for ax, rows in zip(axes, tables):
            panel(ax, rows, short_title=True)
        fig.suptitle("Bullet crossing: error of the vertical momentum jump against CPU time, per numerical setting",
                     fontsize=10)
        fig.tight_layout()
        save_checked(fig, out_dir / "convergence_all.png", dpi=90)


if __name__ == "__main__":
    main()
