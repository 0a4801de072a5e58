"""The general integrator's time march over a uniform grid, for a batch of cases at once.

Node by node (:func:`fem_racket.impact.general.step.solve_step`), the history of the nodal
forces enters through the kernel tables of :mod:`fem_racket.impact.general.receptance`. The first
three nodes use the forward (starting) stencil, which reaches nodes 1-3 at once: they are solved by
Gauss-Seidel sweeps over the three (the coupling through the later nodes is O((omega h)^2), so
a few sweeps converge to round-off). Separation is found per case on the law's own end
condition inside its step; the outcomes integrate the same piecewise cubic force (impulse,
ball velocity) so that they are fourth order like the states.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.general.cubic_force import BACKWARD, ORDER, lagrange, step_stencil
from fem_racket.impact.general.receptance import (
    Receptance,
    free_motion,
    kernels,
    stencil_quadrature,
)
from fem_racket.impact.general.step import (
    cubic_root,
    hermite_root,
    per_case,
    solve_step,
    turn_max,
)

__all__ = ["GeneralOutcome", "march"]

#: Gauss-Seidel sweeps over the starting nodes at most (converged at round-off in 3-5).
_START_SWEEPS = 12


@dataclass(frozen=True, eq=False)
class GeneralOutcome:
    """Per-case results of the general integrator (arrays of shape (C,), histories (C, N)).

    Attributes
    ----------
    contact_time : ndarray
        t_c [s].
    ball_velocity : ndarray
        Ball velocity at separation [m/s] (negative: rebounding).
    impulse : ndarray
        int F dt over the contact [N s].
    peak_force : ndarray
        Largest contact force [N].
    step : ndarray
        Time step h of each case [s] (cases with similar contact times share one).
    force, deflection, rate, state : ndarray, shape (C, N)
        F [N], delta [m], delta' [m/s] and the law's state [m] at t = m h (valid up to each
        case's separation step ``last``); F between nodes is the piecewise cubic of
        :mod:`fem_racket.impact.general.cubic_force`.
    last : ndarray of int
        Index of the step in which each case separated.
    fraction : ndarray
        Where in that step it separated (0-1].
    kept : ndarray of int
        Flexible modes kept per case (the others: one pseudo-mode).
    """

    contact_time: np.ndarray
    ball_velocity: np.ndarray
    impulse: np.ndarray
    peak_force: np.ndarray
    step: np.ndarray
    force: np.ndarray
    deflection: np.ndarray
    rate: np.ndarray
    state: np.ndarray
    last: np.ndarray
    fraction: np.ndarray
    kept: np.ndarray


def _stencil_values(arr: np.ndarray, k: int) -> tuple[np.ndarray, tuple[int, ...]]:
    """Values (C, 4) of ``arr`` at step k's stencil nodes, and the stencil's offsets."""
    off = step_stencil(k)
    return arr[:, [k + o for o in off]], off


def march(
    law: ContactLaw,
    rec: Receptance,
    speed: np.ndarray,
    frame_velocity: np.ndarray | None,
    omega_c: np.ndarray,
    beta: float,
    span: float,
    h: float,
    whole: bool = False,
) -> GeneralOutcome | None:
    """One run with step ``h`` [s] up to ``span`` [s] (None: some case is still in contact).

    ``whole``: solve every node at once (:func:`fem_racket.impact.general.nodes.solve_all`,
    laws without an ODE state), marching only if that does not converge.
    """
    ncase = rec.a.shape[0]
    wide = per_case(law, ncase, column=True)  # evaluated on (C, N) histories
    nsteps = max(int(np.ceil(span / h)) + 1, ORDER + 2)
    K = kernels(rec, omega_c, beta, h, nsteps)
    t = np.arange(nsteps) * h
    dfree, vfree = free_motion(rec, speed, frame_velocity, t)
    F, D, V, Z, G = (np.zeros((ncase, nsteps)) for _ in range(5))
    D[:, 0], V[:, 0] = dfree[:, 0], vfree[:, 0]
    zero = np.zeros(ncase)
    F[:, 0] = law.force(D[:, 0], V[:, 0], zero)
    ode, memory = law.state == "ode", law.state == "memory"
    if ode:
        G[:, 0] = law.rate(D[:, 0], V[:, 0], zero)
    scale = np.abs(speed) / (rec.compliance * span)
    if whole and not ode:
        done = _whole(wide, K, dfree, vfree, F[:, 0], h, scale, speed / rec.compliance, span, G)
        if done is not None:
            F, D, V, Z, last, frac = done
            if np.any(last < 0):
                return None
            return _outcome(F, D, V, Z, last, frac, h, speed, rec, K.kept)

    def node(m: int, guess: np.ndarray) -> None:
        """Solve node m with every other node's current values."""
        hd = np.einsum("ij,ij->i", K.Td[:, m:0:-1], F[:, :m])
        hv = np.einsum("ij,ij->i", K.Tv[:, m:0:-1], F[:, :m])
        kd0, kv0 = K.Td[:, 0], K.Tv[:, 0]
        others = [j for j in range(ORDER) if j != m]  # the starting corrections
        hd = hd + np.einsum("ij,ij->i", K.Sd[:, m, others], F[:, others])
        hv = hv + np.einsum("ij,ij->i", K.Sv[:, m, others], F[:, others])
        if m < ORDER:
            kd0, kv0 = kd0 + K.Sd[:, m, m], kv0 + K.Sv[:, m, m]
        A, B = dfree[:, m] - hd, vfree[:, m] - hv
        z_base, zc = Z[:, m - 1], 0.0
        if ode:
            vals, off = _stencil_values(G, m - 1)
            q = h * stencil_quadrature(off)
            pos = off.index(1)
            zc = q[pos]
            z_base = Z[:, m - 1] + vals @ q - zc * vals[:, pos]
        start = (D[:, m - 1], V[:, m - 1])
        states = (Z[:, m - 1], z_base, zc)
        Fm, zm = solve_step(law, (A, B, kd0, kv0), guess, states, h, scale, start)
        d, v = A - kd0 * Fm, B - kv0 * Fm
        if memory:
            zm = np.maximum(Z[:, m - 1], turn_max(D[:, m - 1], V[:, m - 1], d, v, h))
        F[:, m], D[:, m], V[:, m], Z[:, m] = Fm, d, v, zm
        if ode:
            G[:, m] = law.rate(d, v, zm)

    # starting nodes 1-3: Gauss-Seidel sweeps (the forward stencil couples them)
    F[:, 1:ORDER] = F[:, :1]
    G[:, 1:ORDER] = G[:, :1]
    for _ in range(_START_SWEEPS):
        before = F[:, 1:ORDER].copy(), Z[:, 1:ORDER].copy()
        for m in range(1, ORDER):
            node(m, F[:, m])
        dF = np.abs(F[:, 1:ORDER] - before[0]) <= 1e-13 * (np.abs(F[:, 1:ORDER]) + scale[:, None])
        dZ = np.abs(Z[:, 1:ORDER] - before[1]) <= 1e-13 * (np.abs(Z[:, 1:ORDER]) + 1e-9)
        if np.all(dF) and np.all(dZ):
            break
    last = np.full(ncase, -1)
    frac = np.ones(ncase)
    for m in range(1, nsteps):
        if m >= ORDER:
            node(m, 3.0 * F[:, m - 1] - 3.0 * F[:, m - 2] + F[:, m - 3])
        ended, s = find_end(wide, F, D, V, Z, G, h, m, m + 1)
        ended = (ended > 0) & (last < 0)
        last = np.where(ended, m, last)
        frac = np.where(ended, s, frac)
        if np.all(last >= 0):
            break
    else:
        return None
    return _outcome(F, D, V, Z, last, frac, h, speed, rec, K.kept)


def _whole(law, K, dfree, vfree, F0, h, scale, momentum, span, G):
    """Every node at once from a half-sine guess (impulse 1.5 m_eff v0 over span / 2)."""
    from fem_racket.impact.general.nodes import solve_all

    t = np.arange(dfree.shape[1]) * h
    dur = 0.5 * span
    pulse = np.where(t < dur, np.sin(np.pi * np.minimum(t, dur) / dur), 0.0)
    guess = (0.75 * np.pi * momentum / dur)[:, None] * pulse[None, :]
    guess[:, 0] = F0

    def ends(F, D, V, Z):
        last = find_end(law, F, D, V, Z, G, h, where=False)[0]
        return np.where(last < 0, F.shape[1] - 1, last)

    out = solve_all(law, K, dfree, vfree, guess, h, scale, ends)
    if out is None:
        return None
    F, D, V, Z = out
    return (F, D, V, Z, *find_end(law, F, D, V, Z, G, h))


def find_end(law, F, D, V, Z, G, h, first=1, stop=None, where=True):
    """First step (its end node ``last``) in which each case's contact ends among the nodes
    ``first`` .. ``stop`` - 1, and where in it (fraction; ones unless ``where``); last = -1
    where it does not."""
    stop = F.shape[1] if stop is None else stop
    sl, pr = slice(first, stop), slice(first - 1, stop - 1)
    if law.end == "force":
        cond = (F[:, pr] > 0) & (F[:, sl] <= 0)
    elif law.end == "state":
        cond = (Z[:, pr] > 0) & (Z[:, sl] <= 0)
    else:
        end = np.broadcast_to(law.end_deflection(Z), F.shape)
        cond = (D[:, pr] - end[:, pr] > 0) & (D[:, sl] - end[:, sl] <= 0)
    hit = np.any(cond, axis=1)
    last = np.where(hit, first + np.argmax(cond, axis=1), -1)
    frac = np.ones(F.shape[0])
    k = np.flatnonzero(hit)
    if k.size == 0 or not where:
        return last, frac
    m = last[k]
    if law.end == "force":
        vals = np.stack([F[k, m - 1 + o] for o in BACKWARD], axis=1) if np.all(m >= 3) else None
        if vals is None:
            for i, mm in zip(k, m, strict=True):
                v_, off = _stencil_values(F[i : i + 1], int(mm) - 1)
                frac[i] = cubic_root(v_, off)[0]
        else:
            frac[k] = cubic_root(vals, BACKWARD)
    elif law.end == "state":
        frac[k] = hermite_root(Z[k, m - 1], G[k, m - 1], Z[k, m], G[k, m], 0.0, h)
    else:
        frac[k] = hermite_root(D[k, m - 1], V[k, m - 1], D[k, m], V[k, m], end[k, m], h)
    return last, frac


def _dot(vals: np.ndarray, w: np.ndarray) -> np.ndarray:
    """sum_r vals[..., r] w[r], term by term in order (no BLAS: the same bits for any batch)."""
    return sum(vals[..., r] * w[r] for r in range(w.size))


def _outcome(F, D, V, Z, last, frac, h, speed, rec, kept) -> GeneralOutcome:
    """Scalars from the histories: the impulse of the piecewise cubic up to separation (``h``:
    the step, one for all cases or one per case)."""
    ncase, nsteps = F.shape
    h = np.broadcast_to(np.asarray(h, dtype=float), (ncase,))
    steps = np.zeros((ncase, nsteps - 1))  # int over each whole step
    for k in (0, 1):  # elementwise sums: a case's bits do not depend on the batch
        vals, off = _stencil_values(F, k)
        steps[:, k] = h * _dot(vals, stencil_quadrature(off))
    qb = stencil_quadrature(BACKWARD)
    steps[:, 2:] = h[:, None] * sum(qb[r] * F[:, r : nsteps - 3 + r] for r in range(ORDER))
    done = np.concatenate([np.zeros((ncase, 1)), np.cumsum(steps, axis=1)], axis=1)
    idx = np.arange(ncase)
    k = last - 1  # the step of separation, integrated up to its fraction
    impulse = done[idx, k].copy()
    powers = np.arange(1, ORDER + 1)[:, None]
    c = lagrange(BACKWARD)
    x = frac[None, :] ** powers / powers
    q = sum(c[:, j : j + 1] * x[j] for j in range(ORDER))  # (4, C): int_0^frac L_r
    ks = np.maximum(k, 2)[:, None] + np.array(BACKWARD)
    impulse += np.where(k >= 2, h * np.sum(F[idx[:, None], ks] * q.T, axis=1), 0.0)
    for i in np.flatnonzero(k < 2):  # separation in a starting step (forward stencil)
        off = step_stencil(int(k[i]))
        impulse[i] += h[i] * _dot(F[i, [k[i] + o for o in off]], stencil_quadrature(off, frac[i]))
    # peak: the parabola through the largest node before separation and its neighbours
    masked = np.where(np.arange(nsteps)[None, :] <= last[:, None], F, -np.inf)
    i = np.clip(np.argmax(masked, axis=1), 1, nsteps - 2)
    a, b, c = masked[idx, i - 1], masked[idx, i], masked[idx, i + 1]
    den = a - 2.0 * b + c
    ok = np.isfinite(den) & (den < 0.0)
    peak = np.where(ok, b - 0.125 * (c - a) ** 2 / np.where(ok, den, -1.0), np.max(masked, axis=1))
    return GeneralOutcome(
        contact_time=(last - 1 + frac) * h,
        ball_velocity=speed - impulse / rec.ball_mass,
        impulse=impulse,
        peak_force=peak,
        step=h.copy(),
        force=F[:, : last.max() + 1],
        deflection=D[:, : last.max() + 1],
        rate=V[:, : last.max() + 1],
        state=Z[:, : last.max() + 1],
        last=last,
        fraction=frac,
        kept=kept,
    )
