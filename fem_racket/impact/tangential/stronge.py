"""Stronge's closed forms for a sphere striking a clamped rigid target obliquely.

Stronge 2000 (*Impact Mechanics*, section 5.3; the regimes as implemented in pooltool's
``physics/resolve/stronge_compliant.py``, Apache-2.0), in units of the normal speed V and
omega_n (the normal force of :class:`~fem_racket.impact.tangential.normal.StrongeNormal`;
tangential spring eta^2 = k_n / k_t; contact point slip r = s_0 / V at impact)::

    initial grip       r < mu eta^2
    gross slip         r > mu ((1 + e) beta_t - eta^2 / e):  s_f = s_0 - mu beta_t V (1 + e)
    slide then grip    otherwise, the grip starting in compression (r <= mu beta_t) at
                       cos(omega_n t) = (r / mu - beta_t) / (eta^2 - beta_t), or in restitution at
                       cos(phi) = (r / mu - beta_t) / (eta^2 / e - e beta_t),
                       phi = omega_n t / e + (pi / 2)(1 - 1 / e)

A grip ends (the ball slides again) where the harmonic stretch of the tangential spring,
frequency omega_t = omega_n sqrt(beta_t / eta^2), reaches the friction limit: the one root that
is not in closed form; after it s_f = s - sigma mu beta_t (P(t_f) - P), i.e.
``- sigma mu beta_t V e (1 + cos phi)`` in restitution.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["StrongeOutcome", "gross_slip_bound", "initial_grip_bound", "stronge_outcome"]


def gross_slip_bound(mu: float, e: float, eta2: float, beta_t: float) -> float:
    """Smallest s_0 / V for which the ball slides throughout: mu ((1 + e) beta_t - eta^2 / e)."""
    return mu * ((1.0 + e) * beta_t - eta2 / e)


def initial_grip_bound(mu: float, eta2: float) -> float:
    """Largest s_0 / V for which the ball grips from the start: mu eta^2."""
    return mu * eta2


@dataclass(frozen=True)
class StrongeOutcome:
    """Final slip s_f / V, the regime, and its grip start and end times in units of 1/omega_n
    (None when absent)."""

    slip: float
    regime: str
    grip_start: float | None
    grip_end: float | None


def _phase(t: float, e: float) -> tuple[float, float, float]:
    """(phi, F / (m V omega_n), P / (m V)) at time t [1/omega_n]."""
    if t <= 0.5 * math.pi:
        return t, math.sin(t), 1.0 - math.cos(t)
    phi = t / e + 0.5 * math.pi * (1.0 - 1.0 / e)
    return phi, math.sin(phi), 1.0 - e * math.cos(phi)


def _grip_start(r: float, mu: float, e: float, eta2: float, beta_t: float) -> float:
    if r <= mu * beta_t:
        return math.acos((r / mu - beta_t) / (eta2 - beta_t))
    x = (r / mu - beta_t) / (eta2 / e - e * beta_t)
    return e * (math.acos(x) - 0.5 * math.pi * (1.0 - 1.0 / e))


def stronge_outcome(r: float, mu: float, e: float, eta2: float, beta_t: float) -> StrongeOutcome:
    """Final slip of a sphere on a clamped rigid target for incident slip ratio ``r`` >= 0.

    Parameters
    ----------
    r : float
        s_0 / V, incident slip over normal speed.
    mu, e, eta2, beta_t : float
        Friction, normal COR in (0, 1], eta^2 > 0, beta_t = 1 + m R^2 / I.
    """
    from scipy.optimize import brentq

    t_f = 0.5 * math.pi * (1.0 + e)
    if r >= gross_slip_bound(mu, e, eta2, beta_t):
        return StrongeOutcome(r - mu * beta_t * (1.0 + e), "slide", None, None)
    if r < initial_grip_bound(mu, eta2):
        t_s, s_s, u_s, regime = 0.0, r, 0.0, "grip"
    else:
        t_s = _grip_start(r, mu, e, eta2, beta_t)
        _, f, p = _phase(t_s, e)
        # stretch u = mu F / k_t = mu eta^2 F / (m omega_n^2) in units V / omega_n
        t_s, s_s, u_s, regime = t_s, r - mu * beta_t * p, mu * eta2 * f, "slide-grip"
    w = math.sqrt(beta_t / eta2)

    def excess(t: float) -> float:  # k_t |u| - mu F in units m V omega_n
        th = w * (t - t_s)
        u = u_s * math.cos(th) + s_s / w * math.sin(th)
        return abs(u) / eta2 - mu * _phase(t, e)[1]

    grid = np.linspace(t_s, t_f, 4001)[1:]
    vals = np.array([excess(t) for t in grid])
    hit = np.flatnonzero(vals >= 0.0)
    th_f = w * (t_f - t_s)
    if hit.size == 0 or grid[hit[0]] >= t_f:
        return StrongeOutcome(s_s * math.cos(th_f) - u_s * w * math.sin(th_f), regime, t_s, None)
    i = int(hit[0])
    t_e = brentq(excess, grid[i - 1], grid[i], xtol=1e-15, rtol=4 * np.finfo(float).eps)
    th = w * (t_e - t_s)
    s_e = s_s * math.cos(th) - u_s * w * math.sin(th)
    sigma = math.copysign(1.0, u_s * math.cos(th) + s_s / w * math.sin(th))
    rest = 1.0 + e - _phase(t_e, e)[2]  # e (1 + cos phi) when t_e is in restitution
    return StrongeOutcome(s_e - sigma * mu * beta_t * rest, regime + "-slide", t_s, t_e)
