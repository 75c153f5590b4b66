"""railjoint.simulate against `railjoint simulate --json --csv` on the same
scene: as_dict() equal to the last digit but for the measured wall time, the
trajectory's arrays equal to the CSV's cells as the CLI writes them, each
field equal to its JSON key."""

import json
from pathlib import Path

import numpy as np
import pytest

from conftest import SOURCE_DIR, cell_as_cli_writes, cli_error, read_csv_text, run_cli, without_wall_times

SCENES = [str(SOURCE_DIR / "scenes" / name) for name in
          ("default.toml", "validation/step_down.toml", "validation/cylinder_config5.toml")]
CSV_DIGITS = 12  # simulate --csv writes 12 significant digits (scenes/cli/simulate_command.cpp)


def cli_run(path, tmp_path, *sets):
    csv_path = tmp_path / "run.csv"
    stdout, _ = run_cli("simulate", path, *sets, "--json", "--csv", csv_path)
    return json.loads(stdout), csv_path


@pytest.mark.parametrize("path", SCENES, ids=lambda p: Path(p).stem)
def test_as_dict_and_trajectory_are_the_cli_json_and_csv(railjoint, path, tmp_path):
    expected, csv_path = cli_run(path, tmp_path)
    run = railjoint.simulate(railjoint.load_scene(path))
    got = run.as_dict()
    print(Path(path).stem, got["sim"]["impulse_Ns"], expected["sim"]["impulse_Ns"])
    assert without_wall_times(got) == without_wall_times(expected)

    header, rows = read_csv_text(csv_path)
    assert list(run.trajectory) == header
    for c, name in enumerate(header):
        column = run.trajectory[name]
        assert len(column) == len(rows)
        written = [cell_as_cli_writes(float(v), CSV_DIGITS) for v in column]
        assert written == [row[c] for row in rows], f"column {name}"


def test_an_inertial_run_is_the_cli_json(railjoint, tmp_path):
    path = str(SOURCE_DIR / "scenes" / "default.toml")
    expected, _ = cli_run(path, tmp_path, "--set", "sim.mode=inertial")
    got = railjoint.simulate(railjoint.load_scene(path, overrides={"sim.mode": "inertial"})).as_dict()
    print(got["sim"]["mode"], len(got["sim"]["flights"]))
    assert without_wall_times(got) == without_wall_times(expected)


FIELDS = {  # field: path of its JSON key
    "impact_found": ("sim", "impact_found"), "verdict": ("sim", "verdict"),
    "verdict_reason": ("sim", "verdict_reason"), "jump_Ns": ("sim", "impulse_Ns"),
    "jump_from_contacts_Ns": ("sim", "impulse_from_contacts_Ns"), "impact_time_s": ("sim", "impact_time_s"),
    "impact_x_m": ("sim", "impact_x_m"), "zdot_before_m_per_s": ("sim", "zdot_before_m_per_s"),
    "zdot_after_m_per_s": ("sim", "zdot_after_m_per_s"), "contact_struck_m": ("sim", "contact_struck_m"),
    "contact_left_m": ("sim", "contact_left_m"), "max_penetration_m": ("sim", "max_penetration_m"),
    "liftoff": ("sim", "liftoff"), "liftoff_time_s": ("sim", "liftoff_time_s"),
    "second_impact": ("sim", "second_impact"), "second_impact_time_s": ("sim", "second_impact_time_s"),
    "second_jump_Ns": ("sim", "second_impulse_Ns"), "preload_N": ("sim", "preload_N"), "steps": ("sim", "steps"),
    "refined_steps": ("sim", "refined_steps"), "wall_time_s": ("sim", "wall_time_s"), "mode": ("sim", "mode"),
    "error_exact": ("error", "exact"), "error_thesis": ("error", "thesis"),
    "error_small_angle": ("error", "small_angle"),
}


@pytest.mark.parametrize("path", SCENES, ids=lambda p: Path(p).stem)
def test_every_field_is_its_json_value(railjoint, path):
    run = railjoint.simulate(railjoint.load_scene(path))
    report = run.as_dict()
    for field, (block, key) in FIELDS.items():
        value = getattr(run, field)
        if isinstance(value, tuple):
            value = list(value)
        assert value == report[block][key], f"{field}: {value!r} != {report[block][key]!r}"
    assert run.analytic.as_dict() == report["analytic"]
    assert run.analytic_as_simulated.as_dict() == report["analytic_as_simulated"]


def test_a_bad_setting_raises_the_cli_message(railjoint):
    path = str(SOURCE_DIR / "scenes" / "default.toml")
    # disc_half_width above the margin's limit: refused by the simulation, not the reader.
    expected = cli_error("simulate", path, "--set", "sim.margin=0.01")
    scene = railjoint.load_scene(path, overrides={"sim.margin": 0.01})
    with pytest.raises(ValueError) as raised:
        railjoint.simulate(scene)
    print(raised.value)
    assert str(raised.value) == expected


def test_the_docstrings_are_the_cli_help_and_units(railjoint):
    help_text, _ = run_cli("simulate", "--help")
    doc = railjoint.simulate.__doc__
    for line in help_text.strip().splitlines():
        assert line.strip() in doc
    for field in list(FIELDS) + ["trajectory", "analytic", "analytic_as_simulated"]:
        assert getattr(railjoint.Simulation, field).__doc__, f"{field} has no docstring"


def test_a_force_runs_trajectory_starts_at_the_static_load(railjoint):
    """Issue 40, item 15: .trajectory's first row had contact_force_z_N = 0 and
    contacts = 0; it holds the static load on the rail, P0 = wheel_load + M g
    = 112.5 kN + 750 kg x 9.81 m/s^2 (scenes/forces/lumped_track.toml)."""
    run = railjoint.simulate(railjoint.load_scene(str(SOURCE_DIR / "scenes" / "forces" / "lumped_track.toml")))
    p0_N = 112.5e3 + 750.0 * 9.81
    force = run.trajectory["contact_force_z_N"]
    print(force[:3], run.trajectory["contacts"][:3], p0_N)
    assert abs(force[0] - p0_N) <= 1e-6 * p0_N
    assert run.trajectory["contacts"][0] >= 1


@pytest.mark.parametrize("track", ["lumped_track", "discrete_track"])
def test_a_force_runs_supports_are_numpy_histories(railjoint, track):
    """Issue 41: the track's support forces reach Python as NumPy arrays, one
    value per trajectory row. The lumped track has one support; the discrete
    track the six sleepers nearest the joint, at +-0.3, +-0.9, +-1.5 m (the
    joint midway between sleepers 0.6 m apart). The peak support's histories
    are --csv's rail_seat_N and ballast_N, its static
    forces the JSON's; before the wheel reaches the joint every support
    carries at least its weight's share (compression +)."""
    run = railjoint.simulate(railjoint.load_scene(str(SOURCE_DIR / "scenes" / "forces" / f"{track}.toml")))
    supports = run.supports
    rows = len(run.trajectory["t_s"])
    report = run.as_dict()["sim"]["forces"]
    assert len(supports) == (1 if track == "lumped_track" else 6)
    for s in supports:
        assert isinstance(s["rail_seat_N"], np.ndarray) and not s["rail_seat_N"].flags.writeable
        assert s["rail_seat_N"].dtype == np.float64 and len(s["rail_seat_N"]) == rows
        assert len(s["ballast_N"]) == rows
    if track == "discrete_track":
        assert [s["x_m"] for s in supports] == pytest.approx([-1.5, -0.9, -0.3, 0.3, 0.9, 1.5], abs=1e-12)
        # At the start the sleeper nearest the wheel is compressed; those
        # more than 3 pi / (4 beta_f) = 1.9 m ahead may be in tension (a beam
        # on an elastic foundation lifts there: -1.5 kN at x = +0.9 m, 2.5 m ahead).
        start = run.trajectory["x_m"][0]
        nearest = min(supports, key=lambda s: abs(s["x_m"] - start))
        assert nearest["rail_seat_N"][0] > 0.1 * report["static_N"]
        peak = next(s for s in supports if s["x_m"] == report["rail_seat_peak_x_m"])
    else:
        assert supports[0]["x_m"] is None
        peak = supports[0]
    assert peak["rail_seat_static_N"] == report["rail_seat_static_N"]
    assert peak["rail_seat_N"].max() == report["rail_seat_peak_N"]
    # .trajectory holds --csv's columns with every digit: the same doubles.
    assert np.array_equal(peak["rail_seat_N"], run.trajectory["rail_seat_N"])
    assert np.array_equal(peak["ballast_N"], run.trajectory["ballast_N"])


def test_a_rigid_tracks_supports_are_none(railjoint):
    run = railjoint.simulate(railjoint.load_scene(str(SOURCE_DIR / "scenes" / "default.toml")))
    assert run.supports is None
