"""compare's :class:`~fem_racket.studies.compare.Play`: a swing's point or pivot without a swing
refused (compare shows no centre of percussion, so the pivot would be dropped at rest)."""

from __future__ import annotations

import pytest

from fem_racket.studies.compare import Play
from fem_racket.validation import InputError


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"pivot": 0.1}, "pivot = 0.1 m is not allowed without a swing"),
        ({"reference": 0.6}, "reference = 0.6 x/L is not allowed without a swing"),
    ],
)
def test_a_swing_point_at_rest_is_refused(kwargs, message):
    with pytest.raises(InputError, match=message):
        Play(**kwargs)
    swinging = Play(racket_speed=10.0, **kwargs)
    assert swinging.swing(0.68).omega != 0.0 or "reference" in kwargs
