"""A run file's ``[strings]`` table in Python (``load_config(f).simulate()``) equals
``fem-racket simulate --config f`` (issue 21.7 "run files = CLI", issue 25's bed): head-on, off
the axis and oblique, and a hand with a bed is refused alike."""

import json

import pytest
from clirun import run_json
from runfile_helpers import BED

from fem_racket import load_config
from fem_racket.cli import main
from fem_racket.validation import InputError


def _same(python: dict, cli: dict) -> None:
    assert python.keys() <= cli.keys()
    for key, value in python.items():
        if isinstance(value, float):
            assert cli[key] == pytest.approx(value, rel=1e-12, abs=1e-15), key
        elif key != "solver":  # the CLI names the method "auto" picked
            assert cli[key] == value, key


@pytest.mark.parametrize(
    "extra",
    ["", "offset_m = 0.03\n", "[oblique]\nangle_deg = 30.0\nspin_rpm = -2000.0\n"],
    ids=["head-on", "off-axis", "oblique"],
)
def test_strings_table_in_python_equals_the_command(capsys, tmp_path, extra):
    path = tmp_path / "run.toml"
    path.write_text(BED + extra)
    python = load_config(path).simulate().summary()
    cli = run_json(capsys, "simulate", "--config", path)
    _same(json.loads(json.dumps(python, default=str)), cli)
    assert cli["pattern"] == "18x20" and cli["string_tension_n"] == 270.0


def test_a_hand_with_strings_is_refused_alike(capsys, tmp_path):
    path = tmp_path / "run.toml"
    path.write_text(BED + '[hand]\ngrip = "firm"\n')
    with pytest.raises(InputError, match="not allowed with"):
        load_config(path).simulate()
    assert main(["simulate", "--config", str(path)]) == 2
    assert "not allowed with" in capsys.readouterr().err
