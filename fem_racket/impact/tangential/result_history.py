"""The normal force history of an impact computed with output times: :func:`normal_history`
(a :class:`~fem_racket.impact.tangential.normal.SampledNormal` of the ball's momentum lost),
from any result that follows :class:`NormalResult` (the free racket's
:class:`~fem_racket.impact.result.ImpactResult`, the strung racket's
:class:`~fem_racket.impact.strung.result.StrungImpact`: this room imports neither)."""

from __future__ import annotations

from typing import Protocol

import numpy as np

from fem_racket.contact.linear import Ball
from fem_racket.impact.tangential.normal import SampledNormal
from fem_racket.validation import InputError

__all__ = ["NormalResult", "normal_history"]


class NormalResult(Protocol):
    """A normal impact computed with histories, as the tangential contact reads it.

    ``t`` output times [s]; ``ball`` (its mass); ``ball_velocity`` v_B at ``t`` [m/s] towards
    the racket; ``force`` the contact force at ``t`` [N]; ``compression_stiffness`` the normal
    stiffness k_n [N/m] of the tangential spring (the secant F / delta at the largest
    compression: K_CB for the paper's linear law); :meth:`normal_samples` the result whose
    samples drive the tangential contact.
    """

    @property
    def t(self) -> np.ndarray: ...

    @property
    def ball(self) -> Ball: ...

    @property
    def ball_velocity(self) -> np.ndarray: ...

    @property
    def force(self) -> np.ndarray: ...

    @property
    def compression_stiffness(self) -> float: ...

    def normal_samples(self) -> NormalResult:
        """This result, or the same solution at the output times the tangential contact needs
        (the strung racket's own samples serve its peaks and energies)."""


def normal_history(result: NormalResult) -> SampledNormal:
    """The normal force history of a computed impact (needs its output times): P = m_B (V_B0 -
    v_B) and F at the output times of ``result.normal_samples()``, k_n its
    ``compression_stiffness``."""
    source = result.normal_samples()
    if source.t.size < 5:
        raise InputError(
            f"an oblique impact needs the normal impact's histories: {source.t.size} output "
            "times given; simulate with an output_step"
        )
    v = source.ball_velocity
    impulse = source.ball.mass * (v[0] - v)
    return SampledNormal(source.t, impulse, source.force, source.compression_stiffness)
