#!/usr/bin/python3
"""scripts/plots/figure_fit.py: a figure whose text does not fit is refused,
a figure whose text fits is saved.

Run: /usr/bin/python3 tests/studies/figure_titles_test.py
"""
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts" / "plots"))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from figure_fit import FigureTextError, save_checked  # noqa: E402

LONG = "Fig. 5.4: absolute and relative uniform pressure (ellipse, a = 16 mm, b = 12 mm, g = 6 mm, theta = 30 deg)"


def normal_figure():
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot([0, 1, 2], [0, 1, 4], label="P")
    ax.set_title("Fig. 5.4: uniform pressure\n(ellipse, a = 16 mm, theta = 30 deg)", fontsize=9)
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("P [MPa]")
    ax.text(0.5, 3, "a note inside the axes", fontsize=7)
    ax.legend()
    fig.tight_layout()
    return fig


class FigureFitTest(unittest.TestCase):
    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.addCleanup(self.folder.cleanup)
        self.path = Path(self.folder.name) / "figure.png"

    def assert_refused(self, fig, *words):
        with self.assertRaises(FigureTextError) as caught:
            save_checked(fig, self.path, dpi=80)
        message = str(caught.exception)
        for word in ("figure.png",) + words:
            self.assertIn(word, message)
        self.assertEqual(list(Path(self.folder.name).iterdir()), [], "a refused figure must leave no file")

    def test_a_normal_figure_is_saved(self):
        save_checked(normal_figure(), self.path, dpi=80)
        self.assertGreater(self.path.stat().st_size, 1000)
        self.assertEqual(list(Path(self.folder.name).iterdir()), [self.path])

    def test_the_file_is_what_savefig_writes(self):
        plain = Path(self.folder.name) / "plain.png"
        fig = normal_figure()
        fig.savefig(plain, dpi=80)
        save_checked(fig, self.path, dpi=80)
        self.assertEqual(self.path.read_bytes(), plain.read_bytes())

    def test_a_title_too_long_for_the_figure_is_refused(self):
        fig = normal_figure()
        fig.axes[0].set_title(LONG, fontsize=9)
        fig.tight_layout()
        self.assert_refused(fig, "axes 0 title", "Fig. 5.4: absolute", "runs off the figure", "right by")

    def test_a_suptitle_too_long_for_the_figure_is_refused(self):
        fig, axes = plt.subplots(1, 2, figsize=(8, 4))
        fig.suptitle("Lift-off: red = simulated flight, open blue = none, grey = scenario 1 (no convex corner); "
                     "square = simulation and pivot+ballistic model disagree on a flight above 2 um", fontsize=9)
        fig.tight_layout()
        self.assert_refused(fig, "suptitle", "Lift-off", "left by", "right by")

    def test_an_axis_label_and_a_text_outside_the_figure_are_refused(self):
        fig = normal_figure()
        fig.axes[0].set_xlabel("x " * 200)
        fig.axes[0].text(1.5, 0.5, "beyond the right edge", transform=fig.axes[0].transAxes)
        self.assert_refused(fig, "axes 0 x label", "axes 0 text", "beyond the right edge")

    def test_titles_of_neighbouring_panels_must_not_overlap(self):
        fig, axes = plt.subplots(1, 2, figsize=(8, 3))
        for ax in axes:
            ax.set_title("a title far too long to share the width of the figure with its neighbour", fontsize=9)
        fig.tight_layout()
        self.assert_refused(fig, "axes 0 title", "overlaps axes 1 title")

    def test_the_check_is_made_at_the_saved_resolution(self):
        for dpi in (50, 90, 150):
            with self.subTest(dpi=dpi):
                fig = normal_figure()
                fig.axes[0].set_title(LONG, fontsize=9)
                fig.tight_layout()
                with self.assertRaises(FigureTextError):
                    save_checked(fig, self.path, dpi=dpi)
                save_checked(normal_figure(), self.path, dpi=dpi)

    def test_the_figure_is_closed_either_way(self):
        before = len(plt.get_fignums())
        save_checked(normal_figure(), self.path, dpi=80)
        fig = normal_figure()
        fig.axes[0].set_title(LONG, fontsize=9)
        with self.assertRaises(FigureTextError):
            save_checked(fig, self.path, dpi=80)
        self.assertEqual(len(plt.get_fignums()), before)


if __name__ == "__main__":
    unittest.main()
