"""The studies' keyword options are small frozen dataclasses behind thin wrappers: an unknown
keyword is refused in one line with the closest known name (as simulate refuses one)."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.frame.model import FrameModel
from fem_racket.impact.constants import DEFAULT_REFERENCE
from fem_racket.impact.swing import Swing
from fem_racket.studies.compare import Play
from fem_racket.studies.map_options import MapPlay, MapSetup
from fem_racket.studies.options import field_names, take
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


def test_a_group_of_options_is_filled_from_the_same_keywords():
    # MapSetup composes the MapPlay that compare's Play extends: racket_map's keywords, and
    # their order in its refusal, are the flat names they were before the group
    names = field_names(MapSetup)
    assert names == ("name", "speed", "racket_speed", "reference", "pivot", "positions",
                     "elements", "power_fraction")  # fmt: skip
    setup, rest = take({"speed": 30.0, "pivot": 0.1, "name": "A"}, "an option", MapSetup)
    assert setup == MapSetup(name="A", play=MapPlay(speed=30.0, pivot=0.1))
    assert rest == {}
    with pytest.raises(InputError) as err:
        racket_map(xyzzy=1)
    assert str(err.value).startswith(
        "xyzzy is not an option of racket_map: must be one of name, speed, racket_speed, "
        "reference, pivot, positions, elements, power_fraction, ball_mass"
    )
    play = Play(25.0, 5.0, pivot=0.05, position=0.7)
    assert isinstance(play, MapPlay) and field_names(Play)[:5] == field_names(MapPlay)
    assert play.keywords() == {
        "speed": 25.0, "racket_speed": 5.0, "reference": DEFAULT_REFERENCE, "pivot": 0.05,
        "positions": None,
    }  # fmt: skip
    swing = play.swing(0.69)
    ref = Swing.from_speed(5.0, 0.69, reference=0.75, pivot=0.05)
    assert (swing.velocity, swing.omega) == (ref.velocity, ref.omega)
