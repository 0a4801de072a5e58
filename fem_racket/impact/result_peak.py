"""The secant normal stiffness at the largest compression, located between output times:
:func:`peak_secant` (:attr:`ImpactResult.compression_stiffness
<fem_racket.impact.result.ImpactResult.compression_stiffness>` and the strung racket's
:attr:`~fem_racket.impact.strung.result.StrungImpact.compression_stiffness`).

The tangential spring of an oblique impact is k_t = k_n / eta^2, with k_n = F / delta where the
compression delta peaks (delta' = 0). The peak lies between two output times: a cubic Hermite
spline through the samples of delta and delta' locates it (the root of its derivative beside
the sample of largest delta) and gives delta* there (fourth order in the output step: delta' = 0
makes the time's error second order in delta), and k_n = F(delta*, 0, z*) / delta*, the law's
own force at the peak. The law's state z* is delta* itself for a memory state (the largest
compression so far is this one), the Hermite spline through z and z' = g(delta, delta', z) for
an ODE state. For a spring-dashpot (the paper's law, the kawazoe-1997-ball) this is its K.

Two cheaper readings move with the output times: the secant F / delta at the sample of largest
compression carries a dashpot's force C delta' at up to half a step from the peak (first order
in the step; second order for an elastic branch), and F at the peak read off the force samples
(P' of the impulse's Hermite spline) is second order where F'' jumps at the peak, as a
hysteretic law's does when it turns from its loading to its unloading branch (the numbers are
in tests/impact/test_result_peak.py).
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["peak_secant"]


def peak_secant(
    t: np.ndarray, deflection: np.ndarray, rate: np.ndarray, law: Any, state: Any = None
) -> float:
    """F(delta*, 0, z*) / delta* [N/m] where delta peaks, between the output times (module
    docstring).

    Parameters
    ----------
    t : ndarray
        Output times [s], non-decreasing (a repeated time, the contact time on the output grid,
        is one sample).
    deflection, rate : ndarray
        delta [m] and delta' [m/s] at ``t``.
    law : ContactLaw
        The law (its ``force``; with an ODE state its ``rate``).
    state : ndarray or None
        The law's state z [m] at ``t`` (needed for an ODE state only).
    """
    from scipy.interpolate import CubicHermiteSpline

    t = np.asarray(t, dtype=float)
    keep = np.concatenate(([True], np.diff(t) > 0.0))
    t, d, v = t[keep], np.asarray(deflection)[keep], np.asarray(rate)[keep]
    i = int(np.argmax(d))
    near = slice(max(i - 1, 0), min(i + 2, t.size))  # the two steps beside the sample
    spline = CubicHermiteSpline(t[near], d[near], v[near])
    times = np.append(spline.derivative().roots(extrapolate=False), t[i])
    peak = float(times[np.argmax(spline(times))])
    d_peak = float(spline(peak))
    z_peak = d_peak  # a memory state (and a law without one: unused)
    if law.state == "ode":
        z = np.asarray(state, dtype=float)[keep][near]
        z_peak = float(CubicHermiteSpline(t[near], z, law.rate(d[near], v[near], z))(peak))
    return float(law.force(d_peak, 0.0, z_peak)) / d_peak
