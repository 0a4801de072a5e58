"""The map's refusals of its grid and label say which parameter and value they refused
(``InputError.parameter``, ``.value``), so that a run file's ``[map]`` value the library
refuses is named by its dotted key and the file, by ``fem-racket map --config`` and
``load_config(f).map()`` alike (they named the library's parameter: ``positions = 3 values is
not allowed``); the same value on the command line is still named as its option."""

from __future__ import annotations

import numpy as np
import pytest
from clirun import file_refused_alike, one_error

from fem_racket.studies.map_options import MapSetup, check_map_points, map_grid
from fem_racket.validation import InputError

ARGV = ["map", "--config", "run.toml", "--no-files"]
INCREASING = "is not allowed: must be at least 3 increasing x/L"


@pytest.mark.parametrize(
    ("call", "parameter", "value"),
    [
        (lambda: map_grid("0.9,0.8,0.7"), "positions", "0.9,0.8,0.7"),
        (lambda: map_grid([0.5, 0.6]), "positions", [0.5, 0.6]),
        (lambda: map_grid([[0.5, "x"]]), "positions", [[0.5, "x"]]),
        (lambda: check_map_points(10**6), "positions", 10**6),
        (lambda: check_map_points(10, 10**5), "offsets", 10**5),
        (lambda: MapSetup(name=3), "name", 3),
    ],
)
def test_the_refusal_names_its_parameter_and_value(call, parameter, value):
    with pytest.raises(InputError) as err:
        call()
    assert err.value.parameter == parameter and err.value.value == value
    assert str(err.value).startswith(f"{parameter} = ")


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ('positions = "0.9,0.8,0.7"', f"run.toml: map.positions = 3 values {INCREASING}"),
        ('positions = "0.5:0.9:2"', f"run.toml: map.positions = 2 values {INCREASING}"),
        ("power_fraction = 2.0", "run.toml: map.power_fraction = 2.0 is not allowed: must lie"),
        (
            'offsets = "0.01,-0.01"',
            "run.toml: map.offsets = 2 values is not allowed: must be at least 2 increasing",
        ),
    ],
)
def test_a_run_file_s_map_key_is_named(cwd, capsys, text, words):
    file_refused_alike(capsys, f"[map]\n{text}\n", ARGV, lambda c: c.map(), words, start=True)


def test_an_array_in_python_is_named_alike(cwd):
    path = cwd / "run.toml"
    path.write_text("[map]\npositions = [0.9, 0.8, 0.7]\n")
    from fem_racket import load_config

    with pytest.raises(InputError, match=f"^{path.name}: map.positions = 3 values {INCREASING}"):
        load_config(path.name).map()
    assert np.array_equal(map_grid([0.5, 0.6, 0.7]), [0.5, 0.6, 0.7])  # a good one runs


def test_the_same_grid_on_the_command_line_is_named_as_its_option(cwd, capsys):
    (cwd / "run.toml").write_text('[map]\npositions = "0.6:0.9:4"\n')
    line = one_error(capsys, *ARGV, "--positions", "0.9,0.8,0.7")
    assert f": error: positions = 3 values {INCREASING}" in line, line
