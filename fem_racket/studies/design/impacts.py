"""Impacts of one racket at many (position, speed) cases: the design studies' only impact calls.

Every objective goes through :func:`apparent_cor` or :func:`handle_shock`, so the impact engines
behind them are chosen in one place: the batched engine
(:func:`fem_racket.impact.exact.engine.impacts`),
all of a design's cases in one call, its modes computed once per design; and for the hand-held
racket the exact modal path (:mod:`fem_racket.impact.held.modal`), the modes of frame + hand
computed once per design.
"""

from __future__ import annotations

import numpy as np

from fem_racket.frame.hand import Hand
from fem_racket.frame.model import FrameModel
from fem_racket.impact.exact.engine import EngineOptions, impacts
from fem_racket.impact.held.basis import held_basis
from fem_racket.impact.held.modal import held_contacts
from fem_racket.impact.held.shock import grip_peak, vibration_rms

__all__ = ["apparent_cor", "handle_shock"]


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
        options=EngineOptions(tolerance=tolerance, modes=modes),
    )
    return np.asarray(batch.cor).reshape(x.shape)


def handle_shock(
    model: FrameModel,
    positions: np.ndarray,
    speeds: np.ndarray,
    *,
    hand: Hand,
    window: float,
    ball_mass: float,
    zeta: float,
    tolerance: float | None,
    peak: bool = True,
) -> tuple[np.ndarray, np.ndarray | None]:
    """Vibration RMS and peak of the grip force [N] of the racket held by ``hand``, each case.

    Parameters
    ----------
    model : FrameModel
    positions, speeds : ndarray
        Impact points x/L and closing speeds [m/s] (a swing is a rigid motion of racket and
        hand superposed on the stationary impact at the closing speed), broadcast together.
    hand : Hand
    window : float
        Window of the shock measures [s] (:mod:`fem_racket.impact.held.shock`).
    ball_mass, zeta, tolerance
        As for :func:`apparent_cor`.
    peak : bool
        Compute the peaks too (about half again the cost).

    Returns
    -------
    rms, peak : ndarray
        Shape of the broadcast inputs (peak None unless asked for).
    """
    x, v = np.broadcast_arrays(np.asarray(positions, float), np.asarray(speeds, float))
    basis = held_basis(model.fe, hand)
    cases = held_contacts(
        basis, x.ravel(), v.ravel(), ball_mass=ball_mass, zeta=zeta, tolerance=tolerance
    )
    rms = np.array([vibration_rms(c, window) for c in cases]).reshape(x.shape)
    if not peak:
        return rms, None
    return rms, np.array([grip_peak(c, window) for c in cases]).reshape(x.shape)
