"""railjoint.analytic against `railjoint analytic --json` on the same scene:
as_dict() equal to the last digit, and each field equal to its JSON key."""

from pathlib import Path

import pytest

from conftest import SOURCE_DIR, cli_json

VALIDATION_SCENES = sorted(str(p) for p in (SOURCE_DIR / "scenes" / "validation").glob("*.toml"))
SCENES = [str(SOURCE_DIR / "scenes" / "default.toml")] + VALIDATION_SCENES

# Each field and the JSON key it reports.
FIELDS = {
    "scenario": "scenario", "on_landing": "on_landing", "y_t_m": "y_t_m", "governing_y_m": "governing_y_m",
    "configuration": "configuration", "line_contact_length_m": "line_contact_length_m", "x_A_m": "x_A_m",
    "x_A_thesis_m": "x_A_thesis_m", "alpha_rad": "alpha_rad", "alpha_thesis_rad": "alpha_thesis_rad",
    "impact_x_m": "impact_x_m", "impact_z_m": "impact_z_m", "contact_A_m": "contact_A_m",
    "contact_B_m": "contact_B_m", "zdot_before_m_per_s": "zdot_before_m_per_s",
    "zdot_after_m_per_s": "zdot_after_m_per_s", "exact_Ns": "exact_Ns", "thesis_Ns": "thesis_Ns",
    "small_angle_Ns": "small_angle_Ns",
}


@pytest.mark.parametrize("path", SCENES, ids=lambda p: Path(p).stem)
def test_as_dict_is_the_cli_json(railjoint, path):
    expected = cli_json("analytic", path)
    got = railjoint.analytic(railjoint.load_scene(path)).as_dict()
    print(Path(path).stem, got["exact_Ns"], expected["exact_Ns"])
    assert got == expected


@pytest.mark.parametrize("path", SCENES, ids=lambda p: Path(p).stem)
def test_every_field_is_its_json_value(railjoint, path):
    prediction = railjoint.analytic(railjoint.load_scene(path))
    report = prediction.as_dict()
    assert set(FIELDS.values()) <= set(report), "a field names a key the JSON does not have"
    for field, key in FIELDS.items():
        value = getattr(prediction, field)
        expected = report[key]
        if isinstance(value, tuple):
            value = list(value)
        assert value == expected, f"{field}: {value!r} != {expected!r}"


def test_overrides_reach_the_model(railjoint):
    path = str(SOURCE_DIR / "scenes" / "default.toml")
    expected = cli_json("analytic", path, "--set", "wheel.speed=10", "--set", "joint.theta_deg=60")
    scene = railjoint.load_scene(path, overrides={"wheel.speed": 10, "joint.theta_deg": 60.0})
    assert railjoint.analytic(scene).as_dict() == expected


def test_the_docstring_is_the_cli_help(railjoint):
    from conftest import run_cli
    help_text, _ = run_cli("analytic", "--help")
    doc = railjoint.analytic.__doc__
    print(doc)
    for line in help_text.strip().splitlines():
        assert line.strip() in doc
    for field in FIELDS:
        assert getattr(railjoint.Prediction, field).__doc__, f"{field} has no docstring"


@pytest.mark.parametrize("path", SCENES[:3], ids=lambda p: Path(p).stem)
def test_the_time_history_is_the_cli_csv(railjoint, path, tmp_path):
    from conftest import cell_as_cli_writes, read_csv_text, run_cli
    csv_path = tmp_path / "history.csv"
    run_cli("analytic", path, "--csv", csv_path, "--before-mm", 8, "--after-mm", 9, "--samples", 301)
    header, rows = read_csv_text(csv_path)
    history = railjoint.analytic(railjoint.load_scene(path)).time_history(before_mm=8, after_mm=9, samples=301)
    assert list(history) == header
    for c, name in enumerate(header):
        # analytic --csv writes 12 significant digits (scenes/cli/analytic_command.cpp)
        assert [cell_as_cli_writes(float(v), 12) for v in history[name]] == [row[c] for row in rows], name


def test_a_time_history_off_the_rails_raises_the_cli_message(railjoint):
    from conftest import cli_error
    path = SCENES[0]
    # The CLI's message, naming the Python argument instead of the CLI's flag.
    expected = cli_error("analytic", path, "--csv", "/dev/null", "--before-mm", 5000).replace("--before-mm", "before_mm")
    with pytest.raises(ValueError) as raised:
        railjoint.analytic(railjoint.load_scene(path)).time_history(before_mm=5000)
    print(raised.value)
    assert str(raised.value) == expected


@pytest.mark.parametrize("argument", ["before_mm", "after_mm"])
@pytest.mark.parametrize("value", [-5.0, float("nan"), float("inf")])
def test_a_time_history_before_the_impact_or_not_finite_is_refused_as_the_cli_does(railjoint, argument, value):
    # Before: before_mm=-5, after_mm=-5 returned 2001 samples running backwards (t from 1e-4 to -1e-4 s).
    from conftest import cli_error
    path = SCENES[0]
    flag = "--" + argument.replace("_", "-")
    expected = cli_error("analytic", path, "--csv", "/dev/null", flag, value)
    print(expected)
    with pytest.raises(ValueError) as raised:
        railjoint.analytic(railjoint.load_scene(path)).time_history(**{argument: value})
    print(raised.value)
    # The CLI's check ("must be a finite number in [0, 100000] mm, got ..."), naming the argument.
    cli_check = expected.split(flag + ": ", 1)[1].split(", got ")[0]
    assert str(raised.value).startswith(f"time_history: key '{argument}': {cli_check}, got ")


@pytest.mark.parametrize("path, sets", [
    (str(SOURCE_DIR / "scenes" / "geometry" / "60e1_cone.toml"), {}),
    (str(SOURCE_DIR / "scenes" / "validation" / "cylinder_config3.toml"), {"joint.gap": 0.006}),
], ids=["60e1_cone", "cylinder_config3_gap"])
def test_a_time_history_has_no_nan(railjoint, path, sets):
    """Issue 40, item 6: where the thesis's jump has no real value (thesis_Ns None)
    its linearised path was NaN in 1,820-2,182 cells. Those columns are None
    (as the CLI's cells are empty), every other one all numbers."""
    import numpy as np
    prediction = railjoint.analytic(railjoint.load_scene(path, overrides=sets))
    assert prediction.thesis_Ns is None
    history = prediction.time_history()
    assert history["z_linear_m"] is None and history["zdot_linear_m_per_s"] is None
    for name, values in history.items():
        if values is not None:
            assert not np.isnan(values).any(), name
