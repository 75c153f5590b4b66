#!/usr/bin/python3
"""Stability of the Bullet crossing on stiff and extreme cases, from `railjoint study stability`.

Usage: stability_figure.py CSV PNG
One bar per case: |error| of the vertical momentum jump against the exact
analytic jump, coloured by verdict; cases without a measurement are listed
with their verdict instead of a bar.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from figure_fit import save_checked  # noqa: E402

COLOURS = {"ok": "tab:green", "inaccurate": "tab:orange", "unstable": "tab:red", "rejected": "0.5"}
FLOOR = 1e-10  # bars of smaller errors are drawn at this height
TARGET = 1e-4  # |error| bound of an ok case (stability_study.cpp)


def power(x):
    """1e-10 -> '1e-10'."""
    mantissa, exponent = f"{x:.0e}".split("e")
    return f"{mantissa}e{int(exponent)}"


def main():
    with open(sys.argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    fig, ax = plt.subplots(figsize=(8, 0.3 * len(rows) + 1.6))
    names = [r["case"] for r in rows][::-1]
    rows = rows[::-1]
    for i, r in enumerate(rows):
        error = float(r["rel_error"]) if r["rel_error"] not in ("", "nan") else math.nan
        colour = COLOURS.get(r["verdict"], "black")
        if math.isfinite(error):
            ax.barh(i, max(abs(error), FLOOR), left=FLOOR / 10, color=colour, height=0.7)
            ax.text(max(abs(error), FLOOR) * 1.15, i, f"{error:+.3g}", va="center", fontsize=6.5)
        else:
            reason = r["reason"].removeprefix(r["verdict"] + ": ")
            reason = reason if len(reason) <= 90 else reason[:87] + "..."
            ax.text(FLOOR / 8, i, f"{r['verdict']}: {reason}", va="center", fontsize=6.5, color=colour)
    ax.axvline(TARGET, color="firebrick", ls="-.", lw=0.8)
    ax.text(TARGET, len(rows) - 0.3, f" {power(TARGET)} target", fontsize=7, color="firebrick")
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels(names, fontsize=7)
    ax.set_xscale("log")
    ax.set_xlim(FLOOR / 10, 10)
    ax.set_xlabel("|simulated - exact| / exact of the vertical momentum jump [-] (beside each bar: signed)\n"
                  f"errors below {power(FLOOR)} drawn at {power(FLOOR)}")
    ax.legend(handles=[Patch(color=c, label=v) for v, c in COLOURS.items()], fontsize=7, loc="lower right",
              title="verdict", title_fontsize=7)
    ax.set_title("Bullet crossing on stiff and extreme cases: error against the exact kinematic jump,\n"
                 "coloured by verdict (ok / inaccurate / unstable / rejected)", fontsize=9)
    ax.grid(alpha=0.3, axis="x", which="both", lw=0.4)
    fig.tight_layout()
    save_checked(fig, sys.argv[2], dpi=90)


if __name__ == "__main__":
    main()
