"""Apparent COR of one racket at many (position, speed) cases: the design studies' only impact call.

Every objective goes through :func:`apparent_cor`, so the impact engine behind it is chosen in one
place. In a linear model the COR at a given K_CB does not depend on the speed, so cases sharing a
position and K_CB share one solve.
"""

from __future__ import annotations

import numpy as np

from fem_racket.contact.linear import LinearContact
from fem_racket.frame.model import FrameModel
from fem_racket.impact.closed_form import exact_outcome
from fem_racket.impact.system import modal_system

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
        Impact points x/L and ball speeds relative to the racket [m/s], broadcast together.
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
    fm = model.modes(modes)
    out = np.empty(x.shape)
    seen: dict[tuple[float, float], float] = {}
    for idx in np.ndindex(x.shape):
        law = LinearContact.for_speed(float(v[idx]), zeta=zeta)
        key = (float(x[idx]), law.stiffness)
        if key not in seen:
            g = model.fe.point_vector(key[0] * model.mesh.length)
            system = modal_system(
                fm.all_omega,
                fm.all_shapes,
                g,
                ball_mass,
                law.stiffness,
                law.damping(ball_mass),
                1.0,
            )
            seen[key] = -exact_outcome(system).rebound_velocity
        out[idx] = seen[key]
    return out
