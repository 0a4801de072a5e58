"""The vector tangential contact (:class:`PlaneContact`) whose slip turns: :func:`march_vector`.

The model is :mod:`fem_racket.impact.tangential.plane`'s. A grip is linear (u' = s,
s' = -k_t A u) and solved in closed form on A's eigenvectors (two harmonic oscillators at
omega_i = sqrt(k_t a_i)); the grip ends at the first time k_t |u| reaches mu F (bracketed on the
normal history's grid, then Brent's method). A slide is not linear: with d = (cos phi, sin phi)
the stretch's direction and rho = mu F / k_t its length::

    s' = -mu F A d,   phi' = (s . d_perp) / rho,   d_perp = (-sin phi, cos phi)

integrated by :func:`fem_racket.impact.tangential.slide.integrate_slide` (DOP853, or Radau where
the slide is stiff, at rtol 1e-13) until the slider stops (s . d = rho') or the normal force
returns to zero. A rigid tangential contact (eta^2 = 0) slides along the slip itself
(d = s / |s|) until |s| = 0; the ball then rolls with no force.
"""

from __future__ import annotations

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
from fem_racket.impact.tangential.slide import integrate_slide

__all__ = ["PlaneContact", "PlanePhase", "PlaneSolution", "march_vector"]


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
            t1, ode, hit = integrate_slide(c, normal, p.start, p.slip, p.stretch)
            phases[-1] = PlanePhase(p.kind, p.start, t1, p.slip, p.stretch, ode)
            if not hit or t1 >= normal.end:
                break
            s1, f1 = (v[0] for v in _slide(c, phases[-1], normal, np.array([t1])))
            s1 = np.zeros(2) if c.rigid else s1
            nxt = PlanePhase("grip", t1, normal.end, s1, -f1 / c.stiffness)
        check_chattering(c.friction, len(phases), t1)
        phases.append(nxt)
    return PlaneSolution(c, normal, tuple(phases))
