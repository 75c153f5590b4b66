"""railjoint.sweep against `railjoint sweep` of the sweep file with the same
base scene and axes: the same rows (but for the measured wall time), the
CLI's messages for a bad axis, a progress callback, and Ctrl-C stopping a
sweep whose rows stay for the same call to resume."""

import os
import signal
import subprocess
import sys
import time

import pandas
import pytest

from conftest import SOURCE_DIR, cli_error, run_cli

BASE = str(SOURCE_DIR / "scenes" / "default.toml")
AXES = {"joint.theta_deg": [30.0, 45.0, 90.0], "wheel.y": {"from": 0.0, "to": 0.019, "count": 5},
        "wheel.speed": {"from": 10.0, "to": 50.0, "count": 3, "scale": "log"}}
AXES_TOML = """[axes]
"joint.theta_deg" = [30.0, 45.0, 90.0]
"wheel.y" = { from = 0.0, to = 0.019, count = 5 }
"wheel.speed" = { from = 10.0, to = 50.0, count = 3, scale = "log" }
"""


def cli_sweep(tmp_path, run, axes_toml=AXES_TOML, extra=""):
    sweep_file = tmp_path / "grid.toml"
    sweep_file.write_text(f'base = "{BASE}"\nrun = {run!r}\n'.replace("'", '"') + extra + axes_toml)
    return sweep_file


def test_the_rows_are_the_cli_results(railjoint, tmp_path):
    run = ["analytic", "simulate"]
    sweep_file = cli_sweep(tmp_path, run)
    run_cli("sweep", sweep_file, "--out", tmp_path / "cli", "--jobs", "2")
    # Read exactly, as sweep() reads it (pandas' default parser is off by ulps).
    expected = pandas.read_csv(tmp_path / "cli" / "results.csv", float_precision="round_trip")
    got = railjoint.sweep(BASE, AXES, run=run, jobs=2)
    print(got[["joint.theta_deg", "wheel.y", "wheel.speed", "verdict", "simulate.jump_Ns"]].head())
    assert len(got) == 3 * 5 * 3
    pandas.testing.assert_frame_equal(got.drop(columns="wall_ms"), expected.drop(columns="wall_ms"), check_exact=True)


def test_a_scene_with_overrides_is_the_base_it_says(railjoint):
    scene = railjoint.load_scene(BASE, overrides={"joint.beta": 0.02})
    got = railjoint.sweep(scene, {"wheel.y": [0.0, 0.01]}, run=["analytic"])
    for y, exact in zip(got["wheel.y"], got["analytic.exact_Ns"]):
        one = railjoint.analytic(railjoint.load_scene(BASE, overrides={"joint.beta": 0.02, "wheel.y": y}))
        print(y, exact, one.exact_Ns)
        assert exact == one.exact_Ns  # results.csv writes the shortest text that reads back to the same double


def test_every_number_is_the_double_the_case_computed(railjoint):
    # results.csv holds the shortest text that reads back to each double; the
    # frame must hold those doubles. The reference is outside the sweep: the
    # axis values as passed, and railjoint.analytic of each case's own scene.
    # pandas' default parser misread about half of these cells (up to 230 ulps).
    ys = [k * 0.019 / 7 for k in range(8)]
    thetas = [15.0 + 75.0 * k / 9 for k in range(10)]
    got = railjoint.sweep(BASE, {"joint.theta_deg": thetas, "wheel.y": ys}, run=["analytic"], jobs=2)
    assert len(got) == len(ys) * len(thetas)
    columns = ["y_t_m", "governing_y_m", "x_A_m", "alpha_rad", "exact_Ns", "thesis_Ns", "small_angle_Ns"]
    differing = []
    for _, row in got.iterrows():
        theta, y = row["joint.theta_deg"], row["wheel.y"]
        assert theta in thetas and y in ys, (theta, y)
        one = railjoint.analytic(railjoint.load_scene(BASE, overrides={"joint.theta_deg": theta, "wheel.y": y}))
        for name in columns:
            expected = getattr(one, name)
            expected = float("nan") if expected is None else expected
            cell = row["analytic." + name]
            if not (cell == expected or (cell != cell and expected != expected)):
                differing.append((theta, y, name, cell, expected))
    print(f"{len(differing)} of {len(got) * len(columns)} cells differ", differing[:5])
    assert not differing


def test_a_sample_is_the_cli_sample(railjoint, tmp_path):
    axes_toml = '[axes]\n"wheel.y" = { from = 0.0, to = 0.019 }\n"joint.theta_deg" = { from = 20.0, to = 90.0 }\n'
    sample = '[sample]\ncount = 20\nseed = 7\nmethod = "random"\n'
    sweep_file = cli_sweep(tmp_path, ["analytic"], axes_toml=sample + axes_toml)
    run_cli("sweep", sweep_file, "--out", tmp_path / "cli")
    expected = pandas.read_csv(tmp_path / "cli" / "results.csv", float_precision="round_trip")
    got = railjoint.sweep(BASE, {"wheel.y": {"from": 0.0, "to": 0.019}, "joint.theta_deg": {"from": 20.0, "to": 90.0}},
                          sample={"count": 20, "seed": 7, "method": "random"})
    pandas.testing.assert_frame_equal(got.drop(columns="wall_ms"), expected.drop(columns="wall_ms"), check_exact=True)


@pytest.mark.parametrize("axes, axes_toml", [
    ({"wheel.yy": [0.0]}, '[axes]\n"wheel.yy" = [0.0]\n'),
    ({"wheel.y": []}, '[axes]\n"wheel.y" = []\n'),
    ({"wheel.y": {"from": 0.0, "to": 0.01, "count": 0}}, '[axes]\n"wheel.y" = { from = 0.0, to = 0.01, count = 0 }\n'),
    ({"speed": [1.0]}, '[axes]\n"speed" = [1.0]\n'),
])
def test_a_bad_axis_raises_the_cli_message(railjoint, tmp_path, axes, axes_toml):
    sweep_file = cli_sweep(tmp_path, ["analytic"], axes_toml=axes_toml)
    expected = cli_error("sweep", sweep_file, "--out", tmp_path / "out").replace(str(sweep_file), "sweep", 1)
    with pytest.raises(ValueError) as raised:
        railjoint.sweep(BASE, axes)
    print(raised.value)
    assert str(raised.value) == expected


def test_a_bad_model_raises_the_cli_message(railjoint, tmp_path):
    sweep_file = cli_sweep(tmp_path, ["analytc"])
    expected = cli_error("sweep", sweep_file, "--out", tmp_path / "out").replace(str(sweep_file), "sweep", 1)
    with pytest.raises(ValueError) as raised:
        railjoint.sweep(BASE, AXES, run=["analytc"])
    assert str(raised.value) == expected


def test_progress_is_reported_to_the_end(railjoint):
    calls = []
    railjoint.sweep(BASE, AXES, run=["analytic"], progress=lambda done, total: calls.append((done, total)))
    print(calls)
    assert calls and calls[-1] == (45, 45)
    assert all(done <= total for done, total in calls)
    # Workers report after their chunks in any order; what is shown only moves forward.
    assert all(earlier[0] < later[0] for earlier, later in zip(calls, calls[1:]))


# A sweep long enough to be stopped half way: 10,000 simulated crossings.
LONG_SWEEP = """
import sys, railjoint
railjoint.sweep({base!r}, {{"joint.theta_deg": {{"from": 30.0, "to": 60.0, "count": 100}},
                 "wheel.y": {{"from": 0.0, "to": 0.019, "count": 100}}}},
                run=["simulate"], jobs=2, out=sys.argv[1])
print("finished")
"""


def test_ctrl_c_stops_a_sweep_and_the_same_call_resumes(tmp_path):
    out = tmp_path / "out"
    script = LONG_SWEEP.format(base=BASE)
    env = dict(os.environ)
    child = subprocess.Popen([sys.executable, "-c", script, str(out)], env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    results = out / "results.csv"
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and (not results.exists() or results.read_text().count("\n") < 3):
        time.sleep(0.02)
    child.send_signal(signal.SIGINT)
    stdout, stderr = child.communicate(timeout=60)
    print(stderr[-400:])
    assert "KeyboardInterrupt: railjoint.sweep interrupted" in stderr
    assert "finished" not in stdout
    rows_kept = results.read_text().count("\n") - 1
    print("rows kept", rows_kept)
    assert 2 <= rows_kept < 10000

    resumed = subprocess.run([sys.executable, "-c", script, str(out)], env=env, capture_output=True, text=True,
                             timeout=600)
    assert resumed.returncode == 0, resumed.stderr
    table = pandas.read_csv(results)
    assert list(table["case"]) == list(range(10000))


def test_a_base_scenes_profile_is_relative_to_the_scene(railjoint, tmp_path, monkeypatch):
    # Issue 40 item 2: sweep() read the base scene's tread from the current
    # folder: every row rejected, or a file of that name there used silently.
    from test_scene import cylinder_exact_Ns, cylinder_tread, write_profile_scene
    write_profile_scene(tmp_path, 0.475)
    (tmp_path / "tread.csv").write_text(cylinder_tread(0.3))  # a decoy in the current folder
    monkeypatch.chdir(tmp_path)
    expected = cylinder_exact_Ns(0.475)
    for base in ("prof/tread.toml", railjoint.load_scene("prof/tread.toml")):
        rows = railjoint.sweep(base, {"wheel.speed": [50.0]}, run=["analytic"], jobs=1)
        print(rows[["verdict", "message", "analytic.exact_Ns"]])
        assert list(rows["verdict"]) == ["ok"]
        assert rows["analytic.exact_Ns"][0] == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize("jobs", [-1, 4097])
def test_jobs_outside_the_clis_range_raises(railjoint, jobs):
    # sweep(jobs=-1) ran on every core as 0 does; the CLI's --jobs is [1, 4096].
    with pytest.raises(ValueError, match=r"jobs.*must be 0 \(every core\) or in \[1, 4096\]"):
        railjoint.sweep(BASE, {"wheel.y": [0.0]}, jobs=jobs)


def test_a_sweep_that_rejects_every_case_raises(railjoint):
    # An out-of-range speed for every case: the rows said "rejected" and the
    # call returned them as if it had computed something.
    with pytest.raises(ValueError, match=r"every case run \(2\) was rejected.*wheel.speed"):
        railjoint.sweep(BASE, {"wheel.y": [0.0, 0.01], "wheel.speed": [5000.0]})
