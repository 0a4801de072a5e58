"""Apparent COR of one racket at many (position, speed) cases: the design studies' only impact call.

Every objective goes through :func:`apparent_cor`, so the impact engine behind it is chosen in one
place: the batched engine (:func:`fem_racket.impact.engine.impacts`), all of a design's cases in
one call, its modes computed once per design.
"""

from __future__ import annotations

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.impact.engine import impacts

__all__ = ["apparent_cor"]


def apparent_cor(
    model: FrameModel,
    positions: np.ndarray,
    speeds: np.ndarray,
    *,
    ball_mass: float,
    zeta: float,
    modes: int | None,
    tolerance: float | None,
) -> np.ndarray:
    """e_A of the stationary free racket for each case.

    Parameters
    ----------
    model : FrameModel
    positions, speeds : ndarray
        Impact points x/L and closing speeds v_in + v_r [m/s] (they set K_CB), broadcast
        together.
    ball_mass : float
        m_B [kg].
    zeta : float
        Damping ratio of the ball/string law.
    modes : int or None
        Flexible modes kept (None: the engine's choice by ``tolerance``).
    tolerance : float or None
        COR tolerance of the engine (None: every mode).

    Returns
    -------
    ndarray
        e_A, shape of the broadcast inputs.
    """
    x, v = np.broadcast_arrays(np.asarray(positions, float), np.asarray(speeds, float))
    batch = impacts(
        model,
        position=x,
        speed=v,
        ball_mass=ball_mass,
        zeta=zeta,
        modes=modes,
        tolerance=tolerance,
    )
    return np.asarray(batch.cor).reshape(x.shape)
