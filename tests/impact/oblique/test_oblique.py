"""Oblique, spinning impacts on the free racket and the clamped head
(fem_racket.impact.oblique.solve): the normal outcome is the head-on one, solvers agree, momentum
and energy hold."""

import math

import numpy as np
import pytest

from fem_racket.impact.analytic.rigid import clamped_impact
from fem_racket.impact.incidence import RPM, Incidence
from fem_racket.impact.simulate import simulate
from fem_racket.impact.simulate_oblique import simulate_oblique
from fem_racket.validation import InputError

STROKE = Incidence(angle=40.0, spin=-3820.0)


@pytest.fixture(scope="module")
def exact():
    return simulate_oblique(incidence=STROKE, speed=25.0)


def test_no_friction_leaves_the_head_on_impact_and_the_spin(exact):
    # mu = 0: the normal outcome is the head-on impact at V cos(angle) to 1e-12, spin unchanged
    inc = Incidence(angle=40.0, spin=-3820.0, friction=0.0)
    out = simulate_oblique(incidence=inc, speed=25.0)
    head_on = simulate(speed=25.0 * math.cos(math.radians(40.0)), output_step=1e-5)
    assert out.normal.cor == pytest.approx(head_on.cor, rel=1e-12)
    assert out.normal.contact_time == pytest.approx(head_on.contact_time, rel=1e-12)
    s = out.summary()
    assert s["spin_out_rpm"] == -3820.0
    assert s["contact_regime"] == "slide"
    assert s["angle_out_deg"] == pytest.approx(
        math.degrees(math.atan2(25 * math.sin(math.radians(40)), head_on.ball_speed_out)),
        rel=1e-12,
    )


def test_head_on_without_spin_is_todays_impact():
    out = simulate_oblique(incidence=Incidence(), speed=20.0)
    today = simulate(speed=20.0, output_step=1e-5)
    s = out.summary()
    assert s["cor"] == today.cor and s["contact_time_s"] == today.contact_time
    assert s["ball_speed_out_m_s"] == today.ball_speed_out
    assert s["spin_out_rpm"] == 0.0 and s["angle_out_deg"] == 0.0
    assert s["contact_regime"] == "grip"  # no slip ever: the ball grips (with zero force)


@pytest.mark.parametrize("solver, tol", [("cvode", 1e-9), ("general", 1e-4)])
def test_solvers_agree(exact, solver, tol):
    # exact eigen-solution, CVODE (rtol 1e-10) and the general integrator (fourth order, COR
    # to ~1e-5 at its default step, DESIGN.md section 11) give one tangential outcome
    other = simulate_oblique(incidence=STROKE, speed=25.0, solver=solver).summary()
    ref = exact.summary()
    for key in ("spin_out_rpm", "angle_out_deg", "ball_speed_out_m_s"):
        assert other[key] == pytest.approx(ref[key], rel=tol), key
    # e_T = -s_end / s_0 near 0 here (the ball leaves nearly rolling): absolute
    assert other["tangential_cor"] == pytest.approx(ref["tangential_cor"], abs=tol)
    assert other["contact_regime"] == ref["contact_regime"]


def test_momentum_and_energy_of_ball_and_free_racket(exact):
    # along the face: m v_t + M V conserved (the racket recoils as a rigid body); the ball's
    # angular momentum about the contact point I omega + m R v_t conserved; kinetic energy
    # (normal + tangential + spin + racket) never created
    t = exact.tangential
    m, big_m = t.ball.mass, exact.normal.model.props.mass
    v_t = 25.0 * math.sin(math.radians(40.0))
    assert m * t.tangential_speed_out + big_m * t.racket_speed_out == pytest.approx(
        m * v_t, rel=1e-12
    )
    lhs = t.inertia * t.spin_out + m * STROKE.radius * t.tangential_speed_out
    assert lhs == pytest.approx(t.inertia * STROKE.spin_rad_s + m * STROKE.radius * v_t, rel=1e-12)
    e_t0, e_t1 = t.tangential_energy()
    n = exact.normal
    e_n0 = 0.5 * m * n.impact.speed**2
    e_n1 = n.energies()
    frame = e_n1["frame_kinetic"][-1] + e_n1["frame_strain"][-1]
    assert 0.5 * m * n.ball_velocity[-1] ** 2 + frame + e_t1 < e_n0 + e_t0


def test_histories_of_slip_and_tangential_force(exact):
    h = exact.histories()
    assert set(h) == {"time [s]", "slip velocity [m/s]", "tangential force [N]"}
    # the force opposes the slip while the ball slides, and its impulse is the ball's
    # tangential momentum change (trapezoid on the 1e-5 s output times)
    t, f = h["time [s]"], h["tangential force [N]"]
    j = np.trapezoid(f, t)
    assert j == pytest.approx(exact.tangential.impulse, rel=1e-4)
    assert h["slip velocity [m/s]"][0] == pytest.approx(
        25 * math.sin(math.radians(40)) + 0.033 * 3820 * RPM, rel=1e-12
    )


def test_clamped_head_the_issues_stroke():
    # fem-racket simulate --angle 40 --spin -3820 --speed 25 --clamped --compliance-ratio 1.5
    # (Mindlin's, the default before the fit to measured spins, test_spin_calibration.py): eqs
    # 1-3 for the normal impact; the ball slides (after the dashpot's first 0.11 ms) and leaves
    # with topspin
    out = simulate_oblique(
        incidence=Incidence(angle=40.0, spin=-3820.0, compliance_ratio=1.5),
        speed=25.0,
        clamped=True,
    )
    s = out.summary()
    v_n = 25.0 * math.cos(math.radians(40.0))
    eqs = clamped_impact(0.057, s["kcb_n_m"], s["zeta"], v_n)
    assert s["cor"] == eqs.cor and s["rebound_speed_m_s"] == -eqs.rebound_velocity
    assert s["spin_out_rpm"] > 0 and "slide" in s["contact_regime"]
    # the friction impulse is mu P(t_F) (the ball slides from its first 0.11 ms)
    normal = out.tangential.solution.normal
    assert -out.tangential.impulse < 0.4 * normal.impulse(normal.end)
    assert -out.tangential.impulse > 0.99 * 0.4 * normal.impulse(normal.end)


def test_clamped_force_criterion_is_the_gross_slip_closed_form():
    # eta^2 = 0 (rigid tangential contact) and the force criterion: the ball slides throughout
    # and v_t out = v_t in - mu v_n beta_t (1 + e) in slip velocity (DESIGN.md section 10),
    # e the printed COR, to 1e-9
    inc = Incidence(angle=60.0, spin=-2000.0, compliance_ratio=0.0)
    out = simulate_oblique(incidence=inc, speed=20.0, clamped=True, separation="force")
    s = out.summary()
    v_n, v_t = inc.components(20.0)
    s0 = v_t - inc.radius * inc.spin_rad_s
    s_out = out.tangential.tangential_speed_out - inc.radius * out.tangential.spin_out
    assert s["contact_regime"] == "slide"
    assert s_out == pytest.approx(s0 - 0.4 * v_n * inc.beta_t * (1 + s["cor"]), abs=1e-9 * s0)


def test_oblique_input_checks():
    with pytest.raises(InputError, match="^position is not allowed with a clamped head"):
        simulate_oblique(incidence=STROKE, clamped=True, position=0.7)
    with pytest.raises(InputError, match="^an oblique impact needs the normal impact.s histories"):
        simulate_oblique(incidence=STROKE, output_step=None)


def test_an_impact_problem_with_an_incidence_through_the_solvers(exact):
    # ImpactProblem(incidence=...) is solved by any Solver as its normal impact (head_on: the
    # ball at V cos(angle)) and then the tangential contact; solve and solve_many agree with
    # simulate_oblique
    from fem_racket.frame.hand import Hand
    from fem_racket.impact.incidence import head_on
    from fem_racket.impact.problem import ImpactProblem
    from fem_racket.impact.solvers import make_solver

    problem = ImpactProblem.build(speed=25.0, incidence=STROKE)
    normal = head_on(problem)
    assert normal.incidence is None
    assert normal.impact.speed == pytest.approx(25.0 * math.cos(math.radians(40.0)), rel=1e-15)
    assert head_on(normal) is normal
    solver = make_solver("exact")
    one = solver.solve(problem).summary()
    (many,) = solver.solve_many([problem])
    ref = exact.summary()
    for key in ("spin_out_rpm", "angle_out_deg", "contact_regime", "cor"):
        assert one[key] == ref[key] == many.summary()[key]
    assert "40 deg, -3820 rpm" in repr(problem)
    # a hand-held racket takes an incidence in the plane of its long axis (issue 26, item 2),
    # not one across the face
    held = ImpactProblem.build(hand=Hand(), incidence=STROKE)
    assert held.held and held.incidence is STROKE
    with pytest.raises(InputError, match="^side_angle and side_spin are not allowed with a hand"):
        solver.solve(held.replace(incidence=Incidence(angle=40.0, side_spin=500.0)))
    with pytest.raises(InputError, match="^incidence = 40 is not allowed"):
        ImpactProblem.build(incidence=40)


def test_a_nonlinear_law_general_and_cvode_agree():
    # Hunt-Crossley (force rising from zero, so the ball slides at once): the general
    # integrator and CVODE give one tangential outcome (their normal COR agree to ~1e-5,
    # DESIGN.md section 11); k_n is the secant stiffness at maximum compression
    inc = Incidence(angle=30.0, spin=500.0)
    a = simulate_oblique(incidence=inc, speed=25.0, law="hunt-crossley", solver="general")
    b = simulate_oblique(incidence=inc, speed=25.0, law="hunt-crossley", solver="cvode")
    sa, sb = a.summary(), b.summary()
    assert sa["contact_regime"] == sb["contact_regime"]
    assert sa["contact_regime"].startswith("slide")
    for key in ("spin_out_rpm", "angle_out_deg", "ball_speed_out_m_s"):
        assert sa[key] == pytest.approx(sb[key], rel=1e-4), key
    assert sa["tangential_stiffness_n_m"] == pytest.approx(sb["tangential_stiffness_n_m"], rel=1e-3)
