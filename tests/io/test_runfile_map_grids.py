"""A run file's ``[map]`` grids (``positions``, ``offsets``) are read by one parser for
``fem-racket map --config`` and ``load_config(f).map()`` (io.config_named.grid_value): an array
of numbers is taken by both (the command refused it as "not a value like --position takes"
while Python took it), and a grid refused while it is parsed (studies.grid_values, whose
refusals now carry ``parameter`` and ``value``) is named by its key in both:
``run.toml: map.positions = ...``."""

from __future__ import annotations

import json

import numpy as np
import pytest
from clirun import file_refused_alike, run_json

from fem_racket import load_config
from fem_racket.outputs.jsonable import json_ready
from fem_racket.studies.grid_values import as_values, parse_values
from fem_racket.validation import InputError

ARGV = ["map", "--config", "run.toml", "--no-files"]
INCREASING = "is not allowed: must be at least 3 increasing x/L"


def _printed(summary):
    """A summary as ``--json`` prints it."""
    return json.loads(json.dumps(json_ready(summary)))


@pytest.mark.parametrize(
    ("text", "words"),
    [
        # an array: the same refusal from the map (it was the command's type refusal)
        ("positions = [0.9, 0.8, 0.7]", f"run.toml: map.positions = 3 values {INCREASING}"),
        # refused while parsed: named by the key (they named the sweep parameter 'position')
        ("positions = 'a,b'", "run.toml: map.positions = 'a,b' is not allowed: must be a number, "
                              "a comma list or start:stop:num[:log]"),
        ("positions = 1.05", "run.toml: map.positions = 1.05 x/L is not allowed: must lie in "
                             "[0, 1]"),
        ("positions = '0.5,1.05'", "run.toml: map.positions = 1.05 x/L is not allowed: must lie "
                                   "in [0, 1]"),
        ("positions = '0.5:0.9:0'", "run.toml: map.positions = '0.5:0.9:0' is not allowed: num "
                                    "must be an integer from 1 to "),
        ("positions = [0.6, 0.6, 0.7]", "run.toml: map.positions = [0.6, 0.6, 0.7] is not "
                                        "allowed: values must be distinct"),
        ("offsets = 'a'", "run.toml: map.offsets = 'a' is not allowed: must be a number, a comma "
                          "list or start:stop:num[:log]"),
        # what is not a grid at all, and one too large, before any array is made
        ("positions = true", "run.toml: map.positions = True is not allowed: must be a number, "
                             "an array of numbers or a string like '0.5:1.0:200'"),
        ("positions = ['a', 'b']", "run.toml: map.positions = ['a', 'b'] is not allowed: must "
                                   "be a number, an array of numbers"),
        ("offsets = '-0.1:0.1:200000'", "run.toml: map.offsets = 200000 values is not allowed: "
                                        "a map takes at most 100000 points"),
    ],
)  # fmt: skip
def test_a_map_grid_is_refused_alike_named_by_its_key(cwd, capsys, text, words):
    file_refused_alike(capsys, f"[map]\n{text}\n", ARGV, lambda c: c.map(), words, start=True)


def test_an_array_gives_the_command_s_map(cwd, capsys):
    (cwd / "run.toml").write_text("[map]\npositions = [0.6, 0.7, 0.8]\n")
    printed = run_json(capsys, "map", "--config", "run.toml")
    (m,) = load_config("run.toml").map()
    assert printed == _printed(m.summary())  # the same map, as the command prints it
    assert printed["curves"]["position_x_over_l"] == [0.6, 0.7, 0.8]
    # the same grid as text: the same map
    (cwd / "run.toml").write_text("[map]\npositions = '0.6,0.7,0.8'\n")
    assert run_json(capsys, "map", "--config", "run.toml") == printed


def test_an_offsets_array_gives_the_command_s_face(cwd, capsys):
    (cwd / "run.toml").write_text("[map]\npositions = '0.6:0.8:3'\noffsets = [-0.02, 0.0, 0.02]\n")
    printed = run_json(capsys, "map", "--config", "run.toml")
    (m,) = load_config("run.toml").map()
    assert printed == _printed(m.summary())


@pytest.mark.parametrize(
    ("call", "parameter", "value"),
    [
        (lambda: parse_values("position", "a,b"), "position", "a,b"),
        (lambda: parse_values("offset", "0:1"), "offset", "0:1"),
        (lambda: parse_values("speed", "1:2:x"), "speed", "1:2:x"),
        (lambda: parse_values("speed", "1:inf:3"), "speed", "1:inf:3"),
        (lambda: parse_values("speed", "1:2:1"), "speed", "1:2:1"),
        (lambda: parse_values("speed", "-1:2:3:log"), "speed", "-1:2:3:log"),
        (lambda: as_values("speed", [[20.0]]), "speed", [[20.0]]),
        (lambda: as_values("speed", [20.0, 20.0]), "speed", [20.0, 20.0]),
        (lambda: as_values("sped", 20.0), "parameter", "sped"),
    ],
)
def test_grid_refusals_name_their_parameter_and_value(call, parameter, value):
    with pytest.raises(InputError) as err:
        call()
    assert err.value.parameter == parameter and np.array_equal(err.value.value, value)
    assert str(err.value).startswith(f"{parameter} = ")
