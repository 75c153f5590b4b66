"""Shared by the Python module's tests: the built `railjoint` executable
(RAILJOINT_EXE, set by ctest) run on the same scene, so every expected value
is the CLI's own output of this build, never a number restated here."""

import csv
import json
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("RAILJOINT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXE = os.environ.get("RAILJOINT_EXE", str(SOURCE_DIR / "build" / "scenes" / "railjoint"))


def scene_path(relative):
    return str(SOURCE_DIR / "scenes" / relative)


def run_cli(*args, expect_status=0):
    """Runs railjoint with args; returns (stdout, stderr)."""
    done = subprocess.run([EXE, *map(str, args)], capture_output=True, text=True, cwd=SOURCE_DIR)
    assert done.returncode == expect_status, f"railjoint {' '.join(map(str, args))}: {done.returncode}\n{done.stderr}"
    return done.stdout, done.stderr


def cli_json(*args):
    return json.loads(run_cli(*args, "--json")[0])


def cli_error(*args):
    """The one-line message the CLI prints for bad input (exit 2), without its 'railjoint: error: ' prefix."""
    _, stderr = run_cli(*args, expect_status=2)
    line = stderr.strip().splitlines()[-1]
    return line.split("error: ", 1)[1] if "error: " in line else line


def read_csv_text(path):
    """Header and rows of a CSV file, cells as the CLI wrote them."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def cell_as_cli_writes(value, significant_digits):
    """A float as the CLI's CSV writer writes it: std::ostream's default format at
    `significant_digits` (printf's %g), no sign on zero, NaN as an empty cell."""
    if value != value:
        return ""
    return "%.*g" % (significant_digits, value + 0.0)


def without_wall_times(report):
    """A report without its measured wall times (they differ from run to run)."""
    if isinstance(report, dict):
        return {k: without_wall_times(v) for k, v in report.items() if k != "wall_time_s"}
    if isinstance(report, list):
        return [without_wall_times(v) for v in report]
    return report


@pytest.fixture(scope="session")
def railjoint():
    import railjoint as module
    return module
