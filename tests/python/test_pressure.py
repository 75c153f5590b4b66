"""railjoint.pressure against `railjoint pressure --json --csv` on the same
scene: as_dict() equal to the last digit, the traversal's arrays equal to the
CSV's cells as the CLI writes them."""

import json
from pathlib import Path

import pytest

from conftest import SOURCE_DIR, cell_as_cli_writes, cli_error, read_csv_text, run_cli

SCENES = [str(SOURCE_DIR / "scenes" / "pressure" / name) for name in ("table6_1.toml", "figure5_3_rectangle.toml")]
CSV_DIGITS = 10  # pressure --csv writes 10 significant digits (scenes/cli/pressure_command.cpp)


@pytest.mark.parametrize("path", SCENES, ids=lambda p: Path(p).stem)
def test_as_dict_and_traversal_are_the_cli_json_and_csv(railjoint, path, tmp_path):
    csv_path = tmp_path / "traversal.csv"
    stdout, _ = run_cli("pressure", path, "--json", "--csv", csv_path)
    expected = json.loads(stdout)
    run = railjoint.pressure(railjoint.load_scene(path))
    got = run.as_dict()
    print(Path(path).stem, got["max_pressure_Pa"])
    assert got == expected
    assert run.max_pressure_Pa == expected["max_pressure_Pa"]
    assert run.max_relative_pressure == expected["max_relative_pressure"]
    assert run.max_rate_Pa_per_s == expected["max_rate_Pa_per_s"]
    assert run.p0_Pa == expected["p0_Pa"]

    header, rows = read_csv_text(csv_path)
    assert list(run.traversal) == header
    for c, name in enumerate(header):
        written = [cell_as_cli_writes(float(v), CSV_DIGITS) for v in run.traversal[name]]
        assert written == [row[c] for row in rows], f"column {name}"


def test_a_patch_the_model_refuses_raises_the_cli_message(railjoint):
    path = SCENES[0]
    expected = cli_error("pressure", path, "--set", "joint.gap=0.5")
    with pytest.raises(ValueError) as raised:
        railjoint.pressure(railjoint.load_scene(path, overrides={"joint.gap": 0.5}))
    print(raised.value)
    assert str(raised.value) == expected
