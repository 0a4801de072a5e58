"""The vector tangential contact (:class:`PlaneContact`) whose slip turns: :func:`march_vector`.

The model is :mod:`fem_racket.impact.tangential.plane`'s. A grip is linear (u' = s,
s' = -k_t A u) and solved in closed form on A's eigenvectors (two harmonic oscillators at
omega_i = sqrt(k_t a_i)); the grip ends at the first time k_t |u| reaches mu F (bracketed on the
normal history's grid, then Brent's method). A slide is not linear: with d = (cos phi, sin phi)
the stretch's direction and rho = mu F / k_t its length::

    s' = -mu F A d,   phi' = (s . d_perp) / rho,   d_perp = (-sin phi, cos phi)

integrated by an explicit Runge-Kutta method of order 8 (scipy's DOP853, rtol 1e-13) until the
slider stops (s . d = rho', an event located by the integrator, with the history's continuous
``slope`` F') or the normal force returns to zero. A rigid tangential contact (eta^2 = 0)
slides along the slip itself (d = s / |s|), written in polar form (|s|' = -mu F d.A d, the
angle turning at -mu F d_perp.A d / |s|) until |s| = 0; the ball then rolls with no force.

The stretch turns toward the slip at the rate |s_perp| / rho, fast where the normal force is
small: below FLOOR of its largest value rho is held at that floor (the force there, under
1e-6 of its peak, acts for ~1e-6 of the contact: an impulse error ~1e-12).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.impact.tangential.march import (
    FrictionSpring,
    PhaseSummary,
    TangentialContact,
    _first_crossing,
    check_chattering,
)
from fem_racket.impact.tangential.normal import NormalHistory
from fem_racket.impact.tangential.scalar import scalar_force

__all__ = ["PlaneContact", "PlanePhase", "PlaneSolution", "march_vector"]

#: Relative tolerance of the slides' integration.
RTOL = 1e-13
METHOD = "DOP853"
#: The stretch length below which the slide turns no faster, over its largest mu F / k_t.
FLOOR = 1e-6


@dataclass(frozen=True, eq=False)
class PlaneContact(FrictionSpring):
    """The tangential contact's mechanics on the face.

    Parameters
    ----------
    friction, stiffness : float
        As :class:`fem_racket.impact.tangential.march.FrictionSpring`.
    compliance : ndarray, shape (2, 2)
        A [1/kg]: s' = A f (symmetric, positive definite).
    """

    compliance: np.ndarray

    def line(self, direction: np.ndarray) -> TangentialContact:
        """The 1-D contact along the unit ``direction``: y when it is (0, 1), else x (A
        diagonal, or a multiple of 1 for any direction)."""
        a = self.compliance
        inv = a[1, 1] if direction[0] == 0.0 else a[0, 0]
        return TangentialContact(self.friction, self.stiffness, 1.0 / inv)


@dataclass(frozen=True, eq=False)
class PlanePhase:
    """One phase over [start, end] [s]: a grip from slip ``slip`` and stretch ``stretch``
    [m/s, m], or a slide whose ``ode`` gives (s_x, s_y, phi) (rigid: (|s|, angle))."""

    kind: str
    start: float
    end: float
    slip: np.ndarray
    stretch: np.ndarray
    ode: Any = None


def _grip(c: PlaneContact, p: PlanePhase, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Slip (n, 2) and stretch (n, 2) during a grip."""
    tau = np.asarray(t, dtype=float)[:, None] - p.start
    if c.rigid:
        return np.zeros((tau.size, 2)), np.zeros((tau.size, 2))
    lam, q = np.linalg.eigh(c.compliance)
    w = np.sqrt(c.stiffness * lam)
    z0, zd0 = q.T @ p.stretch, q.T @ p.slip
    cos, sin = np.cos(w * tau), np.sin(w * tau)
    z = z0 * cos + zd0 / w * sin
    zd = zd0 * cos - z0 * w * sin
    return zd @ q.T, z @ q.T


def _slide(c: PlaneContact, p: PlanePhase, normal, t) -> tuple[np.ndarray, np.ndarray]:
    """Slip (n, 2) and force on the ball (n, 2) during a slide."""
    t = np.asarray(t, dtype=float)
    if p.ode is None:  # no friction: nothing changes
        return np.broadcast_to(p.slip, (t.size, 2)).copy(), np.zeros((t.size, 2))
    y = p.ode(t)
    if c.rigid:
        s = y[0][:, None] * np.column_stack([np.cos(y[1]), np.sin(y[1])])
        d = np.column_stack([np.cos(y[1]), np.sin(y[1])])
    else:
        s = np.column_stack([y[0], y[1]])
        d = np.column_stack([np.cos(y[2]), np.sin(y[2])])
    return s, -c.friction * np.maximum(normal.smooth_force(t), 0.0)[:, None] * d


@dataclass(frozen=True, eq=False)
class PlaneSolution(PhaseSummary):
    """The marched vector contact: its phases, and the slip and force at any time."""

    contact: PlaneContact
    normal: NormalHistory
    phases: tuple[PlanePhase, ...]

    def at(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Slip velocity [m/s] and tangential force on the ball [N] at times ``t`` [s], shape
        (len(t), 2) (after ``end`` the force is zero and the slip keeps its final value)."""
        t = np.minimum(np.atleast_1d(np.asarray(t, dtype=float)), self.normal.end)
        s, f = np.zeros((t.size, 2)), np.zeros((t.size, 2))
        for p in self.phases:
            sel = (t >= p.start) & (t <= p.end)
            if not sel.any():
                continue
            if p.kind == "grip":
                s[sel], u = _grip(self.contact, p, t[sel])
                f[sel] = -self.contact.stiffness * u if not self.contact.rigid else 0.0
            else:
                s[sel], f[sel] = _slide(self.contact, p, self.normal, t[sel])
        return s, f

    @property
    def slip_in(self) -> np.ndarray:
        return self.phases[0].slip

    @property
    def final_slip(self) -> np.ndarray:
        return self.at(np.array([self.normal.end]))[0][0]

    @property
    def impulse(self) -> np.ndarray:
        """Tangential impulse on the ball [N s] = A^-1 (s_end - s_0)."""
        return np.linalg.solve(self.contact.compliance, self.final_slip - self.slip_in)

    @property
    def reversal_times(self) -> list[float]:
        """Times the tangential force's component along the incoming slip changes sign
        inside a grip [s] (the 1-D definition along a line)."""
        s0 = self.slip_in
        if self.contact.rigid or self.contact.friction == 0.0 or not s0.any():
            return []
        from scipy.optimize import brentq

        e = s0 / np.linalg.norm(s0)
        out: list[float] = []
        for p in (q for q in self.phases if q.kind == "grip" and q.end > q.start):

            def along(t, p=p):
                return _grip(self.contact, p, np.atleast_1d(t))[1] @ e

            t = np.linspace(p.start, p.end, 257)
            v = along(t)
            for i in np.flatnonzero(np.sign(v[1:]) * np.sign(v[:-1]) < 0):
                out.append(float(brentq(lambda x: along(x)[0], t[i], t[i + 1], xtol=1e-15)))
        return out


def _start(c: PlaneContact, normal: NormalHistory, s0: np.ndarray) -> PlanePhase:
    """Grip with the spring unstretched, unless the ball slips at once (as the 1-D march)."""
    f0 = max(float(normal.force(0.0)), 0.0)
    size = float(np.linalg.norm(s0))
    slow = f0 == 0.0 and c.stiffness * size >= c.friction * float(normal.slope(0.0))
    zero = np.zeros(2)
    if c.friction == 0.0 or (size > 0.0 and (c.rigid or slow)):
        return PlanePhase("slide", 0.0, normal.end, s0, s0 / size if size else zero)
    return PlanePhase("grip", 0.0, normal.end, s0, zero)


def _integrate(c: PlaneContact, normal: NormalHistory, t0: float, slip, direction):
    """Integrate a slide from ``t0``; (end time, dense solution, stopped by the slider)."""
    from scipy.integrate import solve_ivp

    mu, k, a = c.friction, c.stiffness, c.compliance
    force, slope = scalar_force(normal)
    (a00, a01), (a10, a11) = a.tolist()
    phi0 = math.atan2(direction[1], direction[0])
    scale = max(float(np.linalg.norm(slip)), 1e-300)
    if c.rigid:

        def rhs(t, y):
            cos, sin = math.cos(y[1]), math.sin(y[1])
            f = mu * max(force(t), 0.0)
            ad = (a00 * cos + a01 * sin, a10 * cos + a11 * sin)
            turn = -sin * ad[0] + cos * ad[1]
            return [-f * (cos * ad[0] + sin * ad[1]), -f * turn / max(y[0], 1e-9 * scale)]

        def stop(t, y):
            return y[0]

        y0, atol = [scale, phi0], [1e-14 * scale, 1e-12]
    else:
        floor = FLOOR * mu * max(float(np.max(normal.smooth_force(normal.grid))), 0.0) / k

        def rhs(t, y):
            cos, sin = math.cos(y[2]), math.sin(y[2])
            f = mu * max(force(t), 0.0)
            rho = max(f / k, floor)
            return [
                -f * (a00 * cos + a01 * sin),
                -f * (a10 * cos + a11 * sin),
                (-y[0] * sin + y[1] * cos) / rho,
            ]

        def stop(t, y):
            return y[0] * math.cos(y[2]) + y[1] * math.sin(y[2]) - mu * slope(t) / k

        y0, atol = [slip[0], slip[1], phi0], [1e-14 * scale, 1e-14 * scale, 1e-12]
    stop.terminal, stop.direction = True, -1
    sol = solve_ivp(
        rhs, (t0, normal.end), y0, method=METHOD, rtol=RTOL, atol=atol, dense_output=True,
        events=stop,
    )  # fmt: skip
    if sol.status < 0:
        raise RuntimeError(f"the tangential slide's integration failed: {sol.message}")
    hit = sol.status == 1 and sol.t_events[0].size > 0
    end = float(sol.t_events[0][0]) if hit else normal.end
    return end, sol.sol, hit


def march_vector(c: PlaneContact, normal: NormalHistory, slip: np.ndarray) -> PlaneSolution:
    """March the vector contact from slip ``slip`` [m/s] (shape (2,)) and an unstretched
    spring (module docstring)."""
    phases = [_start(c, normal, np.asarray(slip, dtype=float))]
    while c.friction > 0.0:
        p = phases[-1]
        if p.kind == "grip":
            if c.rigid:
                break  # rolling: no force, no slip

            def g(t, p=p):
                u = _grip(c, p, np.atleast_1d(t))[1]
                val = c.stiffness * np.linalg.norm(u, axis=1) - c.friction * normal.force(t)
                return val if np.ndim(t) else float(val[0])

            t1 = _first_crossing(g, p.start, normal.end, normal.grid)
            if t1 is None or t1 >= normal.end:
                break
            s1, u1 = (v[0] for v in _grip(c, p, np.array([t1])))
            nxt = PlanePhase("slide", t1, normal.end, s1, u1 / np.linalg.norm(u1))
            phases[-1] = PlanePhase(p.kind, p.start, t1, p.slip, p.stretch)
        else:
            t1, ode, hit = _integrate(c, normal, p.start, p.slip, p.stretch)
            phases[-1] = PlanePhase(p.kind, p.start, t1, p.slip, p.stretch, ode)
            if not hit or t1 >= normal.end:
                break
            s1, f1 = (v[0] for v in _slide(c, phases[-1], normal, np.array([t1])))
            s1 = np.zeros(2) if c.rigid else s1
            nxt = PlanePhase("grip", t1, normal.end, s1, -f1 / c.stiffness)
        check_chattering(c.friction, len(phases), t1)
        phases.append(nxt)
    return PlaneSolution(c, normal, tuple(phases))
