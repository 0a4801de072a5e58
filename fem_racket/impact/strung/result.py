"""The outcome of one impact on the strung racket (:func:`fem_racket.impact.strung.impact.
strung_impact`): results, histories and the energy bookkeeping's totals.

Every coordinate x of the strung racket's modal structure stores ``(x'^2 + omega^2 x^2) / 2``
(the bed's coordinates the bed's energy relative to its edge, plus the strings' stretch
potential when they stretch)::

    ball's loss          m_B (V_B0^2 - v_B(t_c)^2) / 2    (= the work of the contact force on it)
    energy to the racket E_frame(t_c) + E_bed(t_c)
    lost in the ball     ball's loss - energy to the racket (the law's dissipation)
    returned by the bed  max_t E_bed(t) - E_bed(t_c)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball
from fem_racket.frame.model import FrameModel
from fem_racket.impact.result_peak import peak_secant
from fem_racket.impact.strung.point import StrungPoint

__all__ = ["StrungImpact"]


@dataclass(frozen=True, eq=False)
class StrungImpact:
    """An impact on the strung racket: results and histories (see the module docstring).

    Attributes
    ----------
    cor : float
        Apparent COR -v_B(t_c)/V_B0.
    contact_time : float
        t_c [s].
    peak_force : float
        Largest contact force [N].
    t, ball_deflection, bed_deflection, force : ndarray
        Times [s], the ball's compression (the law's deflection) [m], the bed's deflection at the
        point relative to its edge [m] and the contact force [N].
    ball_loss, racket_energy, bed_energy_left, bed_peak_energy : float
        Energies [J] of the module docstring.
    frame_momentum : float
        Linear momentum of the frame at t_c [kg m/s] (its rigid translation).
    point : StrungPoint
        The structure used.
    law : ContactLaw
        The ball's law.
    speed, ball_mass : float
        V_B0 [m/s] and m_B [kg].
    solver : str
        The integrator that ran.
    coordinates : ndarray, shape (nt, 1 + n)
        u_B [m] and the structure's coordinates (:attr:`StrungPoint.omega` order) at ``t``.
    rates : ndarray, shape (nt, 1 + n)
        Their time derivatives (u_B' [m/s] first).
    law_state : ndarray or None
        The ball law's state at ``t`` [m] (None for a law without one).
    resampled : callable
        The same solution at the oblique impact's output times (:meth:`normal_samples`).
    model : FrameModel or None
        The frame (:func:`simulate_strung` sets it).

    The attributes an oblique impact reads of its normal impact
    (:func:`fem_racket.impact.oblique.solve.free_normal`) are those of an
    :class:`~fem_racket.impact.result.ImpactResult`: ``ball``, ``ball_velocity``,
    ``ball_speed_out``, ``x_impact``, ``offset``, ``model``, ``t``, :meth:`summary`, and
    those of the tangential contact's
    :class:`~fem_racket.impact.tangential.result_history.NormalResult`: ``force``,
    :attr:`compression_stiffness` (the ball law's secant at its largest compression: no
    lumped K_CB) and :meth:`normal_samples`.
    """

    cor: float
    contact_time: float
    peak_force: float
    t: np.ndarray
    ball_deflection: np.ndarray
    bed_deflection: np.ndarray
    force: np.ndarray
    ball_loss: float
    racket_energy: float
    bed_energy_left: float
    bed_peak_energy: float
    frame_momentum: float
    point: StrungPoint
    law: ContactLaw
    speed: float
    ball_mass: float
    solver: str
    coordinates: np.ndarray
    rates: np.ndarray
    law_state: np.ndarray | None
    resampled: Callable[[], StrungImpact] = field(repr=False)
    model: FrameModel | None = None

    @property
    def ball(self) -> Ball:
        """The ball (its mass)."""
        return Ball(self.ball_mass)

    @property
    def ball_velocity(self) -> np.ndarray:
        """u_B' at ``t`` [m/s] (towards the racket)."""
        return self.rates[:, 0]

    @property
    def ball_speed_out(self) -> float:
        """The ball's speed away from the racket after impact [m/s]."""
        return -float(self.rates[-1, 0])

    @property
    def deflection(self) -> np.ndarray:
        """The ball law's deflection (the ball's compression) at ``t`` [m]."""
        return self.ball_deflection

    @property
    def compression_stiffness(self) -> float:
        """The ball law's secant stiffness F / delta at its largest compression [N/m]: the
        normal stiffness k_n of an oblique impact's tangential contact, located between the
        output times (:func:`~fem_racket.impact.result_peak.peak_secant`; delta' is u_B' minus
        the bed's rate at the point). For the kawazoe-1997-ball (F = K delta + C delta') it is
        K = 137 357.79 N/m at any sample count; the secant at the output time of largest
        compression instead moved by 4e-4 relative with the number of samples (the dashpot's
        C delta' at up to half a step from the peak: 137 310, 137 388 and 137 349 N/m at 801,
        6 401 and 12 801 samples), and the outgoing spin of a strung oblique impact with it
        (by 1.2e-4 between 3 201 and 6 401 samples).
        """
        rate = self.rates[:, 0] - self.rates[:, 1:] @ self.point.a
        return peak_secant(self.t, self.ball_deflection, rate, self.law, self.law_state)

    def normal_samples(self) -> StrungImpact:
        """The same solution at :data:`~fem_racket.impact.strung.impact.OBLIQUE_SAMPLES` output
        times: the normal force history an oblique impact's tangential contact marches over
        (the result's own samples serve its peaks and energies)."""
        return replace(self.resampled(), model=self.model)

    @property
    def x_impact(self) -> float:
        """The impact point's distance from the grip end x_i [m] (``model`` must be set)."""
        return self.point.position * self.model.mesh.length

    @property
    def offset(self) -> float:
        """The impact point's lateral offset from the long axis y [m]."""
        return self.point.lateral_m

    def summary(self) -> dict[str, Any]:
        """The results, the bed and what the run used, JSON-ready, units in the keys."""
        return {
            "cor": self.cor,
            "contact_time_s": self.contact_time,
            "rebound_speed_m_s": self.cor * self.speed,
            "peak_force_n": self.peak_force,
            "position_x_over_l": self.point.position,
            "speed_m_s": self.speed,
            "ball_mass_kg": self.ball_mass,
            "solver": self.solver,
            **self.law.describe(),
            **self.point.describe(),
            "peak_bed_deflection_m": float(np.max(self.bed_deflection)),
            "peak_ball_deflection_m": float(np.max(self.ball_deflection)),
            "ball_energy_loss_j": self.ball_loss,
            "energy_lost_in_ball_j": self.ball_loss - self.racket_energy,
            "bed_energy_returned_j": self.bed_peak_energy - self.bed_energy_left,
            "bed_energy_left_j": self.bed_energy_left,
            "roll_rate_rad_s": self.roll_rate,
        }

    @property
    def roll_rate(self) -> float:
        """The racket's rigid roll rate about its long axis after impact [rad/s] (0 on the
        axis): the roll coordinate's rate times its value per unit offset, 1/sqrt(I_p)."""
        p = self.point
        if p.rigid_count < 3:
            return 0.0
        return float(self.rates[-1, 3] * p.a[2] / p.lateral_m)
