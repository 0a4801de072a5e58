"""A second, independent path through the tangential contact: fixed steps and a return map.

The spring and slider of :mod:`fem_racket.impact.tangential.march` are 1-D elastoplasticity
(the friction limit mu F(t) plays the yield force), so the classic elastic-predictor /
return-mapping step applies (Simo & Hughes 1998, *Computational Inelasticity*, ch. 1), here
inside a velocity-Verlet step of s' = F_t / m*::

    s_half = s_n + h F_t,n / (2 m*)
    F_trial = F_t,n - k_t h s_half;  F_t,n+1 = F_trial clipped to [-mu F_n+1, mu F_n+1]
    s_n+1 = s_half + h F_t,n+1 / (2 m*)

No switching times are searched for: the steps run over a uniform grid and a step slides when
its trial force is clipped. Second order away from the switches, first order across them.
Used by the tests to check the march; rigid tangential contacts (eta^2 = 0) are not stepped.
On the face (:func:`step_plane`, the vector contact of :mod:`fem_racket.impact.tangential.plane`)
the same step with s' = A f and the radial return: a trial force outside the disk
|f| <= mu F is scaled back onto its edge (Simo & Hughes 1998, section 2.3, isotropic yield).
"""

from __future__ import annotations

import numpy as np

from fem_racket.impact.tangential.march import TangentialContact
from fem_racket.impact.tangential.normal import NormalHistory
from fem_racket.impact.tangential.plane import PlaneContact

__all__ = ["step_plane", "step_tangential"]


def step_tangential(
    c: TangentialContact, normal: NormalHistory, slip: float, steps: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Step the tangential contact over [0, normal.end].

    Parameters
    ----------
    c : TangentialContact
        Compliant (finite k_t) contact.
    normal : NormalHistory
    slip : float
        Initial slip velocity s_0 [m/s]; the spring starts unstretched.
    steps : int
        Number of equal steps.

    Returns
    -------
    t, s, f : ndarray, shape (steps + 1,)
        Times [s], slip velocity [m/s] and tangential force on the ball [N].
    """
    t = np.linspace(0.0, normal.end, steps + 1)
    h = t[1] - t[0]
    limit = c.friction * np.maximum(normal.force(t), 0.0)
    s, f = np.empty_like(t), np.empty_like(t)
    s[0], f[0] = slip, 0.0
    half = 0.5 * h / c.effective_mass
    for n in range(steps):
        s_half = s[n] + half * f[n]
        f[n + 1] = np.clip(f[n] - c.stiffness * h * s_half, -limit[n + 1], limit[n + 1])
        s[n + 1] = s_half + half * f[n + 1]
    return t, s, f


def step_plane(
    c: PlaneContact, normal: NormalHistory, slip: np.ndarray, steps: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Step the vector contact over [0, normal.end] (as :func:`step_tangential`).

    Returns
    -------
    t : ndarray, shape (steps + 1,)
    s, f : ndarray, shape (steps + 1, 2)
        Slip velocity [m/s] and tangential force on the ball [N].
    """
    t = np.linspace(0.0, normal.end, steps + 1)
    h = t[1] - t[0]
    limit = c.friction * np.maximum(normal.force(t), 0.0)
    s, f = np.empty((t.size, 2)), np.empty((t.size, 2))
    s[0], f[0] = slip, 0.0
    half = 0.5 * h * c.compliance
    for n in range(steps):
        s_half = s[n] + half @ f[n]
        trial = f[n] - c.stiffness * h * s_half
        size = float(np.hypot(trial[0], trial[1]))
        f[n + 1] = trial if size <= limit[n + 1] else trial * (limit[n + 1] / size)
        s[n + 1] = s_half + half @ f[n + 1]
    return t, s, f
