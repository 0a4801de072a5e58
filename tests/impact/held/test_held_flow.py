"""A linear output's energy and extrema between samples of a linear flow
(impact/held/flow.py), against the closed forms of one oscillator."""

import numpy as np
import pytest

from fem_racket.impact.held.flow import flow_energy, flow_extrema

#: A 120 Hz oscillator (the frame's first mode), lightly damped in the extremum test.
OMEGA = 2.0 * np.pi * 120.0


def oscillator(sigma: float = 0.0) -> np.ndarray:
    """y' = A y for x'' + 2 sigma x' + omega^2 x = 0, y = [x, x']."""
    return np.array([[0.0, 1.0], [-(OMEGA**2), -2.0 * sigma]])


@pytest.mark.parametrize("scale", [1.0, 1e-6])
def test_energy_is_the_closed_form_on_any_samples(scale):
    # x = cos(omega t): int_0^T x^2 dt = T/2 + sin(2 omega T) / (4 omega), exactly; from samples
    # at uneven times (the last step shorter), over 6 periods. With x' scaled by 1e-6 the matrix
    # spans 12 decades, as the held racket's physical one spans 13: without balancing the
    # Gramian's error was 8e-8 here (2e-4 on the held racket). Within 1e-12 (round-off).
    T = 0.05
    t = np.array([0.0, 0.011, 0.022, 0.033, 0.044, T])
    S = np.diag([1.0, scale])
    A = np.linalg.solve(S, oscillator() @ S)
    y = np.column_stack([np.cos(OMEGA * t), -OMEGA * np.sin(OMEGA * t) / scale])
    exact = T / 2 + np.sin(2 * OMEGA * T) / (4 * OMEGA)
    assert flow_energy(A, np.array([1.0, 0.0]), t, y) == pytest.approx(exact, rel=1e-12)


def test_extremum_between_grid_points_is_root_found():
    # x = exp(-sigma t) sin(omega_d t) / omega_d from x(0) = 0, x'(0) = 1: its first maximum is
    # at tan(omega_d t*) = omega_d / sigma. A grid of 0.37 ms (1/22 of a period) misses it by
    # 8e-3; root-found it is the closed form to 1e-12.
    sigma = 0.05 * OMEGA
    wd = OMEGA * np.sqrt(1 - 0.05**2)
    ts = np.arctan(wd / sigma) / wd
    peak = np.exp(-sigma * ts) * np.sin(wd * ts) / wd
    values = flow_extrema(
        oscillator(sigma), np.array([1.0, 0.0]), np.array([0.0, 1.0]), 0.02, 3.7e-4
    )
    assert np.max(values) == pytest.approx(peak, rel=1e-12)
    grid = np.arange(0.0, 0.02, 3.7e-4)
    assert np.max(np.exp(-sigma * grid) * np.sin(wd * grid) / wd) < peak * (1 - 1e-3)
