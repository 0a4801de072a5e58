"""One step of the general integrator: the contact equation at a new node, and in-step roots.

At node m every case solves ``F_m = law(delta_m, delta'_m, z_m)`` with delta_m, delta'_m affine in
F_m (:mod:`fem_racket.impact.general.receptance`): Newton on F alone, or on (F, z) for an ODE state
advanced by the same cubic quadrature (``z_m = z_base + c g(delta_m, delta'_m, z_m)``, Adams-Moulton
4 on the backward stencil). A memory state (hysteresis) is the largest deflection reached,
including a maximum inside the step, found on the cubic Hermite interpolant of delta through
delta and delta' at the step's ends (fourth order like the scheme); it is refreshed every Newton
iteration. Separation inside a step is found the same way (Hermite root of delta or of an ODE
state with its rate; the force's root on the step's cubic).
"""

from __future__ import annotations

from dataclasses import fields, replace
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.general.cubic_force import lagrange

__all__ = ["cubic_root", "hermite_root", "hermite_value", "solve_step", "turn_max"]

_NEWTON_ITER = 40


def hermite_value(s, p0, m0, p1, m1):
    """Cubic Hermite interpolant at fraction s of a step (values p, slopes m per step)."""
    s2, s3 = s * s, s * s * s
    ends = (2 * s3 - 3 * s2 + 1) * p0 + (-2 * s3 + 3 * s2) * p1
    return ends + (s3 - 2 * s2 + s) * m0 + (s3 - s2) * m1


def turn_max(d0, v0, d1, v1, h) -> np.ndarray:
    """Largest delta on the step (cubic Hermite through the ends' delta and delta')."""
    turn = (v0 > 0) & (v1 <= 0)
    if not np.any(turn):
        return np.maximum(d0, d1)
    m0, m1, dd = h * v0, h * v1, d0 - d1
    qa = 6.0 * dd + 3.0 * m0 + 3.0 * m1
    qb = -6.0 * dd - 4.0 * m0 - 2.0 * m1
    disc = np.sqrt(np.maximum(qb * qb - 4.0 * qa * m0, 0.0))
    # the root of p'(s) = qa s^2 + qb s + m0 where p' falls from m0 > 0 (stable form)
    den = -qb + disc
    s = np.minimum(np.maximum(2.0 * m0 / np.where(den > 0, den, 1.0), 0.0), 1.0)
    p = hermite_value(s, d0, m0, d1, m1)
    return np.where(turn, np.maximum(p, np.maximum(d0, d1)), np.maximum(d0, d1))


def hermite_root(d0, v0, d1, v1, end, h) -> np.ndarray:
    """Fraction s in (0, 1] where the cubic Hermite interpolant of delta reaches ``end``."""
    p0, p1, m0, m1 = d0 - end, d1 - end, h * v0, h * v1
    s = np.minimum(np.maximum(p0 / np.where(p0 - p1 > 0, p0 - p1, 1.0), 0.0), 1.0)
    for _ in range(8):
        f = hermite_value(s, p0, m0, p1, m1)
        s2 = s * s
        df = (6 * s2 - 6 * s) * (p0 - p1) + (3 * s2 - 4 * s + 1) * m0 + (3 * s2 - 2 * s) * m1
        s = np.minimum(np.maximum(s - f / np.where(df != 0, df, -1.0), 0.0), 1.0)
    return np.where(p1 >= 0, 1.0, s)


def cubic_root(values: np.ndarray, offsets: tuple[int, ...]) -> np.ndarray:
    """Fraction s in (0, 1] where the step's cubic through ``values`` (C, 4) at ``offsets``
    falls through zero (the step's end value is <= 0, its start > 0)."""
    coef = values @ lagrange(offsets)  # (C, 4): coefficients of sigma^q
    p0, p1 = values[:, offsets.index(0)], values[:, offsets.index(1)]
    s = np.minimum(np.maximum(p0 / np.where(p0 - p1 > 0, p0 - p1, 1.0), 0.0), 1.0)
    for _ in range(8):
        f = coef[:, 0] + s * (coef[:, 1] + s * (coef[:, 2] + s * coef[:, 3]))
        df = coef[:, 1] + s * (2 * coef[:, 2] + 3 * s * coef[:, 3])
        s = np.minimum(np.maximum(s - f / np.where(df != 0, df, -1.0), 0.0), 1.0)
    return np.where(p1 > 0, 1.0, s)


def solve_step(
    law: ContactLaw,
    linear: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray],
    guess: np.ndarray,
    states: tuple[np.ndarray, np.ndarray, float],
    h: float,
    scale: np.ndarray,
    start: tuple[np.ndarray, np.ndarray],
) -> tuple[np.ndarray, np.ndarray]:
    """Newton on F (and an ODE state z) at one node for every case.

    ``linear`` = (A, B, kd0, kv0): delta = A - kd0 F, delta' = B - kv0 F; ``states`` = (z_prev,
    z_base, zc): an ODE state obeys z = z_base + zc g(delta, delta', z); a memory state is
    max(z_prev, the step's largest delta) (``start`` = delta, delta' at the step's start).
    ``guess``: the starting F [N]; ``h`` the step [s]; ``scale`` the force scale [N].
    """
    A, B, kd0, kv0 = linear
    z_prev, z_base, zc = states
    F = guess.copy()
    ode = law.state == "ode"
    memory = law.state == "memory"
    z = z_prev
    for _ in range(_NEWTON_ITER):
        d = A - kd0 * F
        v = B - kv0 * F
        if memory:
            z = np.maximum(z_prev, turn_max(start[0], start[1], d, v, h))
        r1 = F - law.force(d, v, z)
        tol = 1e-12 * (np.abs(F) + scale)
        if ode:
            r2 = z - z_base - zc * law.rate(d, v, z)
            if np.all(np.abs(r1) <= tol) and np.all(np.abs(r2) <= 1e-12 * (np.abs(z) + 1e-9)):
                break
            fd, fv, fz = law.partials(d, v, z)
            gd, gv, gz = law.rate_partials(d, v, z)
            j11 = 1.0 + fd * kd0 + fv * kv0
            j21 = zc * (gd * kd0 + gv * kv0)
            j22 = 1.0 - zc * gz
            det = j11 * j22 + fz * j21
            dF = -(r1 * j22 + fz * r2) / det
            z = z - (j11 * r2 - j21 * r1) / det
        else:
            if np.all(np.abs(r1) <= tol):
                break
            fd, fv, _ = law.partials(d, v, z)
            dF = -r1 / (1.0 + fd * kd0 + fv * kv0)
        # damped update: a step at most doubles the force scale (hardening laws overshoot)
        cap = 2.0 * (np.abs(F) + scale)
        F = F + np.maximum(np.minimum(dF, cap), -cap)
    else:
        raise RuntimeError("contact-law Newton iteration did not converge")
    return F, z


def per_case(obj: Any, ncase: int, idx: np.ndarray | None = None, column: bool = False) -> Any:
    """A law or receptance with its per-case array fields (first axis ``ncase``; a frame's
    ``omega`` is shared unless it has a row per case) cut to the cases ``idx`` and, with
    ``column``, shaped (C, 1) to broadcast against (C, N) histories."""
    cut = {}
    for f in fields(obj):
        value = getattr(obj, f.name)
        shared = f.name == "omega" and np.ndim(value) == 1
        if np.ndim(value) > 0 and np.shape(value)[0] == ncase and not shared:
            value = np.asarray(value) if idx is None else np.asarray(value)[idx]
            cut[f.name] = value[:, None] if column else value
    return replace(obj, **cut) if cut else obj
