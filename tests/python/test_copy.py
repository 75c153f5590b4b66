"""copy.copy, copy.deepcopy and pickle of scenes and results (issue 40,
item 12: each raised "cannot pickle 'railjoint.Prediction' object"): every
property, as_dict() and the columns of the copy equal the original's, so a
result can cross a multiprocessing pool or be stored with pickle."""

import copy
import pickle

import numpy as np
import pytest

from conftest import scene_path


def pickled(value):
    return pickle.loads(pickle.dumps(value))


COPIES = {"copy": copy.copy, "deepcopy": copy.deepcopy, "pickle": pickled}


def properties(result):
    """Every public property of the result's class, by name."""
    cls = type(result)
    return {name: getattr(result, name) for name in dir(cls)
            if not name.startswith("_") and isinstance(getattr(cls, name), property)}


def same(a, b):
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, np.ndarray):
        return np.array_equal(a, b, equal_nan=True)
    if hasattr(a, "as_dict"):  # a Prediction inside a Simulation
        return type(a) is type(b) and same(properties(a), properties(b)) and a.as_dict() == b.as_dict()
    return a == b or (a != a and b != b)


def results(railjoint):
    scene = railjoint.Scene(wheel={"y": 0.012})
    return {
        "analytic": railjoint.analytic(scene),
        "simulate": railjoint.simulate(scene),
        "pressure": railjoint.pressure(railjoint.load_scene(scene_path("pressure/table6_1.toml"))),
    }


@pytest.mark.parametrize("how", COPIES)
@pytest.mark.parametrize("kind", ["analytic", "simulate", "pressure"])
def test_a_copied_result_has_the_values_of_the_original(railjoint, kind, how):
    original = results(railjoint)[kind]
    twin = COPIES[how](original)
    print(kind, how, twin)
    assert type(twin) is type(original)
    assert same(properties(twin), properties(original))
    assert twin.as_dict() == original.as_dict()
    assert repr(twin) == repr(original)


def test_a_copied_as_dict_is_the_copy_s_own(railjoint):
    twin = pickled(railjoint.analytic(railjoint.Scene()))
    twin.as_dict()["exact_Ns"] = 0.0
    assert twin.as_dict()["exact_Ns"] == railjoint.analytic(railjoint.Scene()).exact_Ns


@pytest.mark.parametrize("how", COPIES)
def test_a_copied_scene_reads_as_the_original(railjoint, how):
    scene = railjoint.load_scene(scene_path("default.toml"), overrides={"wheel.speed": 30.0}, unsets=["joint.beta"])
    twin = COPIES[how](scene)
    assert (twin.file, twin.overrides, twin.given_keys) == (scene.file, scene.overrides, scene.given_keys)
    assert twin.as_dict() == scene.as_dict()
    assert railjoint.analytic(twin).as_dict() == railjoint.analytic(scene).as_dict()


def test_a_copied_prediction_still_gives_its_time_history(railjoint):
    prediction = railjoint.analytic(railjoint.Scene())
    history = copy.deepcopy(prediction).time_history(samples=11)
    assert same(history, prediction.time_history(samples=11))


def test_an_unpickled_prediction_says_why_it_has_no_time_history(railjoint):
    with pytest.raises(ValueError) as raised:
        pickled(railjoint.analytic(railjoint.Scene())).time_history()
    assert "railjoint.analytic(scene)" in str(raised.value)
