"""The batched engine's case loop, compiled (numba): poles -> roots -> COR, t_c, peak force.

One pass per case (:mod:`fem_racket.impact.exact.kernel_roots`, then
:mod:`fem_racket.impact.exact.kernel_events`), scratch arrays shared across cases and grown
when a case needs a finer grid. Per case, in the columns of :data:`LAW` (``law``): 1/m_B plus
the rigid modes' squared values mu0 [1/kg], omega_c [rad/s], the flexibility [s^2/kg] and mass
[1/kg] of the modes not given, K_CB [N/m], C_CB [N s/m], m_B [kg]. Results per case, in the
columns of :data:`OUT`: COR, t_c [s], peak force per unit speed [N s/m] (NaN unless asked),
flexible modes kept, and a status (0 solved, 1 solved but its event came close to zero before
separating, 2 no separation, 3 roots not converged: the caller solves those by
eigen-decomposition and :func:`events_cases`).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from fem_racket.impact.exact import kernel_events as ke
from fem_racket.impact.exact.kernel_roots import case_poles, case_roots
from fem_racket.impact.exact.separation import RESOLVED
from fem_racket.impact.kernel_cache import KERNEL_OPTIONS

__all__ = ["LAW", "OUT", "T_MAX_FACTOR", "events_cases", "solve_cases"]

#: Columns of the per-case law array and of the results.
LAW = ("mu0", "omega_c", "flex", "mass", "k", "c", "mb")
OUT = ("cor", "contact_time", "peak", "kept", "status")
#: Give up on separation after this many eq-11 contact times.
T_MAX_FACTOR = 20.0


@njit(**KERNEL_OPTIONS)
def _scratch(R_max):
    """Per-case work arrays (use, vals, buf, fw) for up to R_max roots."""
    return (
        np.empty(R_max, np.bool_),
        np.empty(1024),
        np.empty(1024, np.complex128),
        np.empty(R_max, np.complex128),
    )


@njit(**KERNEL_OPTIONS)
def _grow(scratch, G):
    """Scratch (use, vals, buf) holding at least G grid points."""
    use, vals, buf, fw = scratch
    if vals.size >= G:
        return scratch
    return use, np.empty(2 * G), np.empty(2 * G, np.complex128), fw


@njit(**KERNEL_OPTIONS)
def _events(lam, res, R, mult, law, flags, out, scratch):
    """COR, t_c, peak force and status of one case from its roots (out[0, 1, 2, 4]);
    ``flags`` = (force event, want peak). Returns the scratch (grown if it had to)."""
    k, c, mb = law[4], law[5], law[6]
    fw = scratch[3]
    for j in range(R):
        fw[j] = (k + c * lam[j]) * res[j]
    w = fw if flags[0] else res
    t_est = np.pi / law[1]
    use = scratch[0]
    G = ke.grid_size(lam, w, R, 2.0 * t_est, RESOLVED, use)
    scratch = _grow(scratch, G)
    t, touch = ke.separation_time(lam, w, R, t_est, T_MAX_FACTOR * t_est, G, scratch)
    out[1] = t
    if not np.isfinite(t):
        out[0] = out[2] = np.nan
        out[4] = 2
        return scratch
    out[0] = ke.impulse(lam, fw, R, mult, t) / mb - 1.0
    out[2] = np.nan
    if flags[1]:
        G = ke.peak_points(lam, fw, R, t, use)
        scratch = _grow(scratch, G)
        out[2] = ke.peak_force(lam, fw, R, mult, t, G, scratch)
    out[4] = 1 if touch else 0
    return scratch


@njit(**KERNEL_OPTIONS)
def solve_cases(omega, values, law, beta, flags):
    """Every case: omega, values (n, m) its flexible modes [rad/s] and mode values at the
    impact point [1/sqrt(kg)], ``law`` (n, 7) as :data:`LAW`, cut-off factor ``beta`` (inf:
    every mode), ``flags`` (force event, want peak). Returns (n, 5) as :data:`OUT`."""
    n, m = omega.shape
    out = np.empty((n, 5))
    R_max = m + 2
    d, v, work = np.empty(R_max), np.empty(R_max), np.empty(R_max)
    lam, res = np.empty(R_max, np.complex128), np.empty(R_max, np.complex128)
    step, dfl = np.empty(R_max, np.complex128), np.empty(R_max, np.complex128)
    pole = np.empty(R_max, np.int64)
    scratch = _scratch(R_max)
    for i in range(n):
        L = law[i]
        R, kept = case_poles(omega[i], values[i], L[0], L[1], beta, L[2], L[3], d, v)
        out[i, 3] = kept
        if case_roots(d, v, R, L[4], L[5], lam, res, work, (step, dfl, pole)):
            scratch = _events(lam, res, R, 2.0, L, flags, out[i], scratch)
        else:
            out[i, 0] = out[i, 1] = out[i, 2] = np.nan
            out[i, 4] = 3
    return out


@njit(**KERNEL_OPTIONS)
def events_cases(lam, res, count, law, flags):
    """COR, t_c, peak force and status of cases given every root ``lam`` and residue ``res``
    (n, R) (the first ``count`` of each row; conjugates included, as an eigen-decomposition
    gives them). Returns (n, 5) as :data:`OUT` (``kept`` left NaN)."""
    n, R_max = lam.shape
    out = np.full((n, 5), np.nan)
    scratch = _scratch(R_max)
    for i in range(n):
        scratch = _events(lam[i], res[i], count[i], 1.0, law[i], flags, out[i], scratch)
    return out
