"""The outcome of a :class:`~fem_racket.impact.problem_batch.ProblemBatch`: arrays of one value
per case (:class:`BatchOutcome`)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["BatchOutcome"]


@dataclass(frozen=True, eq=False)
class BatchOutcome:
    """The outcome of a :class:`~fem_racket.impact.problem_batch.ProblemBatch`, one value per
    case (NaN where a case failed).

    Attributes
    ----------
    cor : ndarray
        Apparent COR e_A = (v_out - v_r) / (v_in + v_r) (the paper's COR at rest).
    contact_time : ndarray
        t_c [s].
    ball_speed_out : ndarray
        Ball speed after impact away from the racket, v_out [m/s].
    peak_force : ndarray
        Largest contact force [N] (NaN unless the batch asked for it).
    kcb : ndarray
        K_CB used [N/m] (NaN under another law).
    racket_speed : ndarray
        v_r [m/s].
    modes : ndarray
        Flexible modes kept (NaN for the physical basis).
    extra : dict of str to ndarray
        Outputs of the string bed (``stringbed_stiffness_n_m``, ``stringbed_frequency_hz``) or
        of the oblique impact (``ball_speed_out_m_s``, ``angle_out_deg``, ``spin_out_rpm``,
        ``tangential_cor``, ``contact_regime`` as strings) or of the racket held in a hand
        (``grip_vibration_rms_n``, and ``peak_grip_force_n``: NaN unless the batch asked for the
        peaks; :mod:`fem_racket.impact.held.shock`); empty otherwise. With an incidence the
        fields above are the normal impact's (at V cos(angle)).
    """

    cor: np.ndarray
    contact_time: np.ndarray
    ball_speed_out: np.ndarray
    peak_force: np.ndarray
    kcb: np.ndarray
    racket_speed: np.ndarray
    modes: np.ndarray
    extra: dict = field(default_factory=dict)

    def columns(self) -> np.ndarray:
        """The fields as columns, shape (cases, 7), in the order of the attributes."""
        return np.column_stack(
            [
                self.cor,
                self.contact_time,
                self.ball_speed_out,
                self.peak_force,
                self.kcb,
                self.racket_speed,
                self.modes,
            ]
        )
