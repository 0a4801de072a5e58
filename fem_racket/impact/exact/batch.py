"""The batch solve behind :func:`fem_racket.impacts`: poles -> roots -> COR, t_c, peak force.

Cases are grouped by the size of their reduced problem (:func:`.reduction.pole_blocks`) and
solved :data:`BLOCK` at a time: roots and residues (:mod:`fem_racket.impact.exact.roots`),
separation time, impulse and peak force (:mod:`fem_racket.impact.exact.separation`), all per unit
impact speed. A case whose
event function
nearly touches zero before it separates (an ill-conditioned criterion: the reduced model may
cross there or not, the COR jumping with it) is solved again with every mode given.
"""

from __future__ import annotations

import math

import numpy as np

from fem_racket.impact.exact.roots import RootSet, coupled_roots
from fem_racket.impact.exact.separation import impulse, peak_force, separation_time
from fem_racket.impact.reduction import pole_blocks

__all__ = ["BLOCK", "T_MAX_FACTOR", "solve_cases"]

#: Cases solved together (bounded memory; small arrays stay in cache).
BLOCK = 512
#: Give up on separation after this many eq-11 contact times.
T_MAX_FACTOR = 20.0


def solve_cases(omega, values, rigid, flex, mass, k, c, mb, beta, separation, want_peak):
    """COR, t_c [s], peak force per unit speed [N s/m] and flexible modes kept of n cases.

    Parameters
    ----------
    omega, values : ndarray, shape (n, m)
        Each case's flexible angular frequencies (ascending) [rad/s] and mode values at its
        impact point [1/sqrt(kg)].
    rigid, flex, mass : ndarray, shape (n,)
        Rigid modes' summed squared values [1/kg]; flexibility [s^2/kg] and mass [1/kg] of
        the modes not given.
    k, c, mb : ndarray, shape (n,)
        K_CB [N/m], C_CB [N s/m], m_B [kg].
    beta : float
        Cut-off factor (inf: every mode given).
    separation : {"displacement", "force"}
    want_peak : bool
        Compute the peak force (NaN otherwise).
    """
    n = omega.shape[0]
    mu0 = 1.0 / mb + rigid
    omega_c = np.sqrt(k * mu0)
    cor, tc = np.full(n, np.nan), np.full(n, np.nan)
    peak = np.full(n, np.nan)
    kept = np.zeros(n, dtype=int)
    touch = np.zeros(n, dtype=bool)
    for rows, d, v in pole_blocks(omega, values, mu0, omega_c, beta, flex, mass):
        kept[rows] = np.sum(omega[rows] < beta * omega_c[rows, None], axis=1)
        for start in range(0, rows.size, BLOCK):
            sub, sl = rows[start : start + BLOCK], slice(start, start + BLOCK)
            for part, roots in coupled_roots(d[sl], v[sl], k[sub], c[sub]):
                if part.size:
                    idx = sub[part]
                    cor[idx], tc[idx], peak[idx], touch[idx] = _outcome(
                        roots, k[idx], c[idx], mb[idx], omega_c[idx], separation, want_peak
                    )
    # Near-touch before separation: whether the event crosses zero there may depend on the
    # modes dropped, so such a case is solved again with every mode given.
    again = np.flatnonzero(touch) if math.isfinite(beta) else np.empty(0, dtype=int)
    if again.size:
        sub = solve_cases(
            omega[again],
            values[again],
            rigid[again],
            flex[again],
            mass[again],
            k[again],
            c[again],
            mb[again],
            math.inf,
            separation,
            want_peak,
        )
        cor[again], tc[again], peak[again], kept[again] = sub
    return cor, tc, peak, kept


def _outcome(roots: RootSet, k, c, mb, omega_c, separation, want_peak):
    fw = (k[:, None] + c[:, None] * roots.lam) * roots.res
    w = roots.res if separation == "displacement" else fw
    t_est = np.pi / omega_c
    t, touch = separation_time(roots, w, t_est, T_MAX_FACTOR * t_est)
    ok = np.isfinite(t)
    cor, peak = np.full(t.size, np.nan), np.full(t.size, np.nan)
    if ok.any():
        sub = RootSet(roots.lam[ok], roots.res[ok], roots.mult)
        cor[ok] = impulse(sub, fw[ok], t[ok]) / mb[ok] - 1.0
        if want_peak:
            peak[ok] = peak_force(sub, fw[ok], t[ok])[0]
    return cor, t, peak, touch
