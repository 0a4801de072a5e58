"""Which structure modes an impact keeps, and the residual pseudo-mode standing for the rest.

A mode far above the contact frequency omega_c = sqrt(K_CB (1/m_B + sum a_r^2)) (eq 11 of
Kawazoe & Kanda 1997, with the rigid modes' values a_r at the impact point) follows the contact
force quasi-statically. Each case keeps the flexible modes below beta x omega_c and replaces all
the others by one pseudo-mode with their static flexibility and their mass at the impact point::

    a_p^2 / omega_p^2 = sum_dropped a_f^2 / omega_f^2,     a_p^2 = sum_dropped a_f^2

so the structure's compliance at the impact point is exact at zero frequency and at infinite
frequency (where the dashpot acts at t = 0). Measured, the COR error falls as about
beta^-2.5 with the paper's separation criterion (10-100x below a plain truncation).
The factor beta comes from the COR tolerance the user asks for, through :data:`CALIBRATION`
(measured: the largest COR error over random frames, meshes, impact points, speeds, ball masses
and damping, with a safety factor). ``tolerance=None`` (or 0) keeps every mode given.

Modes not given at all (a fine mesh whose higher modes were never computed) enter through
their totals: ``residual_flexibility`` = sum of a^2/omega^2 and ``residual_mass`` = sum of a^2
over the missing modes, e.g. from static solves (see :mod:`fem_racket.impact.point`).
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np

from fem_racket.impact.constants import DEFAULT_TOLERANCE
from fem_racket.validation import InputError, show

__all__ = [
    "CALIBRATION",
    "DEFAULT_TOLERANCE",
    "check_tolerance",
    "contact_frequency",
    "cutoff_factor",
    "pole_blocks",
    "split_modes",
]

#: (COR tolerance, beta) per separation criterion, measured by scripts/calibrate_engine.py on
#: 30 random frames x 400 random impacts (zeta <= 0.2): the smallest beta of its grid whose
#: largest COR error is at most tolerance / 1.5. Log-log interpolation in between; below the
#: smallest tolerance every mode is kept. The force criterion needs far more modes, and below
#: ~2e-6 every mode: its event K_CB delta + C_CB delta' carries the high modes' ripple (its
#: error stayed at ~1.2e-6 up to beta = 512 on those cases). With it, heavily damped impacts
#: (zeta > 0.1) on very soft frames can even end at a brief dip of the force below zero made
#: by the highest FE modes, which only every mode (tolerance None) reproduces.
CALIBRATION: dict[str, tuple[tuple[float, float], ...]] = {
    "displacement": (
        (1e-3, 12.0),
        (1e-4, 12.0),
        (1e-5, 32.0),
        (1e-6, 64.0),
        (1e-7, 192.0),
        (1e-8, 384.0),
    ),
    "force": ((1e-3, 12.0), (1e-4, 32.0), (1e-5, 128.0), (2e-6, 384.0)),
}


def check_tolerance(tolerance: float | None) -> float | None:
    """The COR tolerance as a float in (0, 0.1], or None for every mode (None or 0)."""
    if tolerance is None:
        return None
    try:
        tol = float(tolerance)
    except (TypeError, ValueError):
        tol = math.nan
    if isinstance(tolerance, bool) or not math.isfinite(tol) or not 0.0 <= tol <= 0.1:
        raise InputError(
            f"tolerance = {show(tolerance)} is not allowed: must be a COR error in [0, 0.1] "
            "(0 or None: every mode)",
            parameter="tolerance",
            value=tolerance,
        )
    return None if tol == 0.0 else tol


def cutoff_factor(tolerance: float | None, separation: str = "displacement") -> float:
    """beta: modes below beta x omega_c are kept (inf for every mode)."""
    tol = check_tolerance(tolerance)
    if tol is None:
        return math.inf
    table = CALIBRATION[separation]
    tols = np.log([t for t, _ in table])[::-1]
    betas = np.log([b for _, b in table])[::-1]
    x = math.log(tol)
    if x < tols[0] - 1e-12:  # finer than calibrated: every mode
        return math.inf
    return float(math.exp(np.interp(x, tols, betas)))


def pole_blocks(
    omega: np.ndarray,
    values: np.ndarray,
    mu0: np.ndarray,
    omega_c: np.ndarray,
    beta: float,
    residual_flexibility: np.ndarray,
    residual_mass: np.ndarray,
) -> Iterator[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Poles and weights of the reduced cases, grouped by size.

    Parameters
    ----------
    omega : ndarray, shape (n, m)
        Flexible angular frequencies of each case, ascending [rad/s].
    values : ndarray, shape (n, m)
        Mass-normalised mode values at each case's impact point [1/sqrt(kg)].
    mu0 : ndarray, shape (n,)
        1/m_B + sum of the rigid modes' squared values [1/kg].
    omega_c : ndarray, shape (n,)
        Contact angular frequency of eq 11 [rad/s].
    beta : float
        Cut-off factor (inf: keep every mode given).
    residual_flexibility, residual_mass : ndarray, shape (n,)
        Sums of a^2/omega^2 [s^2/kg] and a^2 [1/kg] over modes not given.

    Yields
    ------
    rows, d, v
        Case indices and, per case, poles d = [0, omega_kept^2, omega_p^2] [rad^2/s^2] and
        weights v = [mu0, a_kept^2, a_p^2] [1/kg] (the pseudo-mode only where something is
        dropped).
    """
    n, m = omega.shape
    a2 = values * values
    w2 = omega * omega
    kept, pseudo_w2, pseudo_a2 = split_modes(
        omega, values, omega_c, beta, residual_flexibility, residual_mass
    )
    pseudo = pseudo_a2 > 0.0
    for size in np.unique(kept):
        for with_pseudo in (False, True):
            rows = np.flatnonzero((kept == size) & (pseudo == with_pseudo))
            if rows.size == 0:
                continue
            d_cols = [np.zeros((rows.size, 1)), w2[rows, :size]]
            v_cols = [mu0[rows, None], a2[rows, :size]]
            if with_pseudo:
                d_cols.append(pseudo_w2[rows, None])
                v_cols.append(pseudo_a2[rows, None])
            yield rows, np.concatenate(d_cols, axis=1), np.concatenate(v_cols, axis=1)


def contact_frequency(contact_time: np.ndarray, exponent: np.ndarray | float = 1.0) -> np.ndarray:
    """omega_c = sqrt(n) pi / t_c [rad/s], the frequency the cut-off beta multiplies.

    For the linear spring (n = 1) this is eq 11's sqrt(K_CB mu0). For a contact law, t_c is its
    estimated contact time on the impact point's rigid-body compliance
    (:meth:`fem_racket.contact.law.ContactLaw.contact_time_estimate`) and n its power-law
    exponent: near the peak a force k delta^n acts as a spring of tangent stiffness n F/delta,
    n times its secant stiffness, so its pulse is sharper and excites modes up to sqrt(n)
    higher (measured on the paper's racket: with pi / t_c alone a Hunt-Crossley law with
    n = 9 needs ~3x the linear law's beta for the same COR error; ``scripts/bench_laws.py``).
    """
    return np.sqrt(exponent) * np.pi / np.asarray(contact_time, dtype=float)


def split_modes(
    omega: np.ndarray,
    values: np.ndarray,
    omega_c: np.ndarray,
    beta: float,
    residual_flexibility: np.ndarray | float = 0.0,
    residual_mass: np.ndarray | float = 0.0,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The rule: per case, the flexible modes kept and the pseudo-mode standing for the rest.

    Parameters
    ----------
    omega : ndarray, shape (m,) or (n, m)
        Flexible angular frequencies, ascending [rad/s] (shared, or per case).
    values : ndarray, shape (n, m)
        Mass-normalised mode values at each case's impact point [1/sqrt(kg)].
    omega_c : ndarray, shape (n,)
        Contact angular frequency [rad/s] (:func:`contact_frequency`).
    beta : float
        Cut-off factor (inf: keep every mode given).
    residual_flexibility, residual_mass : ndarray, shape (n,), or float
        Sums of a^2/omega^2 [s^2/kg] and a^2 [1/kg] over modes not given.

    Returns
    -------
    kept : ndarray of int, shape (n,)
        The first ``kept`` modes of each case are kept (those below beta x omega_c).
    pseudo_w2, pseudo_a2 : ndarray, shape (n,)
        The pseudo-mode's omega_p^2 [rad^2/s^2] and a_p^2 [1/kg] (both 0 where nothing is
        dropped).
    """
    n = values.shape[0]
    omega = np.broadcast_to(omega, values.shape)
    a2 = values * values
    w2 = omega * omega
    kept = np.sum(omega < beta * np.asarray(omega_c, dtype=float)[:, None], axis=1)
    # Sums over the dropped tail j >= kept, from reversed cumulative sums (no cancellation).
    zero = np.zeros((n, 1))
    tail_f = np.concatenate([np.cumsum((a2 / w2)[:, ::-1], axis=1)[:, ::-1], zero], 1)
    tail_m = np.concatenate([np.cumsum(a2[:, ::-1], axis=1)[:, ::-1], zero], 1)
    r = np.arange(n)
    flex = tail_f[r, kept] + residual_flexibility
    mass = tail_m[r, kept] + residual_mass
    pseudo = (flex > 0.0) & (mass > 0.0)
    w2p = np.where(pseudo, mass / np.where(pseudo, flex, 1.0), 0.0)
    return kept, w2p, np.where(pseudo, mass, 0.0)
