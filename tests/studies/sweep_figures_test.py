#!/usr/bin/python3
"""Every figure script the README runs on a sweep draws the sweeps a user makes
from the README's sweep files: each shipped sweep on a small grid, and the
design map analytic only (run = ["analytic"]) and with one dip angle. Each
script must exit 0 and leave its PNG (figure_fit.py refuses a figure whose
text runs off it).

Run: /usr/bin/python3 tests/studies/sweep_figures_test.py BUILD/scenes/railjoint
"""
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
RAILJOINT = None  # argv[1]


def sweep_file(folder, name, base, run, axes):
    text = f'name = "{name}"\nbase = "{SOURCE / base}"\nrun = {run}\n\n[axes]\n' + "".join(
        f'"{key}" = {value}\n' for key, value in axes.items())
    path = Path(folder) / f"{name}.toml"
    path.write_text(text)
    return path


class SweepFiguresTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)

    def draw(self, script, name, base, run, axes):
        sweep = sweep_file(self.folder.name, name, base, run, axes)
        out = Path(self.folder.name) / name
        ran = subprocess.run([RAILJOINT, "sweep", str(sweep), "--out", str(out), "--jobs", "2"],
                             capture_output=True, text=True, timeout=600)
        self.assertEqual(ran.returncode, 0, ran.stdout + ran.stderr)
        png = out / f"{name}.png"
        drawn = subprocess.run(["/usr/bin/python3", str(SOURCE / "scripts" / "plots" / script),
                                str(out / "results.csv"), str(png)], capture_output=True, text=True, timeout=300)
        print(script, name, drawn.returncode, drawn.stderr.strip().splitlines()[-1:] or "")
        self.assertEqual(drawn.returncode, 0, f"{script} on {name}:\n{drawn.stderr}")
        self.assertGreater(png.stat().st_size, 1000)

    def test_design_map_analytic_only(self):
        self.draw("design_map_figure.py", "design_analytic", "scenes/default.toml", '["analytic"]',
                  {"joint.beta": "[0.01, 0.03]", "joint.theta_deg": "[30.0, 60.0, 90.0]",
                   "wheel.y": "[0.0, 0.01, 0.019]"})

    def test_design_map_one_beta(self):
        self.draw("design_map_figure.py", "design_one_beta", "scenes/default.toml", '["analytic", "simulate"]',
                  {"joint.beta": "[0.03]", "joint.theta_deg": "[30.0, 60.0, 90.0]", "wheel.y": "[0.0, 0.01, 0.019]"})

    def test_design_map_one_beta_analytic_only(self):
        self.draw("design_map_figure.py", "design_one_beta_analytic", "scenes/default.toml", '["analytic"]',
                  {"joint.beta": "[0.05]", "joint.theta_deg": "[45.0, 90.0]", "wheel.y": "[0.0, 0.019]"})

    def test_design_map_as_shipped_on_a_small_grid(self):
        self.draw("design_map_figure.py", "design_map", "scenes/default.toml", '["analytic", "simulate"]',
                  {"joint.beta": "[0.01, 0.03, 0.05]", "joint.theta_deg": "[30.0, 60.0, 90.0]",
                   "wheel.y": "[0.0, 0.01, 0.019]"})

    def test_real_geometry_map_on_a_small_grid(self):
        self.draw("real_geometry_figure.py", "real_geometry", "scenes/default.toml", '["analytic"]',
                  {"joint.half_width": "[0.036]", "joint.rail_profile": '["flat", "60E1"]',
                   "wheel.conicity": "[0.0, 0.025]", "wheel.width": "[0.0, 0.07]",
                   "joint.theta_deg": "[30.0, 60.0, 90.0]", "wheel.y": "[-0.01, 0.0, 0.01]"})

    def test_force_map_on_a_small_grid(self):
        self.draw("force_map_figure.py", "force_map", "scenes/forces/lumped_track.toml", '["analytic", "forces"]',
                  {"joint.theta_deg": "[45.0, 90.0]", "wheel.y": "[0.0, 0.01]"})

    # Small sweeps a user makes that the scripts did not draw (issue 40's
    # leftovers): KeyError 'joint.beta' without a beta axis, a contour's
    # "(2, 2) shaped array" with one wheel.y, a zero-size maximum with one
    # profile, KeyError 'analytic.exact_Ns' for run = ["forces"].
    def test_design_map_without_a_beta_axis(self):
        self.draw("design_map_figure.py", "design_no_beta", "scenes/default.toml", '["analytic"]',
                  {"joint.theta_deg": "[30.0, 60.0, 90.0]", "wheel.y": "[0.0, 0.01]"})

    def test_design_map_one_wheel_position(self):
        self.draw("design_map_figure.py", "design_one_y", "scenes/default.toml", '["analytic"]',
                  {"joint.beta": "[0.01, 0.03]", "joint.theta_deg": "[30.0, 60.0, 90.0]", "wheel.y": "[0.01]"})

    def test_real_geometry_map_one_profile(self):
        self.draw("real_geometry_figure.py", "real_geometry_60e1", "scenes/default.toml", '["analytic"]',
                  {"joint.half_width": "[0.036]", "joint.rail_profile": '["60E1"]', "wheel.conicity": "[0.025]",
                   "wheel.width": "[0.07]", "joint.theta_deg": "[30.0, 60.0, 90.0]", "wheel.y": "[-0.01, 0.0, 0.01]"})

    def test_force_map_forces_only(self):
        self.draw("force_map_figure.py", "force_map_forces_only", "scenes/forces/lumped_track.toml", '["forces"]',
                  {"joint.theta_deg": "[30.0, 90.0]", "wheel.y": "[0.0, 0.01]"})


if __name__ == "__main__":
    RAILJOINT = sys.argv.pop(1)
    unittest.main()
