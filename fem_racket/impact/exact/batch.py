"""The batch solve behind :func:`fem_racket.impacts`: poles -> roots -> COR, t_c, peak force.

Every case runs through the compiled case loop (:mod:`fem_racket.impact.exact.kernel_cases`,
numba, imported here only): its reduced poles (:func:`fem_racket.impact.reduction.pole_blocks`'s
rule), roots and residues (the Aberth iteration of :mod:`fem_racket.impact.exact.roots`),
separation time, impulse and peak force (:mod:`fem_racket.impact.exact.separation`), all per
unit impact speed and each case on its own, so a case gives the same bits alone or in any
batch. A case whose iteration fails its checks is solved by eigen-decomposition of its reduced
state matrix (:func:`fem_racket.impact.exact.roots.coupled_roots`'s fallback). A case whose
event function nearly touches zero before it separates (an ill-conditioned criterion: the
reduced model may cross there or not, the COR jumping with it) is solved again with every mode
given.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from fem_racket.impact.exact.roots import eigen_roots
from fem_racket.impact.reduction import pole_blocks

__all__ = ["Cases", "SolveOptions", "solve_cases"]


@dataclass(frozen=True, eq=False)
class Cases:
    """n impacts on structures given by their modes at the impact points.

    Attributes
    ----------
    omega, values : ndarray, shape (n, m)
        Each case's flexible angular frequencies (ascending) [rad/s] and mode values at its
        impact point [1/sqrt(kg)].
    rigid, flex, mass : ndarray, shape (n,)
        Rigid modes' summed squared values [1/kg]; flexibility [s^2/kg] and mass [1/kg] of
        the modes not given.
    k, c, mb : ndarray, shape (n,)
        K_CB [N/m], C_CB [N s/m], m_B [kg].
    """

    omega: np.ndarray
    values: np.ndarray
    rigid: np.ndarray
    flex: np.ndarray
    mass: np.ndarray
    k: np.ndarray
    c: np.ndarray
    mb: np.ndarray

    def take(self, rows: np.ndarray) -> Cases:
        """The cases ``rows``."""
        return Cases(*(getattr(self, f)[rows] for f in self.__dataclass_fields__))


@dataclass(frozen=True)
class SolveOptions:
    """How the cases are solved.

    Attributes
    ----------
    beta : float
        Cut-off factor: modes below beta x omega_c are kept (inf: every mode given).
    separation : {"displacement", "force"}
    peak_force : bool
        Compute the peak force (NaN otherwise).
    """

    beta: float
    separation: str = "displacement"
    peak_force: bool = False


def solve_cases(cases: Cases, options: SolveOptions) -> tuple[np.ndarray, ...]:
    """COR, t_c [s], peak force per unit speed [N s/m] and flexible modes kept of the cases."""
    from fem_racket.impact.kernel_cache import guard

    guard(Path(__file__).parent, ("kernel_roots", "kernel_events", "kernel_cases"))
    from fem_racket.impact.exact.kernel_cases import events_cases
    from fem_racket.impact.exact.kernel_cases import solve_cases as kernel

    mu0 = 1.0 / cases.mb + cases.rigid
    omega_c = np.sqrt(cases.k * mu0)
    law = np.column_stack(
        [mu0, omega_c, cases.flex, cases.mass, cases.k, cases.c, cases.mb]
    ).astype(float)
    flags = (options.separation == "force", bool(options.peak_force))
    out = kernel(
        np.ascontiguousarray(cases.omega, dtype=float),
        np.ascontiguousarray(cases.values, dtype=float),
        law,
        float(options.beta),
        flags,
    )
    failed = np.flatnonzero(out[:, 4] == 3)
    if failed.size:  # roots by eigen-decomposition, then the same events
        lam, res, count = _eigen_roots(cases.take(failed), mu0[failed], omega_c[failed], options)
        sub = events_cases(lam, res, count, law[failed], flags)
        out[failed, :3], out[failed, 4] = sub[:, :3], sub[:, 4]
    cor, tc, peak, kept = out[:, 0], out[:, 1], out[:, 2], out[:, 3].astype(int)
    # Near-touch before separation: whether the event crosses zero there may depend on the
    # modes dropped, so such a case is solved again with every mode given.
    again = np.flatnonzero(out[:, 4] == 1) if math.isfinite(options.beta) else []
    if len(again):
        every = SolveOptions(math.inf, options.separation, options.peak_force)
        cor[again], tc[again], peak[again], kept[again] = solve_cases(cases.take(again), every)
    return cor, tc, peak, kept


def _eigen_roots(cases: Cases, mu0, omega_c, options: SolveOptions):
    """Every root and residue of each case's reduced problem by eigen-decomposition, padded
    (n, 2 R_max), and how many each case has."""
    blocks = list(
        pole_blocks(cases.omega, cases.values, mu0, omega_c, options.beta, cases.flex, cases.mass)
    )
    width = 2 * max(d.shape[1] for _, d, _ in blocks)
    n = cases.k.size
    lam = np.ones((n, width), complex)
    res = np.zeros((n, width), complex)
    count = np.zeros(n, dtype=np.int64)
    for rows, d, v in blocks:
        for row, i in enumerate(rows):
            L, Z = eigen_roots(d[row], v[row], float(cases.k[i]), float(cases.c[i]))
            lam[i, : L.size], res[i, : L.size], count[i] = L, Z, L.size
    return lam, res, count
