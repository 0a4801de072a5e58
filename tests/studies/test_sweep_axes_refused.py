"""Bad input of the sweep's string-bed and oblique axes: one line each, before any work."""

from __future__ import annotations

import pytest

from fem_racket.studies.sweep import sweep_result
from fem_racket.validation import InputError


@pytest.mark.parametrize(
    ("given", "words"),
    [
        (
            {"string_tension": 250, "angle": 20, "side_angle": 5},
            "side_angle = 5.0 is not allowed with string_tension (a string bed)",
        ),
        ({"pattern": "16x19", "kcb": 3e4}, "kcb is not allowed with pattern (a string bed)"),
        ({"string_tension": 250, "racket_speed": 5}, "racket_speed = 5.0 is not allowed with"),
        # an offset on the bed is struck (tests/studies/test_sweep_strung_offset.py); off it not
        ({"string_tension": 250, "offset": 0.2}, "offset = 0.2 m at position = 0.75 x/L is not"),
        # the solver's own line, as simulate's (check_strung), not a list kept by the sweep
        (
            {"pattern": "16x19", "solver": "bdf"},
            "solver = 'bdf' is not allowed with a string bed: must be one of exact, general, cvode",
        ),
        ({"pattern": "16x19", "tolerance": 1e-8}, "tolerance = 1e-08 is not allowed with"),
        ({"pattern": "16y19"}, "pattern = '16y19' is not allowed: must be MAINSxCROSSES"),
        ({"pattern": "16x19,16x19"}, "pattern = [1619, 1619] is not allowed: values must be"),
        ({"angle": "30,95"}, "angle = 95.0 deg is not allowed: must lie in [0, 90)"),
        ({"friction": -0.1}, "friction = -0.1 is not allowed"),
        ({"string_tension": 250, "position": 0.3}, "is not allowed"),
    ],
)
def test_refused_in_one_line(given, words):
    with pytest.raises(InputError) as err:
        sweep_result(backend="serial", **given)
    assert words in str(err.value) and "\n" not in str(err.value)
