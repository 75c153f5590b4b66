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


def cylinder_tread(radius_m):
    """A measured tread that is a cylinder of radius_m: (y, r) every 5 mm over +-20 mm."""
    return "y_m,r_m\n" + "".join(f"{-0.02 + i * 0.005},{radius_m}\n" for i in range(9))


def write_profile_scene(folder, radius_m):
    """The issue's scene: prof/tread.toml names "tread.csv", beside it (a 20 mm wide wheel 15 mm
    off the centre line: scenario 2, whose jump depends on the radius)."""
    (folder / "prof").mkdir()
    (folder / "prof" / "tread.csv").write_text(cylinder_tread(radius_m))
    (folder / "prof" / "tread.toml").write_text('[wheel]\nprofile = "tread.csv"\nwidth = 0.02\ny = 0.015\n')


def cylinder_exact_Ns(radius_m):
    """The jump of the same wheel as a plain cylinder, by the CLI (no profile file)."""
    return cli_json("analytic", scene_path("default.toml"), "--set", "wheel.width=0.02", "--set", "wheel.y=0.015",
                    "--set", f"wheel.radius={radius_m}")["exact_Ns"]


def test_a_scenes_profile_is_read_once_from_its_folder(railjoint, tmp_path, monkeypatch):
    # Issue 40 item 2: a Scene read its tread from the current folder when a
    # command first checked it, so after os.chdir it read another file.
    write_profile_scene(tmp_path, 0.475)
    (tmp_path / "elsewhere").mkdir()
    (tmp_path / "elsewhere" / "tread.csv").write_text(cylinder_tread(0.3))  # a decoy of the same name
    monkeypatch.chdir(tmp_path)
    scene = railjoint.load_scene("prof/tread.toml")
    monkeypatch.chdir(tmp_path / "elsewhere")
    expected = cylinder_exact_Ns(0.475)
    got = railjoint.analytic(scene).as_dict()["exact_Ns"]
    print(f"0.475 m cylinder {expected} N s, the Scene after chdir {got} N s, 0.3 m decoy {cylinder_exact_Ns(0.3)} N s")
    assert got == pytest.approx(expected, rel=1e-9)  # a measured cylinder is the cylinder to rounding
    # Read once, when the Scene is made: the file gone before any command, the Scene still has its content.
    fresh = railjoint.load_scene(tmp_path / "prof" / "tread.toml")
    (tmp_path / "prof" / "tread.csv").unlink()
    assert railjoint.analytic(fresh).as_dict()["exact_Ns"] == got


def test_an_unpickled_scene_reads_its_profile_from_the_scenes_folder(railjoint, tmp_path, monkeypatch):
    # Found by the rerun of issue 40's reproducers: pickle carried the
    # scene's text and file name but not the folders, so an unpickled Scene
    # read "tread.csv" from the folder current then (the 0.3 m decoy here:
    # 1125.08 N s where the scene's own tread gives 1275.05 on that rerun's scene).
    import pickle
    write_profile_scene(tmp_path, 0.475)
    (tmp_path / "elsewhere" / "prof").mkdir(parents=True)
    (tmp_path / "elsewhere" / "prof" / "tread.csv").write_text(cylinder_tread(0.3))  # a decoy where the name leads
    monkeypatch.chdir(tmp_path)
    scene = railjoint.load_scene("prof/tread.toml")
    state = pickle.dumps(scene)
    monkeypatch.chdir(tmp_path / "elsewhere")
    got = railjoint.analytic(pickle.loads(state)).as_dict()["exact_Ns"]
    print(f"0.475 m cylinder {cylinder_exact_Ns(0.475)} N s, unpickled elsewhere {got} N s")
    assert got == pytest.approx(cylinder_exact_Ns(0.475), rel=1e-9)
