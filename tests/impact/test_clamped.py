"""A clamped head as an ImpactProblem structure: the ball on a rigid support or on the string bed
clamped at its edge, answered by the exact and general solvers (the ODE solvers refuse it)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from fem_racket.contact.bed_ball import kawazoe_ball
from fem_racket.contact.linear import PAPER_CLAMPED_COR, Ball, LinearContact, zeta_from_cor
from fem_racket.contact.presets import get_law
from fem_racket.frame.model import FrameModel
from fem_racket.impact.clamped import CENTRE, ClampedHead, ClampedImpact
from fem_racket.impact.exact.engine import EngineOptions, modal_impacts
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.problem import Impact, ImpactProblem
from fem_racket.impact.solvers import make_solver
from fem_racket.impact.strung.point import clamped_point
from fem_racket.impact.swing import Swing
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError

RIGID = ClampedHead()


@pytest.fixture(scope="module")
def bed():
    return ClampedHead(StringBed())


def _problem(head, speed, **fields):
    return ImpactProblem(head, Impact(CENTRE, speed), **fields)


@pytest.mark.parametrize("speed", [20.0, 30.0, 40.0])
def test_rigid_support_is_the_papers_clamped_spring_dashpot(speed):
    # Kawazoe & Kanda 1997 eqs 1-4: on a fixed support the linear spring-dashpot returns the
    # clamped COR 0.83 at every speed, its contact time half a damped period pi / omega_d,
    # omega_d = sqrt(K_CB / m_B) sqrt(1 - zeta^2) (displacement separation of a Kelvin-Voigt
    # oscillator released from delta = 0: exact, so to round-off)
    r = make_solver("exact").solve(_problem(RIGID, speed))
    assert isinstance(r, ClampedImpact) and r.time is None
    k, zeta, m = LinearContact.for_speed(speed).stiffness, zeta_from_cor(0.83), Ball().mass
    assert r.cor == pytest.approx(PAPER_CLAMPED_COR, rel=1e-12)
    assert r.contact_time == pytest.approx(
        math.pi / (math.sqrt(k / m) * math.sqrt(1.0 - zeta**2)), rel=1e-12
    )


def test_general_agrees_with_exact_on_both_heads(bed):
    # two independent paths: the eigen-solution and the time-stepped general integrator, the
    # latter vouched for at the COR tolerance 1e-6
    for head in (RIGID, bed):
        problems = [_problem(head, v, kcb=4e4, zeta=0.1) for v in (15.0, 30.0)]
        ex = make_solver("exact").solve_many(problems)
        ge = make_solver("general").solve_many(problems)
        for a, b in zip(ex, ge, strict=True):
            assert b.cor == pytest.approx(a.cor, abs=2e-6)
            assert b.contact_time == pytest.approx(a.contact_time, rel=1e-4)
            assert b.time[-1] == pytest.approx(b.contact_time, rel=2e-2)
            assert b.force.max() > 0.0 and b.deflection.shape == b.time.shape


def test_the_bed_is_the_clamped_point_and_softens_the_contact(bed):
    # the exact solver runs the engine on the clamped bed's modes (every mode with tolerance
    # None): the same numbers as the engine called on them directly
    w, a = clamped_point(StringBed()).flexible
    ref = modal_impacts(
        w, a, 0.0, speed=25.0, kcb=8e4, zeta=0.3, options=EngineOptions(tolerance=None)
    )
    r = make_solver("exact", tolerance=None).solve(_problem(bed, 25.0, kcb=8e4, zeta=0.3))
    assert r.cor == float(ref.cor) and r.contact_time == float(ref.contact_time)
    # a ball in series with the bed is softer than the ball alone on a rigid support
    rigid = make_solver("exact").solve(_problem(RIGID, 25.0, kcb=8e4, zeta=0.3))
    assert r.contact_time > rigid.contact_time


def test_many_is_each_one(bed):
    law = get_law("hysteretic")
    problems = [_problem(RIGID, v, law=law) for v in (10.0, 25.0, 40.0)]
    many = make_solver("auto").solve_many(problems)  # auto picks general for the law
    for p, r in zip(problems, many, strict=True):
        one = make_solver("general").solve(p)
        assert (r.cor, r.contact_time) == pytest.approx((one.cor, one.contact_time), rel=1e-12)
    # auto picks the exact solution for the paper's law, one problem or many
    p = _problem(RIGID, 30.0)
    assert make_solver("auto").solve(p).time is None
    assert make_solver("auto").solve_many([p])[0].cor == make_solver("exact").solve(p).cor
    # the ball's own law is allowed on the clamped bed (it is fitted there)
    r = make_solver("general").solve(_problem(bed, 20.0, law=kawazoe_ball(0.057)))
    assert 0.0 < r.cor < 1.0


def test_what_a_clamped_head_refuses(bed):
    model = FrameModel.build(None, 8)
    cases = [
        ({"swing": Swing(5.0, 0.0)}, "swing is not allowed with a clamped head"),
        ({"offset": 0.01}, "offset = 0.01 m is not allowed with a clamped head"),
        ({"strings": StringBed()}, "strings is not allowed with a clamped head"),
        ({"incidence": Incidence(20.0, 0.0)}, "incidence is not allowed with a clamped head"),
    ]
    for fields, message in cases:
        with pytest.raises(InputError, match=message):
            _problem(RIGID, 20.0, **fields)
    with pytest.raises(InputError, match="position = 0.6 x/L is not allowed with a clamped"):
        ImpactProblem(RIGID, Impact(0.6, 20.0))
    with pytest.raises(InputError, match="must be a StringBed"):
        ClampedHead(model)
    p = _problem(RIGID, 20.0)
    for name in ("cvode", "bdf"):
        with pytest.raises(InputError, match=f"solver = '{name}' is not allowed with a clamped"):
            make_solver(name).solve(p)
    with pytest.raises(
        InputError,
        match="modes = 10 is not allowed with solver 'exact' on a clamped head: every mode",
    ):
        make_solver("exact", modes=10).solve(p)
    with pytest.raises(InputError, match="output_step = 0.0001 is not allowed with solver 'gen"):
        make_solver("general", output_step=1e-4).solve(p)
    with pytest.raises(InputError, match="solver = 'exact' is not allowed with contact law"):
        make_solver("exact").solve(_problem(bed, 20.0, law=get_law("hysteretic")))
    assert repr(p) == "ImpactProblem(clamped head (rigid support); 20 m/s; law linear (paper))"
    assert "clamped head, strings 16x19 at 246 N" in repr(_problem(bed, 20.0))


def test_a_clamped_head_has_no_frame_model(bed, standard_model):
    # problem.model is the frame struck (held too); a clamped head has none: None, not the head
    from fem_racket.frame.hand import GRIPS

    assert _problem(RIGID, 20.0).model is None and _problem(bed, 20.0).model is None
    assert ImpactProblem(standard_model).model is standard_model
    held = ImpactProblem.build(standard_model, hand=GRIPS["firm"])
    assert held.held and held.model is standard_model
    # what reads a problem's model refuses the head as it refuses any non-frame
    from fem_racket.impact.problem_batch import ProblemBatch

    with pytest.raises(InputError, match="models is not allowed: must be one or more FrameModels"):
        ProblemBatch.of(_problem(RIGID, 20.0))


def test_equal_laws_are_solved_in_one_call(monkeypatch):
    # The general integrator takes the problems of one law in one call, laws compared by value
    # (clamped_solve.law_key): a law referred to the problems' 0.1 kg ball is a fresh copy per
    # problem, a second object with its parameters is the same law; each case's numbers are
    # those of the case alone, bit for bit. The law at its own ball is another law: its call.
    import fem_racket.impact.clamped_solve as clamped_solve

    calls = []
    real = clamped_solve.solve_general

    def counted(law, rec, speed, **options):
        calls.append(len(speed))
        return real(law, rec, speed, **options)

    a, b = LinearContact(3e4, 0.1), LinearContact(3e4, 0.1)
    heavy = Ball(0.1)
    problems = [_problem(RIGID, v, ball=heavy, law=law) for v, law in ((15.0, a), (25.0, b))]
    problems += [_problem(RIGID, 35.0, ball=heavy, law=a), _problem(RIGID, 20.0, law=a)]
    assert len({id(p.law) for p in problems[:3]}) == 3  # no copy kept to be shared
    assert set(vars(a)) == {"stiffness", "zeta", "ball_mass", "separation"}
    monkeypatch.setattr(clamped_solve, "solve_general", counted)
    many = make_solver("general").solve_many(problems)
    assert calls == [3, 1]
    for p, r in zip(problems, many, strict=True):
        one = make_solver("general").solve(p)
        assert (r.cor, r.contact_time) == (one.cor, one.contact_time)
        assert all(np.array_equal(x, y) for x, y in zip(
            (r.time, r.deflection, r.force), (one.time, one.deflection, one.force), strict=True
        ))  # fmt: skip


def test_law_key_is_the_law_s_value():
    from fem_racket.impact.clamped_solve import law_key

    law = LinearContact(3e4, 0.1)
    assert law_key(law.for_ball(0.1)) == law_key(LinearContact(3e4, 0.1).for_ball(0.1))
    assert law_key(law.for_ball(0.1)) != law_key(law)  # zeta and ball mass of another ball
    assert law_key(law) != law_key(LinearContact(3e4, 0.1, separation="force"))
    assert law_key(law) != law_key(get_law("hunt-crossley"))
    batch = LinearContact(np.array([3e4, 4e4]), np.array([0.1, 0.2]))  # a batch's arrays
    same = LinearContact(np.array([3e4, 4e4]), np.array([0.1, 0.2]))
    assert hash(law_key(batch)) == hash(law_key(same)) and law_key(batch) == law_key(same)
    assert law_key(batch) != law_key(LinearContact(np.array([3e4, 4e4]), np.array([0.1, 0.3])))
