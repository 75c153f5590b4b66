"""The results' tables (issue 39, item 4): the columns reach NumPy from the
table the CLI's --csv writes, with no text between; the same columns as a
pandas.DataFrame; a force run's P0, P1, P2 and its other numbers as
attributes of the Simulation, each equal to `simulate --json`'s field. Every
expected value is the CLI's output for the same scene (conftest.py)."""

import copy
import json
import pickle
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas
import pytest

from conftest import SOURCE_DIR, cell_as_cli_writes, read_csv_text, run_cli

FORCE_SCENES = [str(SOURCE_DIR / "scenes" / "forces" / f"{name}.toml")
                for name in ("lumped_track", "discrete_track", "bogie")]
CSV_DIGITS = 12  # simulate --csv and analytic --csv write 12 significant digits (scenes/cli/*_command.cpp)

# Simulation attribute: its key under the JSON's sim.forces (ForceRunNumbers reads the same outcome).
FORCE_FIELDS = {
    "p0_N": ("static_N",), "p1_N": ("p1_N",), "p1_time_s": ("p1_time_s",), "p2_N": ("p2_N",),
    "p2_time_s": ("p2_time_s",), "jenkins_p1_N": ("jenkins_p1_N",), "jenkins_p2_N": ("jenkins_p2_N",),
    "p2_rail_seat_N": ("p2_rail_seat_N",), "rail_seat_peak_N": ("rail_seat_peak_N",),
    "ballast_peak_N": ("ballast_peak_N",), "p2_after_p1": ("p2_after_p1",),
    "p2_across_flight": ("p2_across_flight",), "flight_count": ("flights",), "flight_time_s": ("flight_time_s",),
    "longest_flight_s": ("longest_flight_s",), "track_mass_p1_kg": ("jenkins", "track_mass_p1_kg"),
    "track_mass_p2_kg": ("jenkins", "track_mass_p2_kg"),
    "track_stiffness_N_per_m": ("jenkins", "track_stiffness_N_per_m"),
    "track_damping_N_s_per_m": ("jenkins", "track_damping_N_s_per_m"),
}


def bits(value):
    """A float's 64 bits (so 0.0 and -0.0 differ, as == would not say)."""
    return struct.pack("<d", value)


@pytest.fixture(scope="module", params=FORCE_SCENES, ids=lambda p: Path(p).stem)
def force_run(request, railjoint, tmp_path_factory):
    """(the Simulation, simulate --json, the CSV's header and rows) of one force scene, each run once."""
    csv_path = tmp_path_factory.mktemp("cli") / "run.csv"
    stdout, _ = run_cli("simulate", request.param, "--json", "--csv", csv_path)
    header, rows = read_csv_text(csv_path)
    return railjoint.simulate(railjoint.load_scene(request.param)), json.loads(stdout), header, rows


def test_a_force_runs_arrays_are_its_csv_columns(force_run):
    """Every array, written as the CLI writes a cell, is that cell; the arrays
    are the doubles themselves: the first time is the JSON's start_time_s
    (written with every digit) bit for bit."""
    run, report, header, rows = force_run
    trajectory = run.trajectory
    assert list(trajectory) == header
    for c, name in enumerate(header):
        column = trajectory[name]
        assert column.dtype == np.float64 and not column.flags.writeable and len(column) == len(rows)
        written = [cell_as_cli_writes(float(v), CSV_DIGITS) for v in column]
        assert written == [row[c] for row in rows], f"column {name}"
    print(Path(report["scene"]["file"]).stem, len(rows), "rows", len(header), "columns")
    assert bits(trajectory["t_s"][0]) == bits(report["sim"]["start_time_s"])
    assert not np.any(np.signbit(trajectory["t_s"]) & (trajectory["t_s"] == 0.0)), "a -0.0 (the CSV writes 0)"


def test_the_trajectory_is_made_once(force_run):
    run = force_run[0]
    assert run.trajectory is run.trajectory


def test_the_force_attributes_are_the_json_fields_bit_for_bit(force_run):
    run, report, _, _ = force_run
    forces = report["sim"]["forces"]
    for attribute, path in FORCE_FIELDS.items():
        expected = forces
        for key in path:
            expected = expected[key]
        got = getattr(run, attribute)
        print(f"{attribute:24s} {got!r:24s} {expected!r}")
        if expected is None or isinstance(expected, bool):
            assert got is expected, attribute
        elif isinstance(expected, int) and attribute == "flight_count":
            assert type(got) is int and got == expected, attribute
        else:
            assert type(got) is float and bits(got) == bits(float(expected)), attribute


def test_a_rigid_tracks_absent_numbers_are_none(railjoint):
    """On a rigid track the run has no P2, no supports and no track reading:
    None, as the JSON's null; P0 and P1 are there."""
    path = str(SOURCE_DIR / "scenes" / "forces" / "lumped_track.toml")
    run = railjoint.simulate(railjoint.load_scene(path, overrides={"track.model": "rigid"}))
    forces = run.as_dict()["sim"]["forces"]
    for attribute in ("p2_N", "p2_time_s", "p2_rail_seat_N", "rail_seat_peak_N", "ballast_peak_N",
                      "track_mass_p1_kg", "track_stiffness_N_per_m"):
        assert getattr(run, attribute) is None, attribute
    assert run.p0_N == forces["static_N"] and run.p1_N == forces["p1_N"]
    assert run.p1_N > run.p0_N


@pytest.mark.parametrize("mode", ["kinematic", "inertial"])
def test_off_a_force_run_every_force_attribute_is_none(railjoint, mode):
    run = railjoint.simulate(railjoint.Scene(sim={"mode": mode}))
    assert "forces" not in run.as_dict()["sim"]
    for attribute in FORCE_FIELDS:
        assert getattr(run, attribute) is None, attribute
        assert getattr(railjoint.Simulation, attribute).__doc__, f"{attribute} has no docstring"


def test_the_trajectory_frame_is_the_arrays(force_run):
    run = force_run[0]
    frame = run.trajectory_frame()
    print(frame.shape, set(frame.dtypes))
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == list(run.trajectory)
    assert all(dtype == np.float64 for dtype in frame.dtypes)
    for name, column in run.trajectory.items():
        assert np.array_equal(frame[name].to_numpy(), column, equal_nan=True), name
    # The frame is the caller's own: changing it leaves the arrays as they were.
    first = run.trajectory["z_m"][0]
    frame.loc[0, "z_m"] = 1.0
    assert run.trajectory["z_m"][0] == first


def test_a_time_history_frame_keeps_a_column_without_values_as_nan(railjoint, tmp_path):
    """On a 60E1 head the thesis's jump has no real value: --csv leaves the
    linearised columns empty, time_history() gives None, the frame a float64
    column of NaN (what pandas.read_csv makes of a column of empty cells)."""
    path = str(SOURCE_DIR / "scenes" / "default.toml")
    csv_path = tmp_path / "history.csv"
    run_cli("analytic", path, "--set", "joint.rail_profile=60E1", "--csv", csv_path, "--samples", 101)
    prediction = railjoint.analytic(railjoint.load_scene(path, overrides={"joint.rail_profile": "60E1"}))
    history = prediction.time_history(samples=101)
    frame = prediction.time_history_frame(samples=101)
    expected = pandas.read_csv(csv_path)
    print(frame.dtypes.to_dict())
    assert history["z_linear_m"] is None and history["zdot_linear_m_per_s"] is None
    assert list(frame.columns) == list(expected.columns) == list(history)
    assert all(dtype == np.float64 for dtype in frame.dtypes)
    assert frame["z_linear_m"].isna().all() and expected["z_linear_m"].isna().all()
    header, rows = read_csv_text(csv_path)
    for c, name in enumerate(header):
        assert [cell_as_cli_writes(v, CSV_DIGITS) for v in frame[name]] == [row[c] for row in rows], name


def test_the_traversal_frame_is_the_arrays_and_no_zero_has_a_sign(railjoint):
    """While the whole patch bears on one rail its pressure is constant:
    dP/dx is computed as -0.0 in about a fifth of table6_1's rows. The CSV
    writes 0 there; the arrays hold 0.0, as the CSV and the JSON say."""
    run = railjoint.pressure(railjoint.load_scene(str(SOURCE_DIR / "scenes" / "pressure" / "table6_1.toml")))
    frame = run.traversal_frame()
    assert list(frame.columns) == list(run.traversal)
    for name, column in run.traversal.items():
        assert frame[name].dtype == np.float64 and np.array_equal(frame[name].to_numpy(), column), name
        assert not np.any(np.signbit(column) & (column == 0.0)), name
    rate = run.traversal["rate_Pa_per_s"]
    print(int(np.sum(rate == 0.0)), "of", len(rate), "rows with dP/dt = 0")
    assert np.sum(rate == 0.0) > 0


@pytest.mark.parametrize("how", ["pickle", "deepcopy"])
def test_a_copied_force_run_keeps_its_columns_frame_and_forces(force_run, how):
    run = force_run[0]
    twin = pickle.loads(pickle.dumps(run)) if how == "pickle" else copy.deepcopy(run)
    assert list(twin.trajectory) == list(run.trajectory)
    for name, column in run.trajectory.items():
        assert np.array_equal(twin.trajectory[name], column, equal_nan=True), name
    pandas.testing.assert_frame_equal(twin.trajectory_frame(), run.trajectory_frame(), check_exact=True)
    for attribute in FORCE_FIELDS:
        assert getattr(twin, attribute) == getattr(run, attribute), attribute


def test_without_pandas_a_frame_says_what_to_install(railjoint):
    """A Python without pandas: trajectory_frame() raises ImportError naming
    pandas and the arrays that need none (.trajectory still works)."""
    probe = """
import sys
sys.modules["pandas"] = None  # import pandas now raises ImportError
import railjoint
run = railjoint.simulate(railjoint.Scene())
print(len(run.trajectory["t_s"]))
try:
    run.trajectory_frame()
except ImportError as error:
    print(error)
"""
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True)
    print(done.stdout, done.stderr[-2000:])
    rows, message = done.stdout.strip().splitlines()
    assert int(rows) > 0
    assert message.startswith("railjoint.Simulation.trajectory_frame() needs pandas")
    assert "python3-pandas" in message and "Simulation.trajectory" in message
