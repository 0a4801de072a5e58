"""Every refusal of a ``validation.check_*`` helper says which parameter and value it refused
(``InputError.parameter``, ``.value``), so that a caller names the value its own way
(``InputError.named``: a run file's key) without reading the message; the message is unchanged."""

from __future__ import annotations

import pickle

import numpy as np
import pytest

from fem_racket.validation import (
    AccuracyError,
    InputError,
    check_choice,
    check_elements,
    check_file,
    check_finite,
    check_integer,
    check_positive,
    check_range,
)

#: (call, the parameter, the value refused, the one line)
REFUSALS = [
    (lambda: check_finite("speed", "20", "m/s"), "speed", "20",
     "speed = '20' m/s is not allowed: must be a finite number"),
    (lambda: check_finite("speed", None), "speed", None,
     "speed = None is not allowed: must be a finite number"),
    (lambda: check_positive("kcb", -3.0, "N/m"), "kcb", -3.0,
     "kcb = -3.0 N/m is not allowed: must be a finite number > 0"),
    (lambda: check_range("speed", 1000.0, 1, 100, unit="m/s"), "speed", 1000.0,
     "speed = 1000.0 m/s is not allowed: must lie in [1, 100]"),
    (lambda: check_range("face angle", 180.0, 0, 180, include_high=False), "face angle", 180.0,
     "face angle = 180.0 is not allowed: must lie in [0, 180)"),
    (lambda: check_choice("solver", "rk4", ("exact", "cvode")), "solver", "rk4",
     "solver = 'rk4' is not allowed: must be one of exact, cvode"),
    (lambda: check_integer("modes", 0), "modes", 0,
     "modes = 0 is not allowed: must be an integer >= 1"),
    (lambda: check_elements(20.5), "elements", 20.5,
     "elements = 20.5 is not allowed: must be an integer >= 2"),
    (lambda: check_elements(np.float64(1.0)), "elements", 1,
     "elements = 1 is not allowed: must be an integer >= 2"),
]  # fmt: skip


@pytest.mark.parametrize(("call", "parameter", "value", "line"), REFUSALS)
def test_a_check_names_the_parameter_and_value_it_refused(call, parameter, value, line):
    with pytest.raises(InputError) as info:
        call()
    assert str(info.value) == line
    assert info.value.parameter == parameter
    assert info.value.value == value and type(info.value.value) is type(value)


@pytest.mark.parametrize("folder", [True, False])
def test_check_file_names_the_path_it_refused(tmp_path, folder):
    path = tmp_path if folder else tmp_path / "none.vtu"
    with pytest.raises(InputError, match="^mesh = ") as info:
        check_file("mesh", str(path), "mesh file")
    assert (info.value.parameter, info.value.value) == ("mesh", path)


def test_an_error_raised_with_no_parameter_names_none():
    exc = InputError("a hand is not allowed with a string bed: give one of them")
    assert (exc.parameter, exc.value) == (None, None)
    assert exc.named("hand.grip") is exc


def test_named_keeps_the_message_from_the_value_on():
    with pytest.raises(InputError) as info:
        check_range("string tension", 1e6, 1, 2000, unit="N")
    key = info.value.named("strings.tension_n")
    assert str(key) == "strings.tension_n = 1000000.0 N is not allowed: must lie in [1, 2000]"
    assert (key.parameter, key.value) == ("strings.tension_n", 1e6)
    where = info.value.named("strings.tension_n", "run.toml: ")
    assert str(where) == f"run.toml: {key}"
    assert where.parameter is None  # the line no longer opens with a parameter


def test_named_refuses_a_message_that_does_not_open_with_its_parameter():
    exc = InputError("the speed = 3 m/s is too low", parameter="speed", value=3.0)
    assert exc.named("impact.speed_m_s") is exc


def test_named_keeps_the_kind_of_error_and_pickles():
    exc = AccuracyError("t_max = 0.01 s is not enough", parameter="t_max", value=0.01)
    named = exc.named("solver.t_max_s")
    assert type(named) is AccuracyError and str(named).startswith("solver.t_max_s = 0.01 s")
    back = pickle.loads(pickle.dumps(named))  # across a process pool
    assert (str(back), back.parameter, back.value) == (str(named), "solver.t_max_s", 0.01)
