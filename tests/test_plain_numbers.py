"""Text made from numbers reads back as the numbers: numpy scalars and arrays written as Python
writes its own (:func:`fem_racket.display.plain`), in messages, JSON, provenance and TOML.

numpy 2 writes ``repr(np.float64(0.5))`` as ``np.float64(0.5)``, and ``json`` takes
``np.int64`` and ``np.bool_`` for strings (``default=str``) or refuses them (audit A3).
"""

import json
import math
import tomllib
from collections import namedtuple

import numpy as np
import pytest

import fem_racket as fr
from fem_racket.display import plain
from fem_racket.frame.hand import Hand
from fem_racket.frame.masses import AddedMass
from fem_racket.frame.specs import fit_racket
from fem_racket.io.config import toml_value
from fem_racket.io.figure_files import check_dpi
from fem_racket.outputs import json_ready, provenance
from fem_racket.studies.design.zone import uniform_zone
from fem_racket.validation import InputError, check_range, show

#: Computed values with every digit, and the kinds numpy hands out.
VALUES = {
    "cor": np.float64(0.3999988703366346),
    "modes": np.int64(80),
    "converged": np.bool_(True),
    "ratio": np.float32(0.1),
    "positions": np.array([0.6, 0.75, 0.9]),
    "count": np.array(3),
}
PLAIN = {
    "cor": 0.3999988703366346,
    "modes": 80,
    "converged": True,
    "ratio": float(np.float32(0.1)),
    "positions": [0.6, 0.75, 0.9],
    "count": 3,
}


def test_plain_gives_python_numbers_at_any_depth():
    Pair = namedtuple("Pair", "a b")
    got = plain({np.int64(1): [VALUES, (np.float64(2.5),), Pair(np.int64(1), "x")], "s": "t"})
    assert got == {1: [PLAIN, (2.5,), Pair(1, "x")], "s": "t"}
    assert type(got[1][2]) is Pair and type(next(iter(got))) is int
    for key, value in got[1][0].items():
        assert type(value) is type(PLAIN[key]), key
    assert repr(got[1][0]["cor"]) == "0.3999988703366346"  # Python's digits, bit for bit


def test_show_writes_numpy_values_as_python_does():
    assert show(np.float64(0.5)) == "0.5"
    assert show({"position": np.float64(0.75)}) == "{'position': 0.75}"
    assert show((np.int64(3), np.bool_(False))) == "(3, False)"
    assert show(np.linspace(0.0, 1.0, 3)) == "[0.0, 0.5, 1.0]"


def test_a_refusal_of_a_numpy_value_is_one_plain_line():
    with pytest.raises(InputError) as info:
        check_range("position", np.float64(1.25), 0.0, 1.0, unit="x/L")
    assert str(info.value).startswith("position = 1.25 x/L is not allowed")


def test_json_ready_gives_numbers_not_strings():
    text = json.dumps(json_ready(VALUES), default=str)
    assert json.loads(text) == PLAIN
    assert "np." not in text and '"80"' not in text and '"True"' not in text
    nan = json.loads(json.dumps(json_ready({"x": np.float64("nan"), "y": np.array([np.inf])})))
    assert nan == {"x": None, "y": [None]}


def test_provenance_parameters_are_plain():
    meta = provenance(VALUES)
    # as the sidecars write it: default=str turned np.int64 into "80", an array into "[0.6 ...]"
    back = json.loads(json.dumps(meta, default=str))["parameters"]
    assert back == PLAIN
    assert {k: type(v) for k, v in back.items()} == {k: type(v) for k, v in PLAIN.items()}


@pytest.mark.parametrize("key", sorted(VALUES))
def test_toml_value_reads_back_as_the_number(key):
    text = toml_value(VALUES[key])
    assert "np." not in text
    assert tomllib.loads(f"x = {text}")["x"] == PLAIN[key]


def test_toml_value_of_numpy_non_finite():
    assert math.isnan(tomllib.loads(f"x = {toml_value(np.float64('nan'))}")["x"])
    assert tomllib.loads(f"x = {toml_value(np.float64('inf'))}")["x"] == math.inf
    assert tomllib.loads(f"x = {toml_value(-math.inf)}")["x"] == -math.inf  # was written "inf"


def _refusal(call):
    with pytest.raises(InputError) as info:
        call()
    return str(info.value)


F = np.float64


@pytest.mark.parametrize(
    ("call", "start"),
    [
        (lambda: fr.simulate(tolerance=F(0.5)), "tolerance = 0.5 is not allowed"),
        (lambda: fr.simulate(kcb=F(100.0), output_step=F(1e-7)), "kcb = 100.0 N/m is not"),
        (lambda: fr.simulate(hand=Hand(grip_end=F(0.9))), "grip_end = 0.9 m is not allowed"),
        (lambda: Hand(stiffness=F(-1.0)), "grip stiffness = -1.0 N/m^2 is not allowed"),
        (lambda: AddedMass(position=0.9, mass=F(-0.01)), "added mass = -0.01 kg is not"),
        (lambda: fit_racket(0.685, 0.318, F(0.9), 316.0, 150.0), "balance = 0.9 m is not"),
        (lambda: uniform_zone(F(0.8), F(0.7), 5), "zone high = 0.7 x/L is not allowed"),
        (lambda: check_dpi(F(10.0)), "dpi = 10.0 is not allowed"),
    ],
)
def test_a_library_refusal_of_a_numpy_scalar_shows_the_number(call, start):
    # e.g. a loop over np.linspace: numpy 2 wrote these as "np.float64(0.5)" (audit A3)
    line = _refusal(call)
    assert line.startswith(start) and "np." not in line, line
