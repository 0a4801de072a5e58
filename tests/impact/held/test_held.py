"""A hand on the grip: held-racket modes, rebound and the grip force."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.frame.hand import FIRM_GRIP, LOOSE_GRIP, Hand, held_frame, held_modes
from fem_racket.frame.model import FrameModel
from fem_racket.impact.held.grip import simulate_held
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.simulate import simulate
from fem_racket.validation import InputError


def first_bending(model: FrameModel, hand: Hand) -> tuple[float, float]:
    f, zeta, share = held_modes(held_frame(model.fe, hand))
    j = int(np.argmax(share > 0.5))  # the lowest mode whose strain is mostly frame bending
    return float(f[j]), float(zeta[j])


def test_a_hand_without_grip_leaves_the_frame_modes(standard_model):
    f, zeta = first_bending(standard_model, Hand(stiffness=0.0, damping=0.0))
    assert f == pytest.approx(standard_model.modes(1).frequencies[0], rel=1e-9)
    assert abs(zeta) < 1e-9


def test_firmer_grip_lowers_f1_and_raises_its_damping(standard_model):
    # Chadefaux et al. (DESIGN section 8): gripping firmer lowers the first frequency and
    # raises its damping. The two grips are this model's illustrative presets (assumptions;
    # the trend is not monotonic in k' and c', see fem_racket.frame.hand).
    f_loose, z_loose = first_bending(standard_model, LOOSE_GRIP)
    f_firm, z_firm = first_bending(standard_model, FIRM_GRIP)
    assert f_firm < f_loose
    assert z_firm > z_loose


@pytest.mark.slow
@pytest.mark.parametrize("position", [0.70, 0.75, 0.80])
def test_rebound_hardly_depends_on_the_hand(standard_model, position):
    # Liu 1983; Cross 1999 ("the hand force can usually be neglected"): free and hand-held e_A
    # within 0.02 near the string centre (measured: <= 0.0033 at 0.70-0.80 L with either grip).
    free = simulate(standard_model, position=position, output_step=None, tolerance=None).cor
    for hand in (LOOSE_GRIP, FIRM_GRIP):
        held = simulate_held(ImpactProblem.build(standard_model, hand=hand, position=position))
        assert abs(held.cor - free) < 0.02


@pytest.mark.slow
def test_grip_force_is_the_hands_momentum(standard_model):
    # Nothing but the grip acts on the hand: int F_h dt = m_h u_h'(t_c) (trapezoid on 2 us).
    r = simulate_held(
        ImpactProblem.build(standard_model, hand=FIRM_GRIP, position=0.8), output_step=2e-6
    )
    f, t = r.grip_force, r.t
    impulse = 0.5 * np.sum((f[1:] + f[:-1]) * np.diff(t))  # numpy >= 1.26: no np.trapezoid
    assert impulse == pytest.approx(FIRM_GRIP.mass * r.hand_velocity[-1], rel=1e-4)
    s = r.summary()
    assert s["peak_grip_force_n"] > 0 and s["peak_grip_vibration_n"] > 0


def test_bad_hand_and_solver(standard_model):
    with pytest.raises(InputError, match="grip_start < grip_end"):
        Hand(grip_start=0.1, grip_end=0.05)
    with pytest.raises(InputError, match="grip stiffness = -1"):
        Hand(stiffness=-1.0)
    with pytest.raises(InputError, match="solver = 'exact'"):
        simulate_held(ImpactProblem.build(standard_model, hand=LOOSE_GRIP), solver="exact")
    with pytest.raises(InputError, match="beyond the frame"):
        held_frame(standard_model.fe, Hand(grip_end=0.9))
