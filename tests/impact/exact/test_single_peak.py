"""One impact's peak force is the same with and without histories (issue 23.4).

``simulate`` without output times runs the batched engine with the COR tolerance's modes; its
peak force used to come from those (608.2 N at 0.75 L, 20 m/s, 2.4e-4 above every mode's
608.07 N) while the histories' path (``--out``) found it on every mode (608.1 N). Both now
root-find dF/dt = 0 on every mode. The independent check is CVODE at its tightest tolerance
(rtol 1e-12, :data:`fem_racket.impact.ode.integrators.RTOL_RANGE`) whose peak is the largest
force on its output grid: with a step of 1e-7 s the sampled maximum lies below the true one
by at most dt^2/8 max|F''| ~ 1e-14/8 x 608 N x (2 pi / 4 ms)^2 ~ 2e-7 N (4e-10 relative,
from the contact pulse's curvature), measured 1.4e-10 relative.
"""

from __future__ import annotations

import pytest

from fem_racket import simulate


def test_peak_force_is_the_same_with_and_without_histories():
    summary = simulate(position=0.75, speed=20.0, output_step=None)
    histories = simulate(position=0.75, speed=20.0)
    every = simulate(position=0.75, speed=20.0, output_step=None, tolerance=None)
    assert summary.n_modes == 40 and summary.tolerance == 1e-6
    assert summary.peak_force == pytest.approx(histories.peak_force, rel=1e-9)  # both exact
    assert summary.peak_force == every.peak_force  # the same roots and search
    assert f"{summary.peak_force:.1f}" == f"{histories.peak_force:.1f}" == "608.1"


def test_peak_force_against_cvode():
    summary = simulate(position=0.75, speed=20.0, output_step=None)
    cvode = simulate(
        position=0.75, speed=20.0, solver="cvode", rtol=1e-12, atol=1e-16, output_step=1e-7
    )
    # the sampling bound (module docstring) plus CVODE's own error: 1e-9 relative (the
    # reduced model's old peak was 2.4e-4 off)
    assert summary.peak_force == pytest.approx(cvode.peak_force, rel=1e-9)
