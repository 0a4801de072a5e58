"""One slide of the vector tangential contact integrated in time: :func:`integrate_slide`.

With d = (cos phi, sin phi) the stretch's direction and rho = mu F / k_t its length, a slide is::

    s' = -mu F A d,   phi' = (s . d_perp) / rho,   d_perp = (-sin phi, cos phi)

(:mod:`fem_racket.impact.tangential.plane`), until the slider stops (s . d = rho', an event
located by the integrator, with the history's continuous ``slope`` F') or the normal force
returns to zero. A rigid tangential contact (eta^2 = 0) slides along the slip itself
(d = s / |s|), in polar form (|s|' = -mu F d.A d, the angle turning at -mu F d_perp.A d / |s|)
until |s| = 0.

The stretch's direction relaxes toward the slip at the rate lambda = (s . d) / rho (the phi
equation's Jacobian), fast where the normal force is small: below FLOOR of its largest value rho
is held at that floor (the force there, under 1e-6 of its peak, acts for ~1e-6 of the contact:
an impulse error ~1e-12). A law whose force rises from zero with zero slope (Hunt-Crossley,
hysteretic, Kawazoe's nonlinear law: F ~ x^n, n > 1) starts its slide at t = 0 with rho at the
floor, and its force stays under 1e-6 of its peak for a tenth of the contact: lambda ~ 1e10 /s
there, far past an explicit method's stability (DOP853 then takes ~1e6 steps of ~1e-9 s and its
dense output grows without end). So each slide's stiffness index, ``|s(t0)|`` times the integral
of 1 / rho over the rest of the contact (on the history's grid), picks the method: below
:data:`STIFF` (the paper's linear law, whose force starts at the dashpot's c V: indices
~1e2..4e4 on the bare racket and the string bed) the explicit Runge-Kutta method of order 8
(DOP853); above it (the laws above: ~1e6..1e7, also for slides that start mid-contact, the
force's soft tail at the end being as stiff) the L-stable implicit Radau IIA method of order 5
with the exact Jacobian, both at rtol 1e-13. A slide that needs more than
:data:`MAX_EVALUATIONS` right-hand-side evaluations is refused in one line
(:class:`fem_racket.validation.AccuracyError`): never an unbounded run.
"""

from __future__ import annotations

import math

import numpy as np

from fem_racket.impact.tangential.normal import NormalHistory
from fem_racket.impact.tangential.scalar import scalar_force
from fem_racket.validation import AccuracyError, show

__all__ = ["integrate_slide", "stiffness_index"]

#: Relative tolerance of the slides' integration.
RTOL = 1e-13
#: The stretch length below which the slide turns no faster, over its largest mu F / k_t.
FLOOR = 1e-6
#: Stiffness index above which a slide is integrated by Radau instead of DOP853 (DOP853's
#: stability interval is ~4: an index of 1e5 costs it >= 2.5e4 steps, Radau ~1e3).
STIFF = 1e5
#: Right-hand-side evaluations one slide may take before it is refused (~1 s of CPU per 1e5;
#: the slides of the tests and reproducers take 1e3..3e4).
MAX_EVALUATIONS = 1_000_000


def stiffness_index(normal: NormalHistory, t0: float, size: float, floor: float, ratio: float):
    """``size`` |s(t0)| [m/s] times the integral of 1 / rho [1/m] over [t0, end] [s] on the
    history's grid (trapezoidal), rho = max(``ratio`` F, ``floor``), ``ratio`` = mu / k_t [m/N]."""
    t = np.asarray(normal.grid, dtype=float)
    t = np.concatenate([[t0], t[(t > t0) & (t < normal.end)], [normal.end]])
    rho = np.maximum(ratio * np.maximum(normal.smooth_force(t), 0.0), floor)
    f = 1.0 / rho  # the trapezoidal rule as numpy's trapezoid (numpy >= 2 only) writes it
    return size * float((np.diff(t) * (f[1:] + f[:-1]) / 2.0).sum())


def _budget(c, t0: float):
    """A counter that refuses the slide from ``t0`` [s] after MAX_EVALUATIONS calls."""
    count = [0]

    def tick():
        count[0] += 1
        if count[0] > MAX_EVALUATIONS:
            raise AccuracyError(
                f"friction = {show(c.friction)} is not allowed for this impact: the tangential "
                f"slide from {t0 * 1e3:.4g} ms took over {MAX_EVALUATIONS} evaluations "
                f"of its right-hand side at rtol {RTOL:g} without reaching its end",
                parameter="friction",
                value=c.friction,
            )

    return tick


def _rigid(c, force, a, scale):
    """Right-hand side of the rigid slide in polar form (|s|, angle)."""
    mu, ((a00, a01), (a10, a11)) = c.friction, a

    def rhs(t, y):
        cos, sin = math.cos(y[1]), math.sin(y[1])
        f = mu * max(force(t), 0.0)
        ad = (a00 * cos + a01 * sin, a10 * cos + a11 * sin)
        turn = -sin * ad[0] + cos * ad[1]
        return [-f * (cos * ad[0] + sin * ad[1]), -f * turn / max(y[0], 1e-9 * scale)]

    def stop(t, y):
        return y[0]

    return rhs, None, stop


def _compliant(c, force, slope, a, floor):
    """Right-hand side, its Jacobian and the slider's stop of the compliant slide."""
    mu, k, ((a00, a01), (a10, a11)) = c.friction, c.stiffness, a

    def rhs(t, y):
        cos, sin = math.cos(y[2]), math.sin(y[2])
        f = mu * max(force(t), 0.0)
        rho = max(f / k, floor)
        return [
            -f * (a00 * cos + a01 * sin),
            -f * (a10 * cos + a11 * sin),
            (-y[0] * sin + y[1] * cos) / rho,
        ]

    def jac(t, y):
        cos, sin = math.cos(y[2]), math.sin(y[2])
        f = mu * max(force(t), 0.0)
        rho = max(f / k, floor)
        return [
            [0.0, 0.0, f * (a00 * sin - a01 * cos)],
            [0.0, 0.0, f * (a10 * sin - a11 * cos)],
            [-sin / rho, cos / rho, -(y[0] * cos + y[1] * sin) / rho],
        ]

    def stop(t, y):
        return y[0] * math.cos(y[2]) + y[1] * math.sin(y[2]) - mu * slope(t) / k

    return rhs, jac, stop


def integrate_slide(c, normal: NormalHistory, t0: float, slip, direction):
    """Integrate a slide of the contact ``c`` (a ``PlaneContact``) from ``t0`` [s], slip
    ``slip`` [m/s] and stretch direction ``direction`` (module docstring).

    Returns
    -------
    (end time [s], dense solution of (s_x, s_y, phi) or, rigid, (|s|, angle), stopped by the
    slider: bool)
    """
    from scipy.integrate import solve_ivp

    force, slope = scalar_force(normal)
    a = c.compliance.tolist()
    phi0 = math.atan2(direction[1], direction[0])
    scale = max(float(np.linalg.norm(slip)), 1e-300)
    method = "DOP853"
    if c.rigid:
        rhs, jac, stop = _rigid(c, force, a, scale)
        y0, atol = [scale, phi0], [1e-14 * scale, 1e-12]
    else:
        peak = max(float(np.max(normal.smooth_force(normal.grid))), 0.0)
        floor = FLOOR * c.friction * peak / c.stiffness
        rhs, jac, stop = _compliant(c, force, slope, a, floor)
        y0, atol = [slip[0], slip[1], phi0], [1e-14 * scale, 1e-14 * scale, 1e-12]
        if stiffness_index(normal, t0, scale, floor, c.friction / c.stiffness) > STIFF:
            method = "Radau"
    tick = _budget(c, t0)

    def counted(t, y):
        tick()
        return rhs(t, y)

    stop.terminal, stop.direction = True, -1
    options = {} if method == "DOP853" else {"jac": jac}
    sol = solve_ivp(
        counted, (t0, normal.end), y0, method=method, rtol=RTOL, atol=atol, dense_output=True,
        events=stop, **options,
    )  # fmt: skip
    if sol.status < 0:
        raise RuntimeError(f"the tangential slide's integration failed: {sol.message}")
    hit = sol.status == 1 and sol.t_events[0].size > 0
    end = float(sol.t_events[0][0]) if hit else normal.end
    return end, sol.sol, hit
