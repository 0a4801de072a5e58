"""ImpactProblem: one statement of an impact, validated once; the shim simulate() over it."""

from __future__ import annotations

import dataclasses

import pytest

import fem_racket as fr
from fem_racket.contact.presets import get_law
from fem_racket.impact.problem import HeldRacket, Impact, ImpactProblem
from fem_racket.impact.swing import Swing
from fem_racket.validation import InputError

MODEL = fr.FrameModel.build(None, 20)


def test_problem_is_immutable_with_a_one_line_repr():
    p = ImpactProblem.build(MODEL, position=0.6, speed=30.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        p.impact = Impact(0.7, 20.0)
    text = repr(p)
    assert "\n" not in text and len(text) < 160
    assert "x = 0.6 L" in text and "30 m/s" in text and "linear (paper)" in text


def test_replace_validates_again():
    p = ImpactProblem.build(MODEL)
    assert p.replace(impact=Impact(0.6, 25.0)).impact.speed == 25.0
    with pytest.raises(InputError, match="kcb = 30000.0 is not allowed"):
        p.replace(law=get_law("hunt-crossley"), kcb=3e4)


@pytest.mark.parametrize(
    ("fields", "needles"),
    [
        (
            {"law": "hunt-crossley", "kcb": 3e4},
            ("kcb = 30000.0 is not allowed", "hunt-crossley", "linear"),
        ),
        ({"law": "hysteretic", "zeta": 0.1}, ("zeta = 0.1 is not allowed", "hysteretic")),
        ({"law": "hysteretic", "separation": "force"}, ("separation = 'force'", "own")),
        ({"separation": "velocity"}, ("separation = 'velocity'",)),
        ({"swing": Swing(1.0, 0.0), "frame_velocity": (1.0, 0.0)}, ("swing and frame_velocity",)),
        ({"hand": fr.Hand(), "law": "hunt-crossley"}, ("with a hand", "linear")),
        ({"hand": fr.Hand(), "separation": "force"}, ("with a hand",)),
        ({"hand": fr.Hand(), "frame_velocity": (1.0, 0.0)}, ("with a hand", "swing")),
        ({"shock_window": 0.01}, ("shock_window = 0.01", "without a hand")),
        ({"position": 1.5}, ("position = 1.5",)),
        ({"speed": -1.0}, ("speed = -1",)),
    ],
)
def test_a_field_that_does_not_apply_is_refused_in_one_line(fields, needles):
    with pytest.raises(InputError) as err:
        ImpactProblem.build(MODEL, **fields)
    message = str(err.value)
    assert "\n" not in message
    for needle in needles:
        assert needle in message


def test_elements_with_a_meshed_model_are_refused():
    # fem_racket.simulate(model, elements=40) used to mesh nothing and say nothing
    with pytest.raises(InputError, match="elements = 40 is not allowed with a FrameModel"):
        ImpactProblem.build(MODEL, elements=40)
    with pytest.raises(InputError, match="elements = 40"):
        fr.simulate(MODEL, elements=40)


def test_the_hand_is_a_structure():
    p = ImpactProblem.build(MODEL, hand=fr.Hand(), shock_window=0.01)
    assert p.held and isinstance(p.structure, HeldRacket) and p.model is MODEL
    assert p.structure.shock_window == 0.01
    assert "held frame" in repr(p)


def test_unknown_simulate_option_names_the_nearest():
    with pytest.raises(
        InputError, match="'positon' is not known to simulate; did you mean 'position'"
    ):
        fr.simulate(MODEL, positon=0.7)
