"""The string bed's options (:mod:`fem_racket.strings.options`): the tension's bound and the
head area refused naming the area, not the axis it derives."""

from __future__ import annotations

import pytest

from fem_racket.strings.options import MAX_STRING_TENSION_N, bed_from_options
from fem_racket.validation import InputError


def test_tension_beyond_any_strung_racket_is_refused():
    with pytest.raises(InputError, match=r"^string tension = 1000000000.0 N .* \[1, 2000\]$"):
        bed_from_options({"string_tension": 1e9})
    bed = bed_from_options({"string_tension": MAX_STRING_TENSION_N})
    assert bed.tension_n == MAX_STRING_TENSION_N


@pytest.mark.parametrize(
    ("values", "area", "made"),
    [
        ({"head_area": 1e9}, "1000000000.0", "405.8 m long"),
        ({"head_area": 5.0}, "5.0", "0.0287 m long"),  # scaled 0.326 x 0.252 m
        ({"head_area": 700.0, "head_length": 0.05}, "700.0", "1.783 m wide"),
        ({"head_area": 1e5, "head_length": 0.3}, "100000.0", "42.44 m wide"),
    ],
)
def test_head_area_is_named(values, area, made):
    with pytest.raises(InputError) as err:
        bed_from_options(values)
    assert str(err.value) == (
        f"head area = {area} cm^2 is not allowed: it makes the head {made}, outside [0.05, 1] m"
    )


def test_a_real_head_area_keeps_its_shape():
    bed = bed_from_options({"head_area": 645.2202991942717})
    assert bed.head_length_m == pytest.approx(0.326, rel=1e-12)
    assert bed.head_width_m == pytest.approx(0.252, rel=1e-12)
