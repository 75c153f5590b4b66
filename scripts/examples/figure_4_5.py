#!/usr/bin/env python3
"""The thesis's figure 4.5 from Python: the wheel centre's height, vertical
velocity and vertical momentum about the impact, the kinematic model's exact
and linearised curves with the Bullet crossing's samples over them, for the
figure's two wheel positions (scenario 2 at y_w = 15 mm, scenario 1 at 2 mm),
and the simulated jump as a point against the three analytic forms.

  PYTHONPATH=build/python /usr/bin/python3 scripts/examples/figure_4_5.py [OUT.png]

Time on the outputs' clock: t = 0 when the wheel centre passes the predicted
impact position (the momentum jump). After a scenario-2 impact the simulated
wheel flies off the corner (inertia); the kinematic path pivots about it.
"""

import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import railjoint  # noqa: E402

SCENE = Path(__file__).resolve().parents[2] / "scenes" / "default.toml"  # the thesis's fig.-4.5 point
WHEEL_POSITIONS_M = {"scenario 2, y_w = 15 mm": 0.015, "scenario 1, y_w = 2 mm": 0.002}


def main(out):
    fig, (height, velocity, momentum) = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    jumps = []
    for (label, y_m), colour in zip(WHEEL_POSITIONS_M.items(), ("tab:blue", "tab:orange")):
        scene = railjoint.load_scene(SCENE, overrides={"wheel.y": y_m})
        model = railjoint.analytic(scene)
        run = railjoint.simulate(scene)
        curve = model.time_history(before_mm=10, after_mm=12)
        samples = run.trajectory
        in_view = (samples["t_s"] >= curve["t_s"][0]) & (samples["t_s"] <= curve["t_s"][-1])
        ms = 1e3
        mass_kg = scene.as_dict()["wheel"]["mass"]
        height.plot(curve["t_s"] * ms, curve["z_exact_m"] * 1e3, color=colour, label=f"{label}: exact")
        height.plot(curve["t_s"] * ms, curve["z_linear_m"] * 1e3, color=colour, ls=":", lw=1, label="linearised")
        height.plot(samples["t_s"][in_view] * ms, samples["z_m"][in_view] * 1e3, "o", ms=3, mfc="none", color=colour,
                    label="Bullet")
        velocity.plot(curve["t_s"] * ms, curve["zdot_exact_m_per_s"], color=colour)
        velocity.plot(curve["t_s"] * ms, curve["zdot_linear_m_per_s"], color=colour, ls=":", lw=1)
        velocity.plot(samples["t_s"][in_view] * ms, samples["zdot_m_per_s"][in_view], "o", ms=3, mfc="none",
                      color=colour)
        momentum.plot(curve["t_s"] * ms, curve["momentum_exact_Ns"], color=colour)
        momentum.plot(samples["t_s"][in_view] * ms, mass_kg * samples["zdot_m_per_s"][in_view], "o", ms=3,
                      mfc="none", color=colour)
        jumps.append(f"{label}: jump exact {model.exact_Ns:.2f} N s, thesis {model.thesis_Ns:.2f}, small angle "
                     f"{model.small_angle_Ns:.2f}; Bullet {run.jump_Ns:.2f} ({run.error_exact:+.1e} vs exact)")
    height.set_ylabel("centre height z [mm]")
    velocity.set_ylabel("vertical velocity [m/s]")
    momentum.set_ylabel("vertical momentum M zdot [N s]")
    momentum.set_xlabel("t [ms], 0 when the centre passes the predicted impact")
    height.legend(fontsize=7, ncol=2)
    height.set_title("Thesis fig. 4.5 from Python: lines kinematic model (solid exact, dotted linearised), circles "
                     "Bullet\n" + "\n".join(jumps), fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=90)
    print("\n".join(jumps))
    print(f"figure: {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "figure_4_5.png")
