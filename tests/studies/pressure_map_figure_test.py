#!/usr/bin/python3
"""scripts/plots/pressure_map_figure.py draws what `railjoint pressure --map`
writes: table 6.1's solved scene on a small grid, elastic and under the R260
cap in one figure, and with the end-post gap closed (no gap cells: only the
cut between the rail ends drawn). The script must exit 0 and leave its PNG
(figure_fit.py refuses a figure whose text runs off it).

Run: /usr/bin/python3 tests/studies/pressure_map_figure_test.py BUILD/scenes/railjoint
"""
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[2]
SCENE = SOURCE / "scenes" / "pressure" / "table6_1_solved.toml"
RAILJOINT = None  # argv[1]
SMALL = ["--set", "contact_patch.steps=7", "--set", "contact_patch.cells_x=48", "--set", "contact_patch.cells_y=36"]


class PressureMapFigureTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)

    def map_csv(self, name, *settings, at_an_edge=False):
        path = Path(self.folder.name) / f"{name}.csv"
        ran = subprocess.run([RAILJOINT, "pressure", str(SCENE), *SMALL, *settings, "--map", str(path)],
                             capture_output=True, text=True, timeout=300)
        # An elastic crossing's peak at a rail end's edge is the grid's: the run withholds it, its map written;
        # on these cells its edge pressure's grid check vouches (exit 0).
        self.assertEqual(ran.returncode, 0, ran.stdout + ran.stderr)
        if at_an_edge:
            self.assertIn("NOT A NUMBER", ran.stdout)
        return path

    def draw(self, png, *arguments):
        drawn = subprocess.run(["/usr/bin/python3", str(SOURCE / "scripts" / "plots" / "pressure_map_figure.py"),
                                str(png), *arguments], capture_output=True, text=True, timeout=300)
        self.assertEqual(drawn.returncode, 0, drawn.stderr)
        self.assertGreater(png.stat().st_size, 1000)

    def test_elastic_and_capped_side_by_side(self):
        elastic = self.map_csv("elastic", at_an_edge=True)
        capped = self.map_csv("capped", "--set", "contact_patch.yield_pressure=1.15e9")
        self.draw(Path(self.folder.name) / "both.png", f"{elastic}=elastic", f"{capped}=cap 1.15 GPa",
                  "--yield-pressure", "1.15e9")

    def test_closed_gap(self):
        closed = self.map_csv("closed", "--set", "joint.gap=0")
        self.draw(Path(self.folder.name) / "closed.png", str(closed))


if __name__ == "__main__":
    RAILJOINT = sys.argv.pop(1)
    unittest.main()
