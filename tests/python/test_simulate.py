"""railjoint.simulate against `railjoint simulate --json --csv` on the same
scene: as_dict() equal to the last digit but for the measured wall time, the
trajectory's arrays equal to the CSV's cells as the CLI writes them, each
field equal to its JSON key."""

import json
from pathlib import Path

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
