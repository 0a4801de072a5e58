"""racket_map against one simulate() per point, and its input checks."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.frame.model import FrameModel
from fem_racket.impact.simulate import simulate
from fem_racket.impact.swing import Swing
from fem_racket.studies.racket_map import racket_map
from fem_racket.validation import InputError


@pytest.fixture(scope="module")
def model() -> FrameModel:
    return FrameModel.build(None, 20)


def test_curves_are_simulate_at_each_point(model):
    x = np.array([0.55, 0.7, 0.85, 0.95])
    m = racket_map(model, speed=25.0, racket_speed=20.0, pivot=-0.4, positions=x)
    swing = Swing.from_speed(20.0, 0.68, pivot=-0.4)
    for k, p in enumerate(x):
        r = simulate(model, position=p, speed=25.0, swing=swing, output_step=None)
        assert m.apparent_cor[k] == pytest.approx(r.apparent_cor, rel=1e-9)
        assert m.ball_speed_out[k] == pytest.approx(r.ball_speed_out, rel=1e-9)
        assert m.racket_speed[k] == pytest.approx(r.racket_speed_at_impact, rel=1e-12)


def test_the_refined_maximum_beats_every_grid_point(model):
    x = np.linspace(0.5, 1.0, 11)
    m = racket_map(model, racket_speed=15.0, pivot=0.1, positions=x)
    best = racket_map(
        model, racket_speed=15.0, pivot=0.1, positions=[0.5, m.spots.max_ball_speed, 1.0]
    )
    assert best.ball_speed_out[1] >= m.ball_speed_out.max()
    lo, hi = m.spots.power_region
    assert lo < m.spots.max_ball_speed < hi


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"positions": [0.6, 0.7]}, "at least 3"),
        ({"positions": [0.6, 0.8, 0.7]}, "increasing"),
        ({"power_fraction": 1.5}, "power_fraction = 1.5"),
        ({"speed": -1.0}, "speed = -1"),
        ({"racket_speed": -50.0}, "must close"),
    ],
)
def test_bad_input(model, kwargs, message):
    with pytest.raises(InputError, match=message):
        racket_map(model, **kwargs)
