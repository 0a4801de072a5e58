"""The general integrator on the bed with the heavily damped linear ball: why it could end
contact falsely, and that, vouched, it agrees with the exact solution and CVODE."""

import numpy as np
import pytest

from fem_racket.contact.bed_ball import kawazoe_ball
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.general.receptance import Receptance
from fem_racket.impact.strung.impact import strung_impact
from fem_racket.impact.strung.point import clamped_point, strung_point
from fem_racket.strings.bed import StringBed

MB = 0.057


def test_coarse_steps_end_falsely_and_the_vouch_catches_it():
    # Clamped bed, kawazoe-1997-ball (c_b V_B0 = 1.36 kN at contact), 20 m/s: every mode, a
    # given number of steps per contact (no vouch). At 100 and 200 steps h omega_p >= 1 on the
    # bed's ~46 kHz pseudo-mode and the contact ends at a false zero (measured 0.09 and 0.21 ms,
    # the ball still moving forward); from 400 steps it is the true 4.53 ms (paper sec. 2.1.1).
    p = clamped_point(StringBed())
    law = kawazoe_ball(MB)
    rec = Receptance(p.omega, p.a[None, :], np.zeros((1, 2)), np.array([MB]))
    t_c = {}
    for steps in (100, 200, 400):
        out = solve_general(law, rec, 20.0, steps=steps, beta=np.inf, tolerance=None)
        t_c[steps] = float(out.contact_time[0])
    assert t_c[100] < 2.5e-4 and t_c[200] < 2.5e-4
    assert t_c[400] == pytest.approx(4.5312e-3, rel=1e-4)
    assert p.omega.max() * 4.53e-3 / 200 > 1.0
    # the vouched integrator (default tolerance 1e-6) against the exact solution
    gen = strung_impact(p, law, MB, 20.0, solver="general")
    exact = strung_impact(p, law, MB, 20.0, solver="exact")
    assert gen.cor == pytest.approx(exact.cor, abs=1e-6)
    assert gen.contact_time == pytest.approx(exact.contact_time, rel=1e-6)


def test_general_exact_cvode_agree_on_the_free_strung_racket():
    # The free strung racket at 0.8 L, 270 N, 30 m/s: general (COR tolerance 1e-6: measured
    # 8e-9 on 20 elements), CVODE (rtol 1e-10) and the exact roots; every mode of a coarser
    # structure (8 elements, 12 bed modes), which CVODE's dense Jacobian keeps quick
    from fem_racket import FrameModel, standard_frame

    model = FrameModel.build(standard_frame(), 8)
    p = strung_point(model, StringBed(tension_n=270.0), 0.8, bed_modes=12)
    law = kawazoe_ball(MB)
    exact = strung_impact(p, law, MB, 30.0, solver="exact")
    gen = strung_impact(p, law, MB, 30.0, solver="general")
    cv = strung_impact(p, law, MB, 30.0, solver="cvode")
    assert gen.cor == pytest.approx(exact.cor, abs=1e-6)
    assert gen.contact_time == pytest.approx(exact.contact_time, rel=1e-6)
    assert cv.cor == pytest.approx(exact.cor, abs=1e-9)
    assert cv.contact_time == pytest.approx(exact.contact_time, abs=1e-10)


def test_solver_general_takes_the_linear_ball(standard_model):
    from fem_racket.impact.simulate import simulate

    bed = StringBed(tension_n=230.0)
    gen = simulate(standard_model, strings=bed, position=0.8, speed=25.0, solver="general")
    exact = simulate(standard_model, strings=bed, position=0.8, speed=25.0)
    assert gen.solver == "general" and exact.solver == "exact"
    assert gen.cor == pytest.approx(exact.cor, abs=1e-6)
