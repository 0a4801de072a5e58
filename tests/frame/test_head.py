"""The head outline: a 100 in^2 ellipse on the long axis (fem_racket.frame.head)."""

import math

import numpy as np
import pytest

from fem_racket.frame.head import DEFAULT_HEAD, HeadOutline
from fem_racket.validation import InputError


def test_default_head_is_100_square_inches():
    # 100 in^2 = 645.16 cm^2; the default ellipse 0.326 m x 0.252 m is within 0.1 % of it
    assert DEFAULT_HEAD.area_m2 == pytest.approx(100 * 0.0254**2, rel=1e-3)
    lo, hi = DEFAULT_HEAD.x_range
    assert lo == pytest.approx(0.340, abs=1e-3) and hi < 0.680


def test_contains_and_half_width_agree_on_the_ellipse():
    h = HeadOutline(length_m=0.3, width_m=0.2, centre=0.7, frame_length_m=0.7)
    xc = h.centre_m
    assert h.contains(xc, 0.1) and not h.contains(xc, 0.1001)
    assert h.contains(xc + 0.15, 0.0) and not h.contains(xc + 0.1501, 0.0)
    x = xc + 0.15 * math.cos(0.3)
    assert float(h.half_width(x)) == pytest.approx(0.1 * math.sin(0.3), rel=1e-14)
    assert np.isnan(h.half_width(xc + 0.2))


def test_check_refuses_off_face_offsets_in_one_line():
    x = DEFAULT_HEAD.centre_m
    assert DEFAULT_HEAD.check(x, 0.12) == 0.12
    assert DEFAULT_HEAD.check(0.05, 0.0) == 0.0  # on the axis: anywhere, as before
    with pytest.raises(InputError, match=r"^offset = 0.13 m is not allowed.*\|offset\| <= 0.126"):
        DEFAULT_HEAD.check(x, 0.13)
    with pytest.raises(InputError, match="face spans x"):
        DEFAULT_HEAD.check(0.2, 0.01)


def test_head_must_lie_on_the_frame():
    with pytest.raises(InputError, match="head length"):
        HeadOutline(length_m=0.5, centre=0.8)
    assert DEFAULT_HEAD.on_frame(0.7).centre_m == pytest.approx(0.74 * 0.7)
