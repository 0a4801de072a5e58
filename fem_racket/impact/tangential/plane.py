"""The tangential contact in the plane of the face: :func:`march_plane`, friction on the slip
vector.

The 1-D contact of :mod:`fem_racket.impact.tangential.march` in two dimensions (x along the
long axis, y across the face). The slip s of the ball's contact point relative to the strings
and the tangential force f on the ball are vectors; the contact point accelerates as::

    s' = A f,   A = (beta_t / m) 1 + C_r

(C_r: the racket's tangential compliance at the impact point, 2x2, symmetric; zero for a
clamped head; :meth:`fem_racket.impact.tangential.oblique.BallMotion.racket_compliance`).
Stronge's tangential spring acts in both directions (k_t = k_n / eta^2, isotropic, stretch u,
f = -k_t u) in series with a Coulomb slider on the vector: while the ball grips, u' = s, and it
slides when |f| reaches mu F, the slider then moving along u (the friction force opposes its
velocity), so |u| = mu F / k_t while u turns toward s: ``rho d' = s - (s.d) d`` (rho = |u|,
d = u / |u|); it grips again when the slider stops, ``s.d = rho'``.

When the motion stays on one line the vector problem is the 1-D one along it, solved in closed
form by :func:`~fem_racket.impact.tangential.march.march`: the slip starts along an eigenvector
of A (always for a clamped head, where A is a multiple of 1; and when nothing crosses the face:
then it is today's march bit for bit). Otherwise the slip turns, and
:mod:`fem_racket.impact.tangential.plane_ode` marches the vector problem (grips in closed form,
slides by an ODE).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fem_racket.impact.tangential.march import TangentialSolution, march
from fem_racket.impact.tangential.normal import NormalHistory
from fem_racket.impact.tangential.plane_ode import PlaneContact, march_vector

__all__ = ["LineSolution", "PlaneContact", "march_plane"]


@dataclass(frozen=True, eq=False)
class LineSolution:
    """The vector contact that stays on one line: the 1-D ``line`` solution along the unit
    ``direction``."""

    line: TangentialSolution
    direction: np.ndarray
    contact: PlaneContact

    @property
    def normal(self) -> NormalHistory:
        return self.line.normal

    def at(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Slip velocity [m/s] and tangential force on the ball [N] at times ``t`` [s], shape
        (len(t), 2)."""
        s, f = self.line.at(t)
        return s[:, None] * self.direction, f[:, None] * self.direction

    @property
    def slip_in(self) -> np.ndarray:
        return self.line.phases[0].slip * self.direction

    @property
    def final_slip(self) -> np.ndarray:
        return self.line.final_slip * self.direction

    @property
    def impulse(self) -> np.ndarray:
        """Tangential impulse on the ball [N s], (along, across)."""
        return self.line.impulse * self.direction

    @property
    def regime(self) -> str:
        return self.line.regime

    @property
    def grip_intervals(self) -> list[tuple[float, float]]:
        return self.line.grip_intervals

    @property
    def reversal_times(self) -> list[float]:
        return self.line.reversal_times


def line_direction(c: PlaneContact, slip: np.ndarray) -> np.ndarray | None:
    """The unit direction of a slip that stays on one line (an eigenvector of A), or None.

    Along x (or y) exactly when nothing crosses (A diagonal): the 1-D march then takes the
    signed slip component unchanged.
    """
    a = c.compliance
    diagonal = a[0, 1] == 0.0 and a[1, 0] == 0.0
    if slip[1] == 0.0 and (diagonal or slip[0] == 0.0):
        return np.array([1.0, 0.0])
    if slip[0] == 0.0 and diagonal:
        return np.array([0.0, 1.0])
    if diagonal and a[0, 0] == a[1, 1]:
        return slip / math.hypot(slip[0], slip[1])
    return None


def march_plane(c: PlaneContact, normal: NormalHistory, slip: np.ndarray, *, line: bool = True):
    """March the tangential contact on the face from slip velocity ``slip`` [m/s] (along,
    across) and an unstretched spring.

    Parameters
    ----------
    c : PlaneContact
    normal : NormalHistory
    slip : array_like, shape (2,)
    line : bool
        Use the 1-D closed form when the slip stays on one line (default); False marches the
        vector problem whatever it is (the tests compare the two).

    Returns
    -------
    LineSolution or fem_racket.impact.tangential.plane_ode.PlaneSolution
    """
    s0 = np.asarray(slip, dtype=float)
    e = line_direction(c, s0) if line else None
    if e is not None:
        return LineSolution(march(c.line(e), normal, float(s0 @ e)), e, c)
    return march_vector(c, normal, s0)
