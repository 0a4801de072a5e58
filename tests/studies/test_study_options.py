"""The studies' keyword options are small frozen dataclasses behind thin wrappers: an unknown
keyword is refused in one line with the closest known name (as simulate refuses one)."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.frame.model import FrameModel
from fem_racket.studies.racket_map import apparent_cor_along, racket_map
from fem_racket.studies.refine import refinement_study
from fem_racket.studies.sweep import sweep_result
from fem_racket.validation import InputError


@pytest.mark.parametrize(
    ("call", "words"),
    [
        (
            lambda: sweep_result(speeds="20,30"),
            "speeds is not a sweep parameter: did you mean 'speed'?",
        ),
        (
            lambda: sweep_result(backnd="serial"),
            "backnd is not a sweep parameter: did you mean 'backend'?",
        ),
        (
            lambda: racket_map(pivots=0.1),
            "pivots is not an option of racket_map: did you mean 'pivot'?",
        ),
        (
            lambda: refinement_study(elements=[5], famly="graded"),
            "famly is not an option of refinement_study: did you mean 'family'?",
        ),
        (
            lambda: apparent_cor_along(FrameModel.build(None, 8), [0.7], [20.0], tolerence=None),
            "tolerence is not an option of apparent_cor_along: did you mean 'tolerance'?",
        ),
    ],
)
def test_an_unknown_keyword_is_refused_with_the_closest_name(call, words):
    with pytest.raises(InputError) as err:
        call()
    assert str(err.value) == words


def test_the_wrappers_keep_their_keywords():
    # the options reach the study: a stiffer K_CB raises e_A at the same point and speed
    model = FrameModel.build(None, 20)
    soft = apparent_cor_along(model, [0.75], [20.0], kcb_factor=0.5)
    stiff = apparent_cor_along(model, [0.75], [20.0], kcb_factor=2.0)
    assert np.all(np.isfinite([soft, stiff])) and stiff[0] != soft[0]
    m = racket_map(model, positions=np.linspace(0.6, 0.9, 4), name="x", power_fraction=0.9)
    assert m.name == "x" and m.spots.power_fraction == 0.9
