"""Stiff slides of the vector tangential contact (fem_racket.impact.tangential.slide): a law whose
normal force rises from zero with zero slope (Hunt-Crossley) off the axis, where the explicit
integrator once ran without end (audit A8). Checked against the 1-D march, the fixed-step
radial return, a tighter tolerance and the energy balance; a slide without end is refused."""

import math
from dataclasses import dataclass

import numpy as np
import pytest

from fem_racket.contact.linear import zeta_from_cor
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate_oblique import simulate_oblique
from fem_racket.impact.tangential import slide
from fem_racket.impact.tangential.march import march
from fem_racket.impact.tangential.normal import ClampedNormal
from fem_racket.impact.tangential.oblique import BallMotion, RacketYaw
from fem_racket.impact.tangential.plane import LineSolution, PlaneContact, march_plane
from fem_racket.impact.tangential.stepping import step_plane
from fem_racket.validation import AccuracyError

V, M, MU, ETA2 = 20.0, 0.057, 0.4, 0.14
# the free racket's compliance 5 cm off the axis, over the ball's (as test_plane.py)
ANISOTROPIC = (1 + 1 / 0.6) / M * np.eye(2) + BallMotion(
    M, 0, 0, 0.36, yaw=RacketYaw(0.017, 0.2, 0.05)
).racket_compliance()


@pytest.fixture(scope="module")
def hunt_crossley():
    # the reproducer: simulate --angle 30 --position 0.7 --law hunt-crossley --offset 0.01
    # (ran > 200 s growing past 330 MB; now ~2 s)
    inc = Incidence(angle=30.0)
    return simulate_oblique(
        incidence=inc, speed=V, position=0.7, offset=0.01, law="hunt-crossley"
    ).tangential.plane


def _with(sol, compliance):
    return PlaneContact(sol.contact.friction, sol.contact.stiffness, compliance)


def test_the_reproducer_is_stiff_and_meets_a_tighter_tolerance(hunt_crossley, monkeypatch):
    sol = hunt_crossley
    assert not isinstance(sol, LineSolution)
    assert [p.kind for p in sol.phases] == ["slide", "grip", "slide"]
    # the first slide starts at t = 0 with rho at its floor: Radau's side of STIFF
    c, normal = sol.contact, sol.normal
    peak = float(np.max(normal.smooth_force(normal.grid)))
    floor = slide.FLOOR * c.friction * peak / c.stiffness
    size = float(np.linalg.norm(sol.slip_in))
    assert slide.stiffness_index(normal, 0.0, size, floor, c.friction / c.stiffness) > slide.STIFF
    # rtol 1e-13 against 1e-12 (the final slip's error scales with rtol): 1e-9 V
    monkeypatch.setattr(slide, "RTOL", 1e-12)
    loose = march_plane(c, normal, sol.slip_in)
    assert loose.final_slip == pytest.approx(sol.final_slip, abs=1e-9 * V)


@dataclass(frozen=True)
class CubeSine:
    """A closed-form normal history that rises from zero with zero slope, as Hunt-Crossley's
    (F ~ t^3 here): F = F_p sin^3(omega t) over [0, pi / omega], F' and P exact, so the 1-D
    march (on F, F', P) and the vector one (on F, F') see the same force."""

    peak: float = 1800.0
    omega: float = math.pi / 5e-3
    stiffness: float = 3.5e4

    @property
    def end(self):
        return math.pi / self.omega

    @property
    def grid(self):
        return np.linspace(0.0, self.end, 501)

    def force(self, t):
        return self.peak * np.sin(self.omega * np.asarray(t)) ** 3

    def rate(self, t):
        w = self.omega * np.asarray(t)
        return 3.0 * self.peak * self.omega * np.sin(w) ** 2 * np.cos(w)

    def impulse(self, t):
        c = np.cos(self.omega * np.asarray(t))
        return self.peak / self.omega * (2.0 / 3.0 - c + c**3 / 3.0)

    slope, smooth_force = rate, force


@pytest.mark.parametrize("across, ratio", [(0.0, 0.2), (1e-12, 1.5), (1e-10, 0.2)])
def test_offset_to_zero_meets_the_1d_march(across, ratio):
    # side angle 0 and the off-axis coupling A_xy -> 0 (F ~ t^3 from zero with zero slope, so
    # the first slide is stiff): the vector march (slides by Radau) meets the 1-D closed-form
    # march along x (march.py) to 1e-9 V
    normal = CubeSine()
    a = np.diag(np.diag(ANISOTROPIC))
    a[0, 1] = a[1, 0] = across * a[0, 0]
    c = PlaneContact(MU, normal.stiffness / ETA2, a)
    vector = march_plane(c, normal, np.array([ratio * V, 0.0]), line=False)
    assert not isinstance(vector, LineSolution)
    ref = march(c.line(np.array([1.0, 0.0])), normal, ratio * V)
    assert vector.final_slip == pytest.approx([ref.final_slip, 0.0], abs=1e-9 * V)
    assert vector.regime == ref.regime


def _dissipation(sol, n=20001):
    """Slider work int mu F (s.d - mu F' / k_t) over the slides, d the stretch's direction."""
    from scipy.integrate import simpson

    c, normal, total = sol.contact, sol.normal, 0.0
    for p in (q for q in sol.phases if q.kind == "slide" and q.end > q.start):
        t = np.linspace(p.start, p.end, n)
        s, f = sol.at(t)
        size = np.linalg.norm(f, axis=1)
        d = -f / np.where(size > 0, size, 1.0)[:, None]
        lag = c.friction * normal.rate(t) / c.stiffness
        total += simpson(c.friction * normal.force(t) * (np.sum(s * d, axis=1) - lag), x=t)
    return total


@pytest.mark.parametrize("theta", [0.9, -2.3])
def test_energy_never_created_and_its_loss_is_the_sliders_work(theta):
    # the tangential kinetic energy 1/2 s.A^-1 s (ball and racket, relative) never grows; the
    # spring is unstretched at both ends, so its loss is the slider's work (F, F' exact)
    normal = CubeSine()
    c = PlaneContact(MU, normal.stiffness / ETA2, ANISOTROPIC)
    s0 = 0.5 * V * np.array([math.cos(theta), math.sin(theta)])
    out = march_plane(c, normal, s0)
    assert not isinstance(out, LineSolution)
    inv = np.linalg.inv(c.compliance)
    before, after = 0.5 * s0 @ inv @ s0, 0.5 * out.final_slip @ inv @ out.final_slip
    assert after <= before * (1 + 1e-12)
    assert before - after == pytest.approx(_dissipation(out), rel=1e-6)


def test_turning_slip_against_radial_return_steps(hunt_crossley):
    # the slip turns (oblique to the axis, A coupled): the fixed-step radial return
    # (stepping.py, first order) converges to the vector march, ~4x per 4x steps
    sol = hunt_crossley
    a = sol.contact.compliance + np.array([[0.0, 2.0], [2.0, 0.0]])
    c = _with(sol, a)
    s0 = 0.3 * V * np.array([math.cos(0.7), math.sin(0.7)])
    ref = march_plane(c, sol.normal, s0)
    errs = [np.abs(step_plane(c, sol.normal, s0, n)[1][-1] - ref.final_slip).max()
            for n in (8000, 32000)]  # fmt: skip
    assert errs[1] < 1e-5 * V
    assert errs[0] / errs[1] > 2.5


def test_a_slide_without_end_is_refused_in_one_line(hunt_crossley, monkeypatch):
    monkeypatch.setattr(slide, "MAX_EVALUATIONS", 500)
    sol = hunt_crossley
    with pytest.raises(AccuracyError, match=r"^friction = 0.4 is not allowed .*its end$"):
        march_plane(sol.contact, sol.normal, sol.slip_in)


def test_the_paper_laws_slides_stay_explicit_bit_for_bit(monkeypatch):
    # the paper's spring-dashpot (force from c V at t = 0) off the axis: under STIFF, so DOP853
    # as before; forbidding Radau (STIFF = inf) changes no bit
    m, vn = 0.057, 20.0
    normal = ClampedNormal(m, 3.5e4, zeta_from_cor(0.83), vn)
    a = (1 + 1 / 0.6) / m * np.eye(2) + np.array([[1.5, -0.8], [-0.8, 3.0]])
    c = PlaneContact(0.4, 3.5e4 / 1.5, a)
    runs = []
    for stiff in (slide.STIFF, math.inf):
        monkeypatch.setattr(slide, "STIFF", stiff)
        runs.append([march_plane(c, normal, r * vn * np.array([0.8, 0.6])).final_slip
                     for r in (0.2, 0.6, 1.2)])  # fmt: skip
    assert all((x == y).all() for x, y in zip(*runs, strict=True))
