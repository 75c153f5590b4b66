#!/usr/bin/python3
"""Peak wheel-rail forces on an elastic track, from `railjoint study forces`.

Usage: forces_figure.py FORCES_CSV HISTORIES_CSV PNG
Left: P1 and P2 against speed for each joint (points: simulated; lines:
Jenkins et al.'s formulas for the same track). Right: the contact force
histories at one speed (raw and low-passed), the familiar P1/P2 double peak.
"""
import csv
import math
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figure_fit import save_checked  # noqa: E402

COLOURS = {"square": "tab:blue", "scenario 1": "tab:green", "scenario 2": "tab:red"}


def number(text):
    return float(text) if text not in ("", "nan") else math.nan


def main():
    with open(sys.argv[1], newline="") as f:
        rows = [r for r in csv.DictReader(f) if r["p1_N"] != ""]
    with open(sys.argv[2], newline="") as f:
        history = defaultdict(lambda: ([], [], []))
        speed = None
        for r in csv.DictReader(f):
            t, raw, smooth = history[r["joint"]]
            t.append(float(r["t_ms"]))
            raw.append(float(r["force_kN"]))
            smooth.append(float(r["force_lowpass_kN"]))
            speed = r["speed_m_per_s"]

    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.6))
    for joint in COLOURS:
        mine = sorted((r for r in rows if r["joint"] == joint), key=lambda r: number(r["speed_m_per_s"]))
        if not mine:
            continue
        v = [number(r["speed_m_per_s"]) for r in mine]
        c = COLOURS[joint]
        left.plot(v, [number(r["p1_N"]) / 1e3 for r in mine], "o", color=c, label=f"P1 {joint}")
        left.plot(v, [number(r["p2_N"]) / 1e3 for r in mine], "s", color=c, mfc="none", label=f"P2 {joint}")
        if joint == "square":
            left.plot(v, [number(r["jenkins_p1_N"]) / 1e3 for r in mine], "-", color="0.3", lw=1,
                      label="Jenkins P1")
            left.plot(v, [number(r["jenkins_p2_N"]) / 1e3 for r in mine], "--", color="0.3", lw=1,
                      label="Jenkins P2")
    left.set_xlabel("speed v [m/s]")
    left.set_ylabel("force [kN]")
    left.set_title("P1 and P2 against speed (Jenkins: same dip beta, all joints)", fontsize=10)
    left.grid(alpha=0.3)
    left.legend(fontsize=7, ncol=2)

    for joint, (t, raw, smooth) in history.items():
        c = COLOURS.get(joint, "black")
        right.plot(t, raw, color=c, lw=0.8, label=f"{joint}")
        right.plot(t, smooth, color=c, lw=1.6, ls="--", label=f"{joint}, 150 Hz low pass")
    right.set_xlabel("time t [ms]")
    right.set_ylabel("vertical contact force [kN]")
    right.set_title(f"Contact force at v = {speed} m/s: P1, then P2", fontsize=10)
    right.grid(alpha=0.3)
    right.legend(fontsize=7)
    fig.tight_layout()
    save_checked(fig, sys.argv[3], dpi=110)


if __name__ == "__main__":
    main()
