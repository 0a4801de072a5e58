"""The outcomes of a batch of impacts: :class:`ImpactBatch` (arrays of COR, contact time, ...)
and how the engine's per-unit-speed results become one (:func:`to_batch`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.impact.exact.inputs import EngineOptions, Laws
from fem_racket.impact.reduction import check_tolerance

__all__ = ["ImpactBatch", "to_batch"]


@dataclass(frozen=True, eq=False)
class ImpactBatch:
    """Outcomes of many impacts, one entry per case (arrays of the broadcast shape).

    Attributes
    ----------
    cor : ndarray
        Coefficient of restitution -v_B(t_c)/V_B0 (NaN: no separation).
    contact_time : ndarray
        t_c [s].
    rebound_speed : ndarray
        -v_B(t_c) [m/s].
    peak_force : ndarray or None
        Largest contact force [N], only when asked.
    kcb, zeta : ndarray
        K_CB [N/m] and damping ratio used.
    modes : ndarray of int
        Flexible modes kept per case (besides the residual pseudo-mode).
    tolerance : float or None
        The COR tolerance asked for (None: every mode).
    """

    cor: np.ndarray
    contact_time: np.ndarray
    rebound_speed: np.ndarray
    peak_force: np.ndarray | None
    kcb: np.ndarray
    zeta: np.ndarray
    modes: np.ndarray
    tolerance: float | None


def to_batch(results: tuple, laws: Laws, options: EngineOptions, shape: tuple) -> ImpactBatch:
    """The :class:`ImpactBatch` of flat ``results`` (COR, t_c, peak per unit speed, kept)."""
    cor, tc, peak, kept = results
    return ImpactBatch(
        cor=cor.reshape(shape),
        contact_time=tc.reshape(shape),
        rebound_speed=(cor * laws.speed).reshape(shape),
        peak_force=(peak * laws.speed).reshape(shape) if options.peak_force else None,
        kcb=laws.k.reshape(shape),
        zeta=laws.zeta.reshape(shape),
        modes=kept.reshape(shape),
        tolerance=check_tolerance(options.tolerance),
    )
