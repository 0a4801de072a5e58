"""The general integrator vouches for its answers (issue 22.1) and its compiled march (issue 27).

- the compiled march solves the numpy march's equations (to round-off);
- every law meets the COR tolerance against CVODE, over a seeded randomised set of law
  parameters (hypothesis, derandomised ``ci`` profile: the same examples every run) and the
  cases issue 22 found wrong (n = 1 laws, a lightly damped or very soft series ball);
- what cannot be vouched for is refused with one line;
- a case's answer does not depend on the batch it is in, batches may span frames.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import contact_laws

from fem_racket import FrameModel
from fem_racket.contact.hunt_crossley import HuntCrossley
from fem_racket.contact.hysteretic import Hysteretic
from fem_racket.contact.linear import LinearContact
from fem_racket.contact.presets import PRESETS, get_law
from fem_racket.contact.series import SeriesBallString
from fem_racket.impact.general.batches import stack_laws, stack_receptances
from fem_racket.impact.general.compiled import (
    MarchCases,
    MarchOptions,
    kernel_law,
    march_compiled,
)
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.general.march import march
from fem_racket.impact.law_impact import LawOptions, receptance, solve_law_impact
from fem_racket.validation import AccuracyError

#: CVODE's own COR error at rtol 1e-10 (measured against rtol 1e-12: <= 2e-9 on these laws).
CVODE_COR = 1e-8


@pytest.fixture(scope="module")
def model10() -> FrameModel:
    m = FrameModel.build(None, 10)
    m.modes(None)
    return m


def _cvode_cor(law, model, position, speed):
    options = LawOptions("cvode", output_step=None, rtol=1e-10, atol=1e-13)
    run = solve_law_impact(law, model, position, 0.057, speed, options=options)
    return -run.ball_velocity[-1] / speed


@pytest.mark.parametrize(
    "law",
    [
        HuntCrossley.from_cor(8e16, 9.0, 0.83, 30.0),
        PRESETS["kawazoe-1997-nonlinear"],
        Hysteretic.from_cor(5e4, 0.83, 1.0),
        SeriesBallString(1.5e5, 10.0, 4e4, 1e9),
        LinearContact(5e4, 0.0592),
        LinearContact(5e4, 0.0592, separation="force"),
    ],
    ids=["hunt-crossley", "hysteretic", "hysteretic-n1", "series", "linear", "linear-force"],
)
def test_compiled_march_solves_the_numpy_equations(standard_model, law):
    # the same discrete equations (cubic force, node equations, end condition), evaluated by
    # modal recursion instead of convolution tables: equal to round-off (measured <= 3e-15)
    rec = receptance(standard_model, [0.75], 0.057)
    t_est = float(np.min(law.contact_time_estimate(1.0 / rec.compliance, 30.0)))
    h, span, oc = t_est / 150, 2 * t_est, np.array([np.pi / t_est])
    ref = march(law, rec, np.array([30.0]), None, oc, 12.0, span, h, False)
    cases = MarchCases(kernel_law(law, 1), rec, np.array([30.0]), None, oc, 12.0)
    out, _, status, _ = march_compiled(
        cases, np.array([h]), np.array([span]), np.array([16 * t_est]), MarchOptions(extend=False)
    )
    assert status[0] == 0
    assert out.ball_velocity[0] == pytest.approx(ref.ball_velocity[0], rel=1e-12, abs=1e-12)
    assert out.contact_time[0] == pytest.approx(ref.contact_time[0], rel=1e-12)
    assert out.peak_force[0] == pytest.approx(ref.peak_force[0], rel=1e-12)


@pytest.mark.parametrize(
    ("law", "position", "speed"),
    [
        (Hysteretic(1e5, 2e5, 1.0), 0.75, 20.0),  # issue 22: 7-9e-6 off with n = 1
        (HuntCrossley(5e4, 1.0, 0.0), 0.9, 40.0),  # a plain linear spring cut at zero
        (get_law("series", ball_damping=1.0), 0.75, 20.0),  # was COR -0.276 vs 0.466
        (get_law("series", ball_stiffness=4e3), 0.75, 20.0),  # a soft ball: its t_c estimate 4x
    ],
    ids=["hysteretic-n1", "hunt-crossley-n1", "series-ball-damping-1", "series-soft-ball"],
)
def test_issue_22_cases_meet_the_tolerance(standard_model, law, position, speed):
    ref = _cvode_cor(law, standard_model, position, speed)
    for tol in (1e-4, 1e-6):
        out = solve_general(law, receptance(standard_model, position, 0.057), speed, tolerance=tol)
        assert -out.ball_velocity[0] / speed == pytest.approx(ref, abs=tol + CVODE_COR)


@pytest.mark.parametrize("family", ["hunt-crossley", "hysteretic", "series"])
def test_random_laws_meet_the_tolerance_against_cvode(model10, family):
    # issue 22: a seeded randomised set (strategies.contact_laws; derandomised) of each family
    # at random impacts, against CVODE, at the default tolerance 1e-6
    @settings(max_examples=5)
    @given(
        law=contact_laws(family),
        position=st.floats(0.4, 0.95),
        speed=st.floats(10.0, 40.0),
    )
    def check(law, position, speed):
        ref = _cvode_cor(law, model10, position, speed)
        rec = receptance(model10, position, 0.057)
        cor = -solve_general(law, rec, speed).ball_velocity[0] / speed
        assert cor == pytest.approx(ref, abs=1e-6 + CVODE_COR)

    check()


def test_an_unresolvable_state_is_refused_in_one_line(standard_model):
    # issue 22: a rigid ball on a linear bed (K_b 1e12 N/m, C_b 1 N s/m) raised "contact-law
    # Newton iteration did not converge"; K_b is now bounded to 1e8 N/m, and C_b = 0.01 N s/m
    # there makes the state relax in 1e-10 s: refused in one line
    law = get_law(
        "series", ball_stiffness=1e8, ball_damping=0.01, string_stiffness=27400.0,
        string_cubic=0.0,
    )  # fmt: skip
    with pytest.raises(AccuracyError, match="could not be met") as err:
        solve_general(law, receptance(standard_model, 0.75, 0.057), 20.0)
    assert "\n" not in str(err.value) and "solver cvode" in str(err.value)
    out = solve_general(law, receptance(standard_model, 0.75, 0.057), 20.0, refused="nan")
    assert np.isnan(out.ball_velocity[0])


def test_a_case_does_not_depend_on_its_batch(standard_model):
    # each case has its own step and modes: alone or among others, the same bits
    law = HuntCrossley(np.array([8e16, 1e17, 9e16]), 9.0, np.array([0.01, 0.02, 0.0]))
    positions = [0.6, 0.8, 0.9]
    rec = receptance(standard_model, positions, 0.057)
    speeds = np.array([25.0, 35.0, 20.0])
    both = solve_general(law, rec, speeds)
    for i, (k, alpha) in enumerate([(8e16, 0.01), (1e17, 0.02), (9e16, 0.0)]):
        one = solve_general(
            HuntCrossley(k, 9.0, alpha), receptance(standard_model, positions[i], 0.057), speeds[i]
        )
        assert both.ball_velocity[i] == one.ball_velocity[0]
        assert both.contact_time[i] == one.contact_time[0]


def test_a_batch_spans_frames(standard_model):
    # the cases of two frames (EI x 1 and x 0.3) and two laws' parameters in one call: each as
    # alone on its own frame
    soft = standard_model.scaled(0.3)
    law = PRESETS["kawazoe-1997-nonlinear"]
    laws = [law, Hysteretic(law.k1, 1.2 * law.k2, law.exponent)]
    recs = [receptance(standard_model, [0.7, 0.9], 0.057), receptance(soft, [0.7, 0.9], 0.057)]
    speeds = np.array([20.0, 40.0, 20.0, 40.0])
    out = solve_general(stack_laws(laws, [2, 2]), stack_receptances(recs), speeds)
    for i in range(4):
        one = solve_general(
            laws[i // 2], receptance([standard_model, soft][i // 2], [0.7, 0.9][i % 2], 0.057),
            speeds[i],
        )  # fmt: skip
        assert out.ball_velocity[i] == one.ball_velocity[0]


def test_no_energy_is_created(standard_model):
    # a passive law on a racket at rest never returns the ball faster than it came
    law = get_law("series", ball_stiffness=4e3)
    out = solve_general(law, receptance(standard_model, [0.6, 0.9], 0.057), np.array([20.0, 40.0]))
    assert np.all(np.abs(out.ball_velocity) <= np.array([20.0, 40.0]))
    assert math.isfinite(out.ball_velocity[0])


@pytest.mark.parametrize(
    "law",
    [
        PRESETS["kawazoe-1997-nonlinear"],
        PRESETS["itf-ball"],
        get_law("hunt-crossley"),
        HuntCrossley(5e4, 1.0, 0.0),
        Hysteretic.from_cor(5e4, 0.83, 1.0),
        get_law("series"),
        LinearContact(5e4, 0.0592),
    ],
    ids=[
        "kawazoe",
        "itf-ball",
        "hunt-crossley",
        "hunt-crossley-n1",
        "hysteretic-n1",
        "series",
        "linear",
    ],  # fmt: skip
)
def test_every_law_batched_across_frames_meets_1e_6(model10, law):
    # issue 27's target: every law (exponent n = 1 included) at COR error <= 1e-6 against CVODE
    # when batched, the cases of two frames (EI x 1 and x 0.4) in one compiled call
    soft = model10.scaled(0.4)
    recs = [receptance(model10, [0.6, 0.9], 0.057), receptance(soft, [0.6, 0.9], 0.057)]
    speeds = np.array([20.0, 40.0, 40.0, 20.0])
    out = solve_general(law, stack_receptances(recs), speeds)
    for i, (frame, x) in enumerate([(model10, 0.6), (model10, 0.9), (soft, 0.6), (soft, 0.9)]):
        ref = _cvode_cor(law, frame, x, speeds[i])
        assert -out.ball_velocity[i] / speeds[i] == pytest.approx(ref, abs=1e-6 + CVODE_COR)
