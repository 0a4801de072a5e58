"""The bounds of :class:`~fem_racket.impact.incidence.Incidence` where the model's assumptions
end (each about an order of magnitude beyond real play), stated in the refusal."""

from __future__ import annotations

import pytest

from fem_racket.impact.incidence import (
    MAX_BALL_RADIUS,
    MAX_COMPLIANCE_RATIO,
    MAX_FRICTION,
    MAX_SPIN_RPM,
    Incidence,
)
from fem_racket.validation import InputError

SPIN = "rpm is not allowed: must lie in [-50000, 50000]"
SIGN = "is not allowed: must lie in [0, 15]"


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"spin": 1e12}, f"spin = 1000000000000.0 {SPIN}"),
        ({"side_spin": -6e4}, f"side_spin = -60000.0 {SPIN}"),
        ({"friction": 1e9}, "friction = 1000000000.0 is not allowed: must lie in [0, 5]"),
        ({"radius": 10.0}, "radius = 10.0 m is not allowed: must lie in (0, 0.1]"),
        ({"compliance_ratio": 1e9}, "compliance_ratio = 1000000000.0 is not allowed: must lie in "
         "[0, 15]"),
        ({"compliance_ratio": -1.0}, f"compliance_ratio = -1.0 {SIGN}"),
    ],
)  # fmt: skip
def test_beyond_the_model_is_refused(kwargs, message):
    with pytest.raises(InputError) as err:
        Incidence(angle=30.0, **kwargs)
    assert str(err.value) == message


def test_the_bounds_themselves_and_real_play_pass():
    Incidence(angle=30.0, spin=MAX_SPIN_RPM, side_spin=-MAX_SPIN_RPM, friction=MAX_FRICTION)
    Incidence(radius=MAX_BALL_RADIUS, compliance_ratio=MAX_COMPLIANCE_RATIO)
    # real play: a heavy topspin, a grippy string, a large ball, Mindlin's solid sphere
    Incidence(angle=40.0, spin=5000.0, friction=0.6, radius=0.0343, compliance_ratio=1.5)


def test_a_normal_speed_below_the_papers_k_cb_names_the_angle():
    # K_CB from the normal speed V cos(angle) is given for 1-100 m/s (contact.linear's
    # KCB_SPEED_RANGE): a steeper angle is refused by the problem itself, named as the angle,
    # not as the normal speed ("speed = 0.868 m/s") it derives; with a K_CB or a law of its own
    # the same ball runs.
    import fem_racket as fr

    steep = Incidence(angle=80.0)
    with pytest.raises(InputError, match=r"^angle = 80.0 deg is not allowed with speed = 5.0"):
        fr.simulate(speed=5.0, incidence=steep)
    assert fr.simulate(speed=5.0, incidence=steep, kcb=30000.0).normal.cor > 0.0
