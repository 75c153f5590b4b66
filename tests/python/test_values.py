"""Python values as scene values (issue 40, items 1 and 7): a NumPy scalar, a
0-d or a one-element array is the value it holds, never its integer part; a
value no scene key takes is a TypeError naming the key; True/False only where
a key is boolean; a text with a line break never becomes two --set lines."""

import numpy as np
import pytest

from conftest import scene_path

# The reference is the plain Python float, whose path the other tests compare
# with the CLI: every NumPy form of 0.03 must give the same jump.
BETA = 0.03


def exact_jump(railjoint, beta):
    return railjoint.analytic(railjoint.Scene(joint={"beta": beta})).exact_Ns


@pytest.mark.parametrize("value", [np.array([BETA]), np.array(BETA), np.float64(BETA), np.array([[BETA]])],
                         ids=["one_element_array", "0d_array", "float64", "1x1_array"])
def test_a_numpy_float_is_its_value_never_its_integer_part(railjoint, value):
    # Before: np.array([0.03]) went through __index__/__int__ and ran at beta 0 (exact_Ns 0.0).
    got = exact_jump(railjoint, value)
    print(type(value).__name__, got)
    assert got == exact_jump(railjoint, BETA)
    assert got > 0.0


def test_a_float32_is_its_own_value(railjoint):
    # float32 cannot hold 0.03: its value is float(np.float32(0.03)), not 0.
    assert exact_jump(railjoint, np.float32(BETA)) == exact_jump(railjoint, float(np.float32(BETA)))


@pytest.mark.parametrize("value", [np.int64(400), np.array([400], dtype=np.int32), np.uint16(400)])
def test_a_numpy_integer_sets_an_integer_key(railjoint, value):
    scene = railjoint.Scene(contact_patch={"steps": value})
    assert scene.as_dict()["contact_patch"]["steps"] == 400


def test_a_numpy_float_for_an_integer_key_is_refused_as_a_float_in_a_file_is(railjoint):
    # No truncation: 400.7 is not read as 400.
    with pytest.raises(ValueError) as raised:
        railjoint.Scene(contact_patch={"steps": np.array([400.7])})
    print(raised.value)
    assert str(raised.value).startswith("scene: key 'contact_patch.steps': must be an integer")


def test_a_numpy_value_in_a_sweep_axis_is_its_value(railjoint):
    # Before: {"wheel.y": [np.array([0.0151])]} ran at y = 0 (scenario 1).
    got = railjoint.sweep(railjoint.Scene(), {"wheel.y": [np.array([0.0151]), np.float64(0.0151)]})
    expected = railjoint.sweep(railjoint.Scene(), {"wheel.y": [0.0151, 0.0151]})
    print(got[["wheel.y", "analytic.exact_Ns"]])
    assert list(got["wheel.y"]) == [0.0151, 0.0151]
    assert list(got["analytic.exact_Ns"]) == list(expected["analytic.exact_Ns"])


def test_a_numpy_value_in_overrides_is_its_value(railjoint):
    path = scene_path("default.toml")
    got = railjoint.analytic(railjoint.load_scene(path, overrides={"joint.beta": np.array([BETA])}))
    expected = railjoint.analytic(railjoint.load_scene(path, overrides={"joint.beta": BETA}))
    assert got.exact_Ns == expected.exact_Ns


@pytest.mark.parametrize("value", [np.array([0.01, 0.02]), np.zeros((2, 2)), np.array([])])
def test_an_array_of_other_than_one_value_is_a_type_error_naming_the_key(railjoint, value):
    with pytest.raises(TypeError) as raised:
        railjoint.Scene(wheel={"y": value})
    print(raised.value)
    assert str(raised.value).startswith("scene: key 'wheel.y': takes one value, got an array of shape")


def test_an_array_in_a_sweep_axis_list_names_the_axis(railjoint):
    with pytest.raises(TypeError) as raised:
        railjoint.sweep(railjoint.Scene(), {"wheel.y": [np.array([0.01, 0.02])]})
    assert str(raised.value).startswith("sweep: key 'axes.wheel.y': takes one value")


def test_a_value_no_scene_key_takes_is_a_type_error_naming_the_key(railjoint):
    with pytest.raises(TypeError) as raised:
        railjoint.Scene(joint={"beta": 0.03j})
    assert str(raised.value).startswith("scene: key 'joint.beta': takes a number, a text or True/False, got complex")


@pytest.mark.parametrize("value", [True, np.bool_(True), np.array([True])], ids=["bool", "numpy_bool", "bool_array"])
def test_a_bool_for_a_number_key_is_a_type_error_naming_the_key(railjoint, value):
    # Before: np.bool_(True) set wheel.speed to 1.0 m/s; True raised ValueError.
    with pytest.raises(TypeError) as raised:
        railjoint.Scene(wheel={"speed": value})
    print(raised.value)
    assert str(raised.value).startswith("scene: key 'wheel.speed': must be a number")
    with pytest.raises(TypeError):
        railjoint.load_scene(scene_path("default.toml"), overrides={"wheel.speed": value})


@pytest.mark.parametrize("value", [False, np.bool_(False)], ids=["bool", "numpy_bool"])
def test_a_bool_sets_a_boolean_key(railjoint, value):
    assert railjoint.Scene(render={"follow": value}).as_dict()["render"]["follow"] is False


@pytest.mark.parametrize("text", ["30\njoint.beta=0.9", "30\r\njoint.beta=0.9"])
def test_a_line_break_in_an_override_is_refused(railjoint, text):
    # Item 7: "wheel.speed=30\njoint.beta=0.9" ran at speed 30 and beta 0.03.
    with pytest.raises(ValueError) as raised:
        railjoint.load_scene(scene_path("default.toml"), overrides={"wheel.speed": text})
    print(raised.value)
    assert "key 'wheel.speed'" in str(raised.value) and "one-line" in str(raised.value)
    assert "\n" not in str(raised.value)


def test_a_line_break_in_an_override_key_is_refused(railjoint):
    with pytest.raises(ValueError) as raised:
        railjoint.load_scene(scene_path("default.toml"), overrides={"wheel.speed=30\njoint.beta": 0.9})
    assert "is not a key" in str(raised.value)


def test_a_line_break_in_a_dict_text_stays_one_value(railjoint):
    # A dict's text is a TOML string: the reader refuses it as one value, never two keys.
    with pytest.raises(ValueError) as raised:
        railjoint.Scene(joint={"kind": "step\nbeta = 0.9"})
    assert "joint.kind" in str(raised.value)
