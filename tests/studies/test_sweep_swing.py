"""Sweeps over the swing: racket speed, reference and pivot as dimensions or fixed values."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.impact.simulate import simulate
from fem_racket.impact.swing import Swing
from fem_racket.studies.sweep import sweep


def test_swing_dimensions_match_simulate(standard_model):
    ds = sweep(
        position=[0.6, 0.85],
        racket_speed=[-5.0, 0.0, 25.0],
        pivot=[-0.5, 0.08],
        speed=20.0,
        backend="serial",
        peak_force=True,
    )
    assert ds.cor.dims == ("position", "racket_speed", "pivot")
    for p in ds.position.values:
        for v in ds.racket_speed.values:
            for piv in ds.pivot.values:
                swing = Swing.from_speed(v, 0.68, pivot=piv)
                r = simulate(standard_model, position=p, speed=20.0, swing=swing, output_step=None)
                case = ds.sel(position=p, racket_speed=v, pivot=piv)
                # The same engine (COR tolerance 1e-6) per case; the sweep solves at unit speed
                # and rescales.
                assert float(case.cor) == pytest.approx(r.apparent_cor, rel=1e-9)
                assert float(case.rebound_speed_m_s) == pytest.approx(r.ball_speed_out, rel=1e-9)
                assert float(case.racket_speed_at_impact_m_s) == pytest.approx(
                    r.racket_speed_at_impact, rel=1e-12, abs=1e-15
                )
                assert float(case.peak_force_n) == pytest.approx(r.peak_force, rel=1e-7)
    assert ds.attrs["reference_x_over_l"] == 0.75


def test_fixed_swing_and_cvode_agree(standard_model):
    kw = dict(position=0.8, speed=[15.0, 30.0], racket_speed=20.0, pivot=0.1, modes=20)
    exact = sweep(backend="serial", tolerance=None, **kw)
    cvode = sweep(backend="serial", solver="cvode", **kw)
    np.testing.assert_allclose(cvode.rebound_speed_m_s, exact.rebound_speed_m_s, rtol=1e-9)
    assert exact.attrs["racket_speed_m_s"] == 20.0 and exact.attrs["pivot_m"] == 0.1


def test_a_racket_at_rest_is_the_old_sweep(standard_model):
    ds = sweep(position=[0.6, 0.8], speed=30.0, backend="serial")
    assert np.all(ds.racket_speed_at_impact_m_s == 0.0)
    r = simulate(standard_model, position=0.8, speed=30.0, output_step=None)
    assert float(ds.cor.sel(position=0.8)) == pytest.approx(r.cor, rel=1e-12)
    assert "pivot_m" not in ds.attrs  # no pivot: the racket would translate
