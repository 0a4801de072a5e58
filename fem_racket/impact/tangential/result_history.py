"""The normal force history of an impact computed with output times: :func:`normal_history`
(a :class:`~fem_racket.impact.tangential.normal.SampledNormal` of the ball's momentum lost)."""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.impact.tangential.normal import SampledNormal
from fem_racket.validation import InputError

__all__ = ["normal_history"]


def normal_history(result: Any) -> SampledNormal:
    """The normal force history of a computed impact (needs its output times).

    The stiffness k_n is K_CB for the paper's linear law; else the result's
    ``compression_stiffness`` when it has one (the strung racket's: the secant F / delta at the
    largest compression, located between the output times), else the secant at the output
    time of largest compression.
    """
    if result.t.size < 5:
        raise InputError(
            f"an oblique impact needs the normal impact's histories: {result.t.size} output "
            "times given; simulate with an output_step"
        )
    v = result.ball_velocity
    impulse = result.ball.mass * (v[0] - v)
    force = result.force
    if result.contact is not None:
        k_n = result.contact.stiffness
    elif hasattr(result, "compression_stiffness"):
        k_n = result.compression_stiffness
    else:
        i = int(np.argmax(result.deflection))
        k_n = float(force[i] / result.deflection[i])
    return SampledNormal(result.t, impulse, force, k_n)
