"""railjoint.load_scene and railjoint.Scene read scenes through the CLI's
scene reader: the same keys and defaults, and for bad input a ValueError with
the CLI's own message (the file, or "scene", the key and the allowed range)."""

import pytest

from conftest import cli_error, cli_json, scene_path


def test_a_loaded_scene_holds_the_keys_the_cli_reads(railjoint):
    path = scene_path("pressure/table6_1.toml")
    expected = cli_json("pressure", path, "--set", "wheel.speed=30")["scene"]
    scene = railjoint.load_scene(path, overrides={"wheel.speed": 30.0})
    print(scene, scene.as_dict()["wheel"])
    assert scene.as_dict() == expected


def test_overrides_take_the_set_syntax(railjoint):
    path = scene_path("default.toml")
    expected = cli_json("analytic", path, "--set", "joint.kind=step", "--set", "joint.step_height=0.002",
                        "--unset", "joint.theta_deg", "--unset", "joint.beta")
    scene = railjoint.load_scene(path, overrides={"joint.kind": "step", "joint.step_height": 0.002},
                                 unsets=["joint.theta_deg", "joint.beta"])
    assert railjoint.analytic(scene).as_dict() == expected


@pytest.mark.parametrize("assignment, python_value", [
    ("wheel.y=15", 15),                # out of range, with the unit hint
    ("wheel.speed=nan", float("nan")),  # not finite
    ("wheel.speeed=30", 30.0),         # an unknown key, the meant one named
    ("wheel.mass=heavy", "heavy"),     # a text for a number
    ("joint.kind=square", "square"),   # not one of the choices
    ("whel.y=0.01", 0.01),             # an unknown section
])
def test_a_bad_override_raises_the_cli_message(railjoint, assignment, python_value):
    path = scene_path("default.toml")
    # `pressure` reads every section, so its message is the scene reader's
    # (`analytic` refuses a --set into a section it does not read first).
    expected = cli_error("pressure", path, "--set", assignment)
    key = assignment.split("=")[0]
    with pytest.raises(ValueError) as raised:
        railjoint.load_scene(path, overrides={key: python_value})
    print(raised.value)
    assert str(raised.value) == expected


def test_a_missing_file_raises_the_cli_message(railjoint, tmp_path):
    path = str(tmp_path / "no_such.toml")
    with pytest.raises(ValueError) as raised:
        railjoint.load_scene(path)
    assert str(raised.value) == cli_error("analytic", path)


def test_a_file_that_is_not_toml_raises_the_cli_message(railjoint, tmp_path):
    path = tmp_path / "broken.toml"
    path.write_text("[wheel]\nspeed = = 3\n")
    with pytest.raises(ValueError) as raised:
        railjoint.load_scene(path)
    assert str(raised.value) == cli_error("analytic", path)


def scene_file_of(tmp_path, sections):
    """The scene file the dicts stand for, written as a user would write it."""
    lines = []
    for section, keys in sections.items():
        lines.append(f"[{section}]")
        lines += [f"{key} = {value!r}".replace("'", '"') for key, value in keys.items()]
    path = tmp_path / "scene.toml"
    path.write_text("\n".join(lines) + "\n")
    return str(path)


@pytest.mark.parametrize("sections", [
    {"joint": {"theta_deg": 45.0, "beta": 0.02}, "wheel": {"y": 0.012, "speed": 30.0}},
    {"joint": {"kind": "step", "step_height": 0.001}, "wheel": {"y": 0.0}},
    {"wheel": {"width": 0.03, "y": 0.005}, "sim": {"time_step": 5e-5}},
])
def test_a_scene_from_dicts_is_the_scene_file_they_describe(railjoint, tmp_path, sections):
    path = scene_file_of(tmp_path, sections)
    expected = cli_json("analytic", path)
    got = railjoint.analytic(railjoint.Scene(**sections)).as_dict()
    # The file names differ ("scene" for dicts): all else is the same.
    for report in (expected, got):
        del report["scene"]["file"], report["scene"]["name"]
    assert got == expected


@pytest.mark.parametrize("sections", [
    {"wheel": {"y": 15}},
    {"wheel": {"radius": 0.01}},
    {"joint": {"theta_deg": 120.0}},
    {"joint": {"crooked": 1.0}},
    {"weel": {"y": 0.0}},
])
def test_a_bad_key_in_a_dict_raises_the_cli_message_naming_scene(railjoint, tmp_path, sections):
    path = scene_file_of(tmp_path, sections)
    expected = cli_error("analytic", path).replace(path, "scene", 1)
    with pytest.raises(ValueError) as raised:
        railjoint.analytic(railjoint.Scene(**sections))
    print(raised.value)
    assert str(raised.value) == expected


def test_a_case_outside_the_model_raises_when_a_command_checks_it(railjoint, tmp_path):
    # |y_w| > b_t: every key is in range, the model refuses the combination.
    sections = {"joint": {"half_width": 0.01}, "wheel": {"y": 0.015}}
    path = scene_file_of(tmp_path, sections)
    expected = cli_error("analytic", path).replace(path, "scene", 1)
    scene = railjoint.Scene(**sections)
    with pytest.raises(ValueError) as raised:
        railjoint.analytic(scene)
    assert str(raised.value) == expected


def test_a_value_no_scene_key_takes_is_refused_with_its_key(railjoint):
    with pytest.raises(TypeError) as raised:
        railjoint.Scene(wheel={"y": [0.01, 0.02]})
    print(raised.value)
    assert str(raised.value).startswith("scene: key 'wheel.y': takes a number, a text or True/False")
