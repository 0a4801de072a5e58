"""Apparent COR of one racket at many (position, speed) cases: the design studies' only impact call.

Every objective goes through :func:`apparent_cor`, so the impact engine behind it is chosen in one
place: today :func:`fem_racket.studies.racket_map.apparent_cor_along` (the map's kernel).
"""

from __future__ import annotations

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.studies.racket_map import apparent_cor_along

__all__ = ["apparent_cor"]


def apparent_cor(
    model: FrameModel,
    positions: np.ndarray,
    speeds: np.ndarray,
    *,
    ball_mass: float,
    zeta: float,
    modes: int | None,
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
        Flexible modes kept (None: all).

    Returns
    -------
    ndarray
        e_A, shape of the broadcast inputs.
    """
    x, v = np.broadcast_arrays(np.asarray(positions, float), np.asarray(speeds, float))
    e = apparent_cor_along(model, x.ravel(), v.ravel(), ball_mass=ball_mass, zeta=zeta, modes=modes)
    return e.reshape(x.shape)
