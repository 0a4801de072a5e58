"""The batched engine against the exact per-case path, closed forms and its own tolerance.

Sources: with every mode kept the engine solves the same linear system as
:func:`fem_racket.impact.exact.outcome.exact_outcome` (the reference; both are exact up to
round-off, measured agreement ~1e-11 in COR and t_c), so they must agree to 1e-9. With a COR
tolerance the error against every mode must stay within it (the point of the tolerance). A
ball on a spring-dashpot against a fixed wall (no structure modes, no rigid modes) is eqs 1-4 of
Kawazoe & Kanda (1997): COR = exp(-zeta pi / sqrt(1 - zeta^2)), t_c = pi / (omega sqrt(1-zeta^2)).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from script_loader import load_script
from strategies import frames

from fem_racket import FrameModel, InputError, LinearContact
from fem_racket.impact.exact.engine import EngineOptions, impacts, modal_impacts
from fem_racket.impact.exact.outcome import exact_outcome
from fem_racket.impact.system import modal_system

#: Impact points between nodes (20 cells: nodes every 0.05 L on a uniform frame).
positions = st.floats(0.3, 0.99).filter(lambda p: abs(p * 20 - round(p * 20)) > 0.05)
cases = st.tuples(positions, st.floats(10.0, 50.0), st.floats(0.0, 0.2), st.floats(0.05, 0.065))


def _exact(model, p, v, z, m, separation):
    """Today's per-case exact path with every mode: (COR, t_c)."""
    fm = model.modes(None)
    g = model.fe.point_vector(p * model.mesh.length)
    law = LinearContact.for_speed(v, zeta=z)
    system = modal_system(fm.all_omega, fm.all_shapes, g, m, law.stiffness, law.damping(m), 1.0)
    o = exact_outcome(system, separation=separation)
    return -o.rebound_velocity, o.contact_time


@settings(max_examples=12)
@given(
    frame=frames(max_segments=4),
    case=st.lists(cases, min_size=1, max_size=3),
    separation=st.sampled_from(["displacement", "force"]),
)
def test_every_mode_matches_the_exact_path(frame, case, separation):
    model = FrameModel.build(frame, 20)
    p, v, z, m = (np.array(c) for c in zip(*case, strict=True))
    every = EngineOptions(separation, tolerance=None)
    b = impacts(model, position=p, speed=v, zeta=z, ball_mass=m, options=every)
    for i in range(p.size):
        cor, tc = _exact(model, p[i], v[i], z[i], m[i], separation)
        assert b.cor[i] == pytest.approx(cor, abs=1e-9)  # both exact: ~1e-11 measured
        assert b.contact_time[i] == pytest.approx(tc, rel=1e-9)


@settings(max_examples=15)
@given(
    frame=frames(max_segments=4),
    ei=st.floats(0.3, 20.0),
    seed=st.integers(0, 2**16),
    tolerance=st.sampled_from([1e-4, 1e-5, 1e-6]),
    separation=st.sampled_from(["displacement", "force"]),
)
def test_error_stays_within_the_tolerance(frame, ei, seed, tolerance, separation):
    model = FrameModel.build(frame, 20)
    rng = np.random.default_rng(seed)
    n = 40
    kw = dict(
        position=rng.uniform(0.3, 1.0, n),
        speed=rng.uniform(10.0, 50.0, n),
        zeta=rng.uniform(0.0, 0.2, n),
        ball_mass=rng.uniform(0.05, 0.065, n),
        ei_factor=ei * np.exp(rng.uniform(-1.0, 1.0, n)),
    )
    if separation == "force":
        # Heavily damped impacts on very soft frames can end, with every FE mode, at a brief
        # dip of the force below zero made by the highest modes' ripple (C_CB delta'): only
        # every mode reproduces that (tolerance None). zeta <= 0.1 keeps clear of it.
        kw["zeta"] = kw["zeta"] / 2.0
    every = impacts(model, options=EngineOptions(separation, None), **kw)
    fast = impacts(model, options=EngineOptions(separation, tolerance), **kw)
    assert np.max(np.abs(fast.cor - every.cor)) <= tolerance
    assert np.all(fast.modes <= every.modes)


def test_graded_mesh_and_fine_mesh_use_static_totals():
    """On 160 cells only the modes below the cut-off are computed; the rest enter through
    static solves and must give the same COR as every mode, to the tolerance."""
    from fem_racket import graded_mesh, standard_frame

    model = FrameModel.build(graded_mesh(standard_frame(), 160, 3.0))
    p = np.array([0.5123, 0.7531, 0.9017])
    fast = impacts(model, position=p, speed=30.0, options=EngineOptions(tolerance=1e-6))
    every = impacts(model, position=p, speed=30.0, options=EngineOptions(tolerance=None))
    assert model.modes(None).omega.size == 320
    assert np.max(np.abs(fast.cor - every.cor)) <= 1e-6
    assert np.max(fast.modes) < 40


def test_ball_against_a_wall_is_eqs_1_to_4():
    """No structure modes and no rigid modes: the clamped frame of eqs 1-4."""
    zeta = np.array([0.0, 0.0592, 0.3, 0.9])
    k, m = 2.74e4, 0.057
    b = modal_impacts(np.empty(0), np.empty((4, 0)), 0.0, kcb=k, zeta=zeta, ball_mass=m)
    root = np.sqrt(1.0 - zeta**2)
    np.testing.assert_allclose(b.cor, np.exp(-zeta * np.pi / root), rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(b.contact_time, np.pi / (np.sqrt(k / m) * root), rtol=1e-12)


def test_heavy_damping_falls_back_to_the_eigen_solution(standard_model):
    """zeta = 0.9 makes the contact roots real: solved by eigen-decomposition, same answer."""
    b = impacts(
        standard_model, position=[0.6, 0.8], zeta=0.9, options=EngineOptions(tolerance=None)
    )
    for i, p in enumerate([0.6, 0.8]):
        cor, tc = _exact(standard_model, p, 20.0, 0.9, 0.057, "displacement")
        assert b.cor[i] == pytest.approx(cor, abs=1e-9)
        assert b.contact_time[i] == pytest.approx(tc, rel=1e-9)


def test_peak_force_with_every_mode_matches_the_exact_path(standard_model):
    every = EngineOptions(tolerance=None, peak_force=True)
    b = impacts(standard_model, position=0.75, speed=[20.0, 40.0], options=every)
    fm = standard_model.modes(None)
    g = standard_model.fe.point_vector(0.75 * standard_model.mesh.length)
    for i, v in enumerate([20.0, 40.0]):
        law = LinearContact.for_speed(v)
        system = modal_system(
            fm.all_omega, fm.all_shapes, g, 0.057, law.stiffness, law.damping(0.057), v
        )
        assert b.peak_force[i] == pytest.approx(exact_outcome(system).peak_force, rel=1e-9)
    assert impacts(standard_model, position=0.75).peak_force is None


def test_broadcasting_and_speed_scaling(standard_model):
    b = impacts(
        standard_model,
        position=[[0.6], [0.8]],
        speed=[20.0, 30.0, 40.0],
        kcb=3e4,
        options=EngineOptions(peak_force=True),
    )
    assert b.cor.shape == (2, 3)
    # At fixed K_CB the impact is linear in the speed: same COR and t_c, force x speed.
    np.testing.assert_allclose(b.cor, b.cor[:, :1] * np.ones(3), rtol=0, atol=1e-15)
    np.testing.assert_allclose(
        b.peak_force / [20.0, 30.0, 40.0], b.peak_force[:, :1] / 20.0 * np.ones(3)
    )
    np.testing.assert_allclose(b.rebound_speed, b.cor * [20.0, 30.0, 40.0])


def test_ei_factor_equals_a_scaled_model(standard_model):
    every = EngineOptions(tolerance=None)
    a = impacts(standard_model, position=0.7, ei_factor=3.0, options=every)
    b = impacts(standard_model.scaled(3.0), position=0.7, options=every)
    assert float(a.cor) == pytest.approx(float(b.cor), abs=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"position": 1.5}, "position = 1.5 x/L is not allowed"),
        ({"position": 0.7, "speed": 0.5}, "speed = 0.5 m/s is not allowed"),
        ({"position": 0.7, "zeta": 1.0}, "zeta = 1.0 is not allowed"),
        ({"position": 0.7, "tolerance": -1e-6}, "tolerance = -1e-06 is not allowed"),
        ({"position": 0.7, "separation": "time"}, "separation = 'time' is not allowed"),
        ({"position": 0.7, "modes": 2.5}, "modes = 2.5 is not allowed"),
        ({"position": 0.7, "ball_mass": 0.0}, "ball_mass = 0.0 kg is not allowed"),
    ],
)
def test_bad_input(standard_model, kwargs, match):
    options = {k: kwargs.pop(k) for k in ("tolerance", "separation", "modes") if k in kwargs}
    with pytest.raises(InputError, match=match):
        impacts(standard_model, **kwargs, options=EngineOptions(**options))


def test_tolerance_zero_means_every_mode(standard_model):
    a = impacts(standard_model, position=0.7, options=EngineOptions(tolerance=0))
    assert a.tolerance is None and int(a.modes) == 40
    assert math.isfinite(float(a.cor))


def test_calibrate_engine_script_quick(capsys):
    table = load_script("calibrate_engine").main(["--quick"])
    out = capsys.readouterr().out
    assert "|dCOR| displ" in out and "|dCOR| force" in out
    # Two frames cannot calibrate, but even they must need a finite beta for 1e-3.
    assert math.isfinite(table["displacement", 1e-3]) and math.isfinite(table["force", 1e-3])


def test_bench_engine_script_quick(capsys):
    rows = load_script("bench_engine").main(["--quick"])
    out = capsys.readouterr().out
    assert "per-case exact" in out and "engine 1e-06" in out and "fem-racket simulate" in out
    engine = [r for r in rows if r.get("path", "").startswith("engine")]
    # Every mode against the per-case path: round-off (measured ~2e-12); the engine within
    # its tolerance of every mode.
    assert all(r["dcor"] < 1e-9 for r in rows if r.get("path") == "per-case exact")
    assert all(r["dcor"] <= float(r["path"].split()[1]) for r in engine)
