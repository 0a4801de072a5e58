"""A study states a LinearContact's zeta for the ball it strikes (racket_map's law summary, a
sweep's ``contact_zeta``), as simulate's settings do: K_CB and C_CB are the law's, zeta that
ball's (:meth:`fem_racket.contact.linear.LinearContact.for_ball`)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from fem_racket.contact.linear import LinearContact
from fem_racket.frame.model import FrameModel
from fem_racket.impact.simulate import simulate
from fem_racket.studies.racket_map import racket_map
from fem_racket.studies.sweep import sweep_result
from fem_racket.validation import InputError

K, ZETA, OWN = 3e4, 0.1, 0.057  # the law: K_CB [N/m], zeta for its own ball of OWN [kg]
LAW = LinearContact(K, ZETA, OWN)
#: C_CB = 2 zeta sqrt(m_B K_CB) [N s/m] for the law's own ball (Kawazoe & Kanda 1997, 2.1).
C = 2.0 * ZETA * math.sqrt(OWN * K)


def struck(mass: float) -> float:
    """zeta = C_CB / (2 sqrt(K_CB m_B)) for a ball of ``mass`` [kg] (Kawazoe & Kanda 1997,
    section 2.1: the damping ratio of the spring-dashpot with that ball)."""
    return C / (2.0 * math.sqrt(K * mass))


@pytest.fixture(scope="module")
def model8() -> FrameModel:
    return FrameModel.build(None, 8)


def test_racket_map_states_zeta_for_the_ball_it_strikes(model8):
    m = racket_map(model8, law=LAW, ball_mass=0.1, positions=[0.6, 0.7, 0.8])
    contact = m.summary(curves=False)["contact"]
    # the closed form to round-off (a few operations: 1e-14), not the law's own 0.1
    assert contact["zeta"] == pytest.approx(struck(0.1), rel=1e-14)
    assert contact["zeta"] == pytest.approx(ZETA * math.sqrt(OWN / 0.1), rel=1e-14)  # 0.0755
    assert contact["kcb_n_m"] == K and contact["ccb_n_s_m"] == pytest.approx(C, rel=1e-14)
    # what simulate states for the same ball (its settings, since M3), every bit
    run = simulate(model8, position=0.7, law=LAW, ball_mass=0.1)
    assert contact["zeta"] == run.settings()["zeta"]
    # at the law's own ball the law itself
    assert racket_map(model8, law=LAW, positions=[0.6, 0.7, 0.8]).law_summary()["zeta"] == ZETA


def test_a_sweep_states_zeta_for_each_ball_it_strikes():
    grid = dict(position=[0.7, 0.8], speed=20.0, law=LAW, elements=8, backend="serial")
    one = sweep_result(**grid, ball_mass=0.1).attrs
    assert one["contact_zeta"] == pytest.approx(struck(0.1), rel=1e-14)  # closed form, round-off
    assert one["contact_kcb_n_m"] == K
    assert one["contact_ccb_n_s_m"] == pytest.approx(C, rel=1e-14)
    # a swept ball mass: one zeta per ball mass, in the order of the ball_mass coordinate; the
    # law's K_CB and C_CB once
    masses = [0.1, 0.2]
    each = sweep_result(**grid, ball_mass=masses).attrs
    assert each["contact_zeta"] == pytest.approx([struck(m) for m in masses], rel=1e-14)
    assert each["contact_kcb_n_m"] == K
    assert each["contact_ccb_n_s_m"] == pytest.approx(C, rel=1e-14)
    assert sweep_result(**grid).attrs["contact_zeta"] == ZETA  # the law's own ball


def test_a_swept_ball_the_law_damps_critically_is_refused_before_any_work():
    # zeta = 0.5 sqrt(0.057 / 0.01) = 1.19 for a 10 g ball: simulate refuses that ball, and so
    # does the sweep, naming it, whatever its place in the grid
    law = LinearContact(K, 0.5, OWN)
    with pytest.raises(InputError, match="ball mass = 0.01 kg is not allowed with contact law"):
        sweep_result(position=[0.7, 0.8], ball_mass=[OWN, 0.01], law=law, elements=8)
    with pytest.raises(InputError, match="ball mass = 0.01 kg is not allowed with contact law"):
        simulate(FrameModel.build(None, 8), law=law, ball_mass=0.01)
    assert np.isfinite(sweep_result(position=0.7, ball_mass=[OWN, 0.02], law=law, elements=8)
                       .values[:, 0]).all()  # fmt: skip
