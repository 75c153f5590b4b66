"""Paths given to the module (issue 40, item 12): str, bytes and os.PathLike
name the same file, a file name that is not UTF-8 is read (os.fsencode), a
NUL is refused naming the argument, errors about a sweep's folder name
`out`, and a progress bar with no sys.stderr is simply not drawn."""

import os
import shutil
import sys
from pathlib import Path

import pytest

from conftest import scene_path

DEFAULT = scene_path("default.toml")


def test_a_bytes_path_is_the_file_it_names(railjoint, tmp_path):
    # Before: b"default.toml" was looked for as "b'default.toml'".
    path = tmp_path / "default.toml"
    shutil.copy(DEFAULT, path)
    got = railjoint.load_scene(os.fsencode(path))
    assert got.file == str(path)
    assert got.as_dict() == railjoint.load_scene(path).as_dict()


def test_a_file_name_that_is_not_utf8_is_read(railjoint, tmp_path):
    # Before: UnicodeEncodeError ('utf-8' codec can't encode character '\udce9').
    name = os.fsencode(tmp_path) + b"/caf\xe9.toml"
    shutil.copy(DEFAULT, name)
    for path in (name, os.fsdecode(name), Path(os.fsdecode(name))):
        scene = railjoint.load_scene(path)
        assert scene.file == os.fsdecode(name)
        assert repr(os.fsdecode(name)) in repr(scene)


def test_a_missing_file_that_is_not_utf8_is_named_in_the_error(railjoint, tmp_path):
    name = os.fsencode(tmp_path) + b"/missing\xe9.toml"
    with pytest.raises(ValueError) as raised:
        railjoint.load_scene(name)
    assert str(raised.value).startswith(os.fsdecode(name) + ": ")


@pytest.mark.parametrize("path", [DEFAULT + "\0junk", os.fsencode(DEFAULT) + b"\0junk"], ids=["str", "bytes"])
def test_a_nul_in_a_path_is_refused_naming_the_argument(railjoint, path):
    # Before: "default.toml\0junk" read default.toml (the name cut at the NUL).
    with pytest.raises(ValueError) as raised:
        railjoint.load_scene(path)
    print(raised.value)
    assert str(raised.value).startswith("path: a path with a NUL character")
    with pytest.raises(ValueError) as raised:
        railjoint.sweep(railjoint.Scene(), {"wheel.y": [0.0]}, out=path)
    assert str(raised.value).startswith("out: a path with a NUL character")


def test_a_value_that_is_no_path_is_a_type_error_naming_the_argument(railjoint):
    with pytest.raises(TypeError) as raised:
        railjoint.load_scene(3)
    assert str(raised.value).startswith("path: takes a path")
    with pytest.raises(TypeError) as raised:
        railjoint.sweep(railjoint.Scene(), {"wheel.y": [0.0]}, out=3.0)
    assert str(raised.value).startswith("out: takes a path")


def test_a_bytes_out_folder_is_the_folder_it_names(railjoint, tmp_path, monkeypatch):
    # Before: out=b"/tmp/x" wrote into a folder literally named "b'" under the current one.
    monkeypatch.chdir(tmp_path)
    out = tmp_path / "rows"
    railjoint.sweep(railjoint.Scene(), {"wheel.y": [0.0, 0.01]}, out=os.fsencode(out))
    assert (out / "results.csv").is_file()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["rows"]


def test_an_out_folder_error_names_the_argument(railjoint, tmp_path):
    # Before: "...: key '--out': cannot create this folder: Not a directory".
    not_a_folder = tmp_path / "a_file"
    not_a_folder.write_text("x")
    with pytest.raises(ValueError) as raised:
        railjoint.sweep(railjoint.Scene(), {"wheel.y": [0.0]}, out=not_a_folder)
    print(raised.value)
    assert str(raised.value).startswith(f"{not_a_folder}: key 'out': ")
    assert "--out" not in str(raised.value)


def test_a_progress_bar_without_sys_stderr_is_not_drawn(railjoint, monkeypatch):
    # Before: AttributeError: 'NoneType' object has no attribute 'write'.
    monkeypatch.setattr(sys, "stderr", None)
    rows = railjoint.sweep(railjoint.Scene(), {"wheel.y": [0.0, 0.01]}, progress=True)
    assert len(rows) == 2
