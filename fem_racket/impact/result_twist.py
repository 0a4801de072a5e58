"""What an off-axis impact leaves in torsion: roll rate, torsion energies, roll momentum.

The twist histories theta(x, t) of :class:`~fem_racket.impact.result.ImpactResult` (torsion
DOFs of :class:`~fem_racket.frame.torsion.TorsionModel`) give, with its K_t and M_t::

    roll rate       Omega = 1^T M_t theta' / I_p                  (the rigid roll [rad/s])
    energies        T_t = theta'^T M_t theta' / 2,  U_t = theta^T K_t theta / 2   [J]
    roll momentum   L_x = y m_B v_B + 1^T M_t theta'               [kg m^2/s]

``result`` is an off-axis :class:`~fem_racket.impact.result.ImpactResult` (which imports this
module where it needs it). L_x is the angular momentum of ball and frame about the long axis
(positive twist moves the face point at +y along the ball's travel); the contact force exerts
no net torque on the pair, so L_x stays at its initial value y m_B V_B0.
"""

from __future__ import annotations

from typing import Any

import numpy as np

__all__ = ["roll_momentum", "roll_rate", "torsion_energies", "twist_summary"]


def roll_rate(result: Any) -> np.ndarray:
    """The frame's rigid roll rate about its long axis at every output time [rad/s] (positive:
    the struck side moving along the ball's travel when the offset is positive)."""
    tors = result.model.torsion
    _, M = tors.matrices
    return (result.twist_rate @ (M @ np.ones(tors.ndof))) / tors.polar_moment


def torsion_energies(result: Any) -> dict[str, np.ndarray]:
    """Kinetic and strain energy of the frame's twist at every output time [J]."""
    K, M = result.model.torsion.matrices
    q, qd = result.twist, result.twist_rate
    return {
        "torsion_kinetic": 0.5 * np.einsum("ij,ij->i", qd, (M @ qd.T).T),
        "torsion_strain": 0.5 * np.einsum("ij,ij->i", q, (K @ q.T).T),
    }


def roll_momentum(result: Any) -> np.ndarray:
    """Angular momentum of ball and frame about the long axis [kg m^2/s] per output time."""
    tors = result.model.torsion
    _, M = tors.matrices
    ball = result.offset * result.ball.mass * result.ball_velocity
    return ball + result.twist_rate @ (M @ np.ones(tors.ndof))


def twist_summary(result: Any) -> dict[str, Any]:
    """``offset_m``, ``roll_rate_rad_s`` after the impact and ``torsion_energy_share``: the
    share of the ball's lost kinetic energy left in the frame's twist (roll and torsion
    vibration) at separation (NaN when the ball lost none)."""
    tors = result.model.torsion
    K, M = tors.matrices
    q, qd = result.twist[-1], result.twist_rate[-1]
    energy = 0.5 * (qd @ (M @ qd) + q @ (K @ q))
    v0 = result.impact.speed
    lost = 0.5 * result.ball.mass * (v0 * v0 - result.ball_velocity[-1] ** 2)
    return {
        "offset_m": result.offset,
        "roll_rate_rad_s": float(qd @ (M @ np.ones(tors.ndof))) / tors.polar_moment,
        "torsion_energy_share": float(energy / lost) if lost > 0.0 else float("nan"),
    }
