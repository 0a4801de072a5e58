"""Friction on the slip vector (fem_racket.impact.tangential.plane and plane_ode): the 1-D march
along a line, Stronge's closed forms in any direction, a second (fixed-step, radial-return)
path, and the energy balance."""

import math

import numpy as np
import pytest

from fem_racket.contact.linear import zeta_from_cor
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.tangential.march import TangentialContact, march
from fem_racket.impact.tangential.normal import ClampedNormal, StrongeNormal
from fem_racket.impact.tangential.oblique import BallMotion, RacketYaw, tangential_impact
from fem_racket.impact.tangential.plane import LineSolution, PlaneContact, march_plane
from fem_racket.impact.tangential.stepping import step_plane
from fem_racket.impact.tangential.stronge import stronge_outcome

M, KN, E, V = 0.057, 3.0e4, 0.8, 20.0
MU, ETA2, BETA = 0.4, 1.5, 1.0 + 1.0 / 0.6
NORMAL = StrongeNormal(M, KN, E, V)
ISOTROPIC = BETA / M * np.eye(2)
# the free racket's compliance at 0.75 L, 5 cm off the axis (M 0.36 kg, b 0.2 m, I_n 0.017)
ANISOTROPIC = (
    ISOTROPIC + BallMotion(0.057, 0, 0, 0.36, yaw=RacketYaw(0.017, 0.2, 0.05)).racket_compliance()
)
# s_0 / V across Stronge's regimes (bounds mu eta^2 = 0.6 and 1.17, test_tangential.py)
RATIOS = [0.1, 0.3, 0.8, 1.0, 1.16, 1.5, 3.0]


def _unit(theta):
    return np.array([math.cos(theta), math.sin(theta)])


@pytest.mark.parametrize("seed", range(4))
def test_along_the_long_axis_it_is_the_1d_march_bit_for_bit(seed):
    # nothing across the face (A diagonal, s_y = 0): today's march, unchanged
    rng = np.random.default_rng(seed)
    a = np.diag([BETA / M + rng.uniform(0, 3), BETA / M + rng.uniform(0, 5)])
    s0 = rng.uniform(-40, 40)
    c = PlaneContact(MU, KN / ETA2, a)
    sol = march_plane(c, NORMAL, np.array([s0, 0.0]))
    ref = march(TangentialContact(MU, KN / ETA2, 1.0 / a[0, 0]), NORMAL, s0)
    assert isinstance(sol, LineSolution)
    assert sol.final_slip[0] == ref.final_slip and sol.final_slip[1] == 0.0
    assert sol.impulse[0] == ref.impulse and sol.regime == ref.regime


@pytest.mark.parametrize("line", [True, False])
@pytest.mark.parametrize("r", RATIOS)
def test_stronges_closed_forms_along_any_direction(r, line):
    # A clamped head (A = beta_t / m 1): the slip stays on its line, so Stronge's closed forms
    # (stronge.py, Stronge 2000 section 5.3) hold along any direction; the vector march
    # (line=False: grips in closed form, slides by DOP853 at rtol 1e-13) meets them to 1e-9 V
    c = PlaneContact(MU, KN / ETA2, ISOTROPIC)
    for theta in (0.3, 2.0, -2.6):
        e = _unit(theta)
        sol = march_plane(c, NORMAL, r * V * e, line=line)
        ref = stronge_outcome(r, MU, E, ETA2, BETA)
        assert sol.final_slip == pytest.approx(ref.slip * V * e, abs=1e-9 * V)
        assert sol.regime == ref.regime


@pytest.mark.parametrize("line", [True, False])
def test_gross_slip_closed_form_in_any_direction(line):
    # v_t out = v_t in - mu v_n beta_t (1 + e) along the slip's direction (issue 26), to 1e-9
    for eta2 in (ETA2, 0.0):
        k = math.inf if eta2 == 0.0 else KN / eta2
        c = PlaneContact(MU, k, ISOTROPIC)
        for theta in np.linspace(-3.0, 3.0, 7):
            e = _unit(theta)
            sol = march_plane(c, NORMAL, 2.5 * V * e, line=line)
            assert sol.regime == "slide"
            want = (2.5 * V - MU * V * BETA * (1 + E)) * e
            assert sol.final_slip == pytest.approx(want, abs=1e-9 * V)


def test_rigid_contact_slides_then_rolls_in_any_direction():
    # eta^2 = 0 (Routh): slides along its line until s = 0, then rolls; the grip starts where
    # mu beta_t P(t) / m = |s_0| (as in 1-D), to 1e-9 of the contact time
    c = PlaneContact(MU, math.inf, ISOTROPIC)
    sol = march_plane(c, NORMAL, 0.8 * V * _unit(2.2), line=False)
    assert sol.regime == "slide-grip" and not sol.final_slip.any()
    t_g = sol.grip_intervals[0][0]
    assert MU * BETA * NORMAL.impulse(t_g) / M == pytest.approx(0.8 * V, rel=1e-9)


@pytest.mark.parametrize("r, theta", [(0.3, 0.6), (1.0, 0.6), (2.0, 2.5), (0.7, -1.2)])
def test_vector_march_against_radial_return_steps(r, theta):
    # A free racket off the axis couples the two directions (A not a multiple of 1): the slip
    # turns. The fixed-step radial return (stepping.py, first order across the switches)
    # converges to the vector march: error below 1e-5 V at 32 000 steps, falling ~4x per 4x
    c = PlaneContact(MU, KN / ETA2, ANISOTROPIC)
    s0 = r * V * _unit(theta)
    sol = march_plane(c, NORMAL, s0)
    assert not isinstance(sol, LineSolution)
    errs = []
    for n in (8000, 32000):
        _, s, _ = step_plane(c, NORMAL, s0, n)
        errs.append(np.abs(s[-1] - sol.final_slip).max())
    assert errs[1] < 1e-5 * V
    assert errs[0] / errs[1] > 2.5
    # the histories agree too (mid-contact)
    t, s, f = step_plane(c, NORMAL, s0, 32000)
    s_m, f_m = sol.at(t[::4000])
    assert s_m == pytest.approx(s[::4000], abs=2e-5 * V)
    assert f_m == pytest.approx(f[::4000], abs=2e-4 * M * V * NORMAL.omega)


def _dissipation(out, n=20001):
    """Slider work int mu F (s.d - mu F' / k_t) over the slides, d the stretch's direction."""
    from scipy.integrate import simpson

    sol = out.plane
    c, normal, total = sol.contact, sol.normal, 0.0
    for a, b in _slides(sol):
        t = np.linspace(a, b, n)
        s, f = sol.at(t)
        size = np.linalg.norm(f, axis=1)
        d = -f / np.where(size > 0, size, 1.0)[:, None]
        lag = 0.0 if c.rigid else c.friction * normal.rate(t) / c.stiffness
        total += simpson(c.friction * normal.force(t) * (np.sum(s * d, axis=1) - lag), x=t)
    return total


def _slides(sol):
    if isinstance(sol, LineSolution):
        return [(p.start, p.end) for p in sol.line.phases if p.kind == "slide" and p.end > p.start]
    return [(p.start, p.end) for p in sol.phases if p.kind == "slide" and p.end > p.start]


@pytest.mark.parametrize("seed", range(6))
def test_energy_never_created_and_momentum_kept_across_the_face(seed):
    # Random incidence in 3-D, side spin, a free racket off the axis (translation and yaw):
    # the kinetic energy in the face's plane never grows and its loss is the slider's work;
    # linear momentum (x, y) and the angular momentum about the face normal are conserved,
    # and so is the ball's angular momentum about the contact point (both axes)
    rng = np.random.default_rng(seed)
    inc = Incidence(
        angle=rng.uniform(0, 60),
        spin=rng.uniform(-4000, 4000),
        friction=rng.uniform(0.1, 0.8),
        compliance_ratio=rng.choice([0.0, rng.uniform(0.3, 3.0)]),
        side_angle=rng.uniform(-40, 40),
        side_spin=rng.uniform(-3000, 3000),
    )
    vn, vt = inc.components(25.0)
    vy = inc.lateral_speed(25.0)
    normal = ClampedNormal(M, 3.5e4, zeta_from_cor(0.83), vn)
    yaw = RacketYaw(0.017, rng.uniform(-0.1, 0.25), rng.uniform(-0.1, 0.1))
    big_m, v_r = 0.36, rng.uniform(-3, 3)
    ball = BallMotion(M, vt, normal.rebound_speed(), big_m, v_r, vy, 0.0, yaw)
    out = tangential_impact(inc, normal, ball)
    before, after = out.tangential_energy()
    assert after <= before * (1 + 1e-12)
    assert before - after == pytest.approx(_dissipation(out), rel=2e-6, abs=1e-8)
    # linear momentum of ball + racket (centre of gravity) along and across the face
    v_cg, w = out._racket_out()
    assert M * out.tangential_speed_out + big_m * v_cg[0] == pytest.approx(M * vt + big_m * v_r)
    assert M * out.lateral_speed_out + big_m * v_cg[1] == pytest.approx(M * vy, abs=1e-12)
    # angular momentum about the face normal through the impact point's CG-frame origin
    # (the racket's CG): ball m (b v_y - y v_x), racket I_n w (it did not turn before)
    b, y = yaw.arm, yaw.offset

    def lz(vx, vy_, w_):
        return M * (b * vy_ - y * vx) + yaw.inertia * w_

    assert lz(out.tangential_speed_out, out.lateral_speed_out, w) == pytest.approx(
        lz(vt, vy, 0.0), abs=1e-12
    )
    r, i_b = inc.radius, out.inertia
    assert i_b * out.spin_out + M * r * out.tangential_speed_out == pytest.approx(
        i_b * inc.spin_rad_s + M * r * vt, abs=1e-13
    )
    assert i_b * out.side_spin_out + M * r * out.lateral_speed_out == pytest.approx(
        i_b * inc.side_spin_rad_s + M * r * vy, abs=1e-13
    )


def test_vector_march_refuses_chattering_in_one_line(monkeypatch):
    # the vector march stops at MAX_PHASES as the 1-D one does (march.check_chattering): one
    # InputError naming the friction, no RuntimeError traceback; a limit of 1 phase makes the
    # rigid slide-grip march (one switch) reach it
    import fem_racket.impact.tangential.march as march_module
    from fem_racket.validation import InputError

    monkeypatch.setattr(march_module, "MAX_PHASES", 1)
    c = PlaneContact(MU, math.inf, ISOTROPIC)
    with pytest.raises(InputError, match=r"^friction = 0.4 is not allowed .*chattering\)$"):
        march_plane(c, NORMAL, 0.8 * V * _unit(2.2), line=False)
