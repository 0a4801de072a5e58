"""The ball on the strung racket: reduction to the paper's model, independent paths, energy and
momentum."""

import math

import numpy as np
import pytest
from scipy.integrate import simpson

from fem_racket.contact.hunt_crossley import HuntCrossley
from fem_racket.contact.linear import LinearContact, kcb_from_speed, zeta_from_cor
from fem_racket.impact.exact.engine import EngineOptions, modal_impacts
from fem_racket.impact.strung.impact import strung_engine, strung_impact
from fem_racket.impact.strung.point import strung_point
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError

EVERY = EngineOptions(tolerance=None)
MB = 0.057
V = 30.0
POS = 0.76
K = kcb_from_speed(V)
ZETA = zeta_from_cor(0.83)
C = 2 * ZETA * math.sqrt(MB * K)


@pytest.fixture(scope="module")
def point(standard_model):
    return strung_point(standard_model, StringBed(), POS)


def test_very_stiff_bed_is_the_papers_model(standard_model):
    # Tension x f: the bed's compliance and its modes' weight fall as 1/f, so the strung racket
    # tends to the frame alone with the paper's spring; measured |dCOR| = 2.52e-5 / (f / 1e4),
    # i.e. 2.5e-13 at f = 1e12 (the exact engine, every mode).
    fm = standard_model.modes(None)
    a = fm.all_shapes.T @ standard_model.fe.point_vector(POS * standard_model.mesh.length)
    ref = modal_impacts(fm.omega, a[2:], np.sum(a[:2] ** 2), speed=V, ball_mass=MB, options=EVERY)
    errs = []
    for f in (1e8, 1e12):
        p = strung_point(standard_model, StringBed(tension_n=246.0 * f), POS)
        out = strung_engine(p, K, ZETA, MB, V, tolerance=None)
        errs.append(abs(float(out.cor) - float(ref.cor)))
        assert abs(float(out.contact_time) - float(ref.contact_time)) < 1e-12 * 1e12 / f
    assert errs[1] < 1e-12
    assert errs[0] / errs[1] == pytest.approx(1e4, rel=0.05)  # error ~ 1/T


def test_exact_cvode_and_general_agree(point):
    # The same linear ball on the same structure: exact roots vs CVODE (rtol 1e-10) agree to
    # ~1e-12 in COR (measured 3e-13); the general integrator to its COR tolerance 1e-6.
    law = LinearContact(K, ZETA, MB)
    exact = strung_engine(point, K, ZETA, MB, V, tolerance=None)
    cv = strung_impact(point, law, MB, V, solver="cvode")
    gen = strung_impact(point, law, MB, V)
    assert cv.cor == pytest.approx(float(exact.cor), abs=1e-9)
    assert cv.contact_time == pytest.approx(float(exact.contact_time), abs=1e-10)
    assert gen.cor == pytest.approx(float(exact.cor), abs=2e-6)
    assert gen.peak_force == pytest.approx(float(exact.peak_force), rel=1e-4)


def test_nonlinear_ball_general_against_cvode(point):
    # A Hunt-Crossley ball (the itf-ball preset's parameters) on the bed: two integrators.
    law = HuntCrossley(3.978e5, 1.690, 0.07212)
    gen = strung_impact(point, law, MB, V, tolerance=1e-7)
    cv = strung_impact(point, law, MB, V, solver="cvode")
    assert gen.cor == pytest.approx(cv.cor, abs=1e-6)
    assert gen.contact_time == pytest.approx(cv.contact_time, rel=1e-5)


def test_energy_and_momentum(point):
    # The work of the contact force on the ball is its loss of kinetic energy; the racket (frame
    # and bed) holds the work done on it; the dashpot dissipates int C delta'^2 dt; the frame's
    # momentum is the ball's impulse (the bed passes the contact force to the frame).
    law = LinearContact(K, ZETA, MB)
    out = strung_impact(point, law, MB, V, tolerance=1e-8)
    t = out.t
    d = out.ball_deflection
    rate = np.gradient(d, t, edge_order=2)
    dissipated = simpson(C * rate**2, x=t)
    assert out.ball_loss - out.racket_energy == pytest.approx(dissipated, rel=1e-3)
    assert MB * V * (1 + out.cor) == pytest.approx(out.frame_momentum, rel=1e-12)
    impulse = simpson(out.force, x=t)
    assert impulse == pytest.approx(out.frame_momentum, rel=1e-5)
    # no damping: everything the ball lost is in the racket
    elastic = strung_impact(point, LinearContact(K, 0.0, MB), MB, V, tolerance=1e-8)
    assert elastic.racket_energy == pytest.approx(elastic.ball_loss, rel=1e-7)
    s = out.summary()
    assert s["peak_bed_deflection_m"] > 0 and s["peak_ball_deflection_m"] > 0
    assert 0 < s["bed_energy_returned_j"] < s["ball_energy_loss_j"]


def test_tension_changes_the_impact(standard_model):
    # Higher tension: a stiffer bed, a shorter contact (Yang, Fafitis & Wiezel 2012: tension
    # changes dwell time and rebound clearly).
    res = {}
    for T in (220.0, 270.0):
        p = strung_point(standard_model, StringBed(tension_n=T), POS)
        res[T] = (strung_engine(p, K, ZETA, MB, V), p.bed_stiffness)
    assert res[270.0][1] / res[220.0][1] == pytest.approx(270 / 220, rel=1e-12)
    assert float(res[270.0][0].contact_time) < float(res[220.0][0].contact_time)
    assert float(res[270.0][0].cor) != pytest.approx(float(res[220.0][0].cor), abs=1e-4)


def test_point_off_the_head(standard_model):
    with pytest.raises(InputError, match="must lie on the head"):
        strung_point(standard_model, StringBed(), 0.3)


def test_kawazoe_ball_exact_histories_against_cvode(standard_model):
    # The calibrated, heavily damped linear ball (zeta_b = 0.40) on the free strung racket: the
    # closed-form histories (roots and residues, every mode) against CVODE (rtol 1e-10) and the
    # batched engine; COR and t_c to ~1e-10 (measured 3e-12 / 1e-13 s), the energies at t_c to
    # 1e-7; the peaks (801 samples, CVODE's interpolated linearly from its own grid) to 1e-4.
    from fem_racket.contact.bed_ball import BALL_STIFFNESS, BALL_ZETA, kawazoe_ball

    point = strung_point(standard_model, StringBed(tension_n=220.0), 0.75)
    law = kawazoe_ball(MB)
    exact = strung_impact(point, law, MB, 20.0, solver="exact")
    cv = strung_impact(point, law, MB, 20.0, solver="cvode")
    engine = strung_engine(point, BALL_STIFFNESS, BALL_ZETA, MB, 20.0, tolerance=None)
    assert exact.cor == pytest.approx(float(engine.cor), abs=1e-10)
    assert exact.contact_time == pytest.approx(float(engine.contact_time), abs=1e-12)
    assert exact.cor == pytest.approx(cv.cor, abs=1e-8)
    s, c = exact.summary(), cv.summary()
    for key in ("energy_lost_in_ball_j", "bed_energy_left_j", "ball_energy_loss_j"):
        assert s[key] == pytest.approx(c[key], rel=1e-7), key
    for key in ("bed_energy_returned_j", "peak_bed_deflection_m", "peak_ball_deflection_m"):
        assert s[key] == pytest.approx(c[key], rel=1e-4), key
    assert MB * 20.0 * (1 + exact.cor) == pytest.approx(exact.frame_momentum, rel=1e-12)


def test_exact_refuses_a_nonlinear_ball(point):
    with pytest.raises(InputError, match="exact strung solver"):
        strung_impact(point, HuntCrossley(3.978e5, 1.690, 0.07212), MB, V, solver="exact")


def test_hoop_edge(standard_model):
    # edge "hoop": the frame seen through the bed's static edge transmission. T reproduces linear
    # functions, so the rigid modes' values are the impact point's (to round-off) and the
    # momentum balance holds; the bending modes differ, and so does the COR (measured at 30 m/s:
    # 0.353 -> 0.393 at 0.60 L, 0.298 -> 0.283 at 0.80 L).
    from fem_racket.contact.bed_ball import BALL_STIFFNESS, BALL_ZETA

    cors = {}
    for edge in ("point", "hoop"):
        p = strung_point(standard_model, StringBed(edge=edge), 0.6)
        cors[edge] = float(strung_engine(p, BALL_STIFFNESS, BALL_ZETA, MB, V, tolerance=None).cor)
        if edge == "point":
            rigid = p.rigid
    assert np.allclose(p.rigid, rigid, rtol=1e-12, atol=0)
    assert cors["point"] == pytest.approx(0.3524, abs=2e-4)
    assert cors["hoop"] == pytest.approx(0.3929, abs=2e-4)
    out = strung_impact(p, LinearContact(K, ZETA, MB), MB, V, solver="exact")
    assert MB * V * (1 + out.cor) == pytest.approx(out.frame_momentum, rel=1e-12)


def test_impact_problem_with_strings(standard_model):
    # The bed as a field of ImpactProblem: simulate(strings=...) and the solvers give what the
    # strung path gives; auto picks exact for the linear ball, general for another law; what
    # the strung racket cannot take is refused in one line.
    from fem_racket.impact.problem import ImpactProblem
    from fem_racket.impact.simulate import simulate
    from fem_racket.impact.solvers import make_solver
    from fem_racket.impact.strung.impact import simulate_strung

    bed = StringBed(tension_n=230.0)
    direct = simulate_strung(standard_model, bed, position=0.8, speed=25.0)
    via = simulate(standard_model, strings=bed, position=0.8, speed=25.0)
    assert via.solver == "exact" and via.cor == direct.cor
    problem = ImpactProblem.build(standard_model, strings=bed, position=0.8, speed=25.0)
    assert make_solver("cvode").solve(problem).cor == pytest.approx(direct.cor, abs=1e-8)
    hc = simulate(standard_model, strings=bed, law="itf-ball", position=0.8, speed=25.0)
    assert hc.solver == "general" and hc.law.name == "hunt-crossley"
    bad = [
        ({"kcb": 3e4}, "kcb is not allowed with a string bed"),
        ({"solver": "bdf"}, "solver = 'bdf' is not allowed with a string bed"),
        ({"solver": "exact", "modes": 10}, "modes = 10 is not allowed with a string bed"),
        ({"position": 0.3}, "must lie on the head"),
    ]
    for kwargs, message in bad:
        with pytest.raises(InputError, match=message):
            simulate(standard_model, strings=bed, **kwargs)
    assert simulate(standard_model).cor != via.cor  # None: the paper's K_CB, unchanged
