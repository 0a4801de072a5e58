"""A swing checked at the impact points of a study before any work, by the library's own check of
one impact (:func:`fem_racket.impact.problem_checks.check_swing`, run when an
:class:`~fem_racket.impact.problem.ImpactProblem` is made), as ``simulate`` checks its one point.

The ball and strings must close at every point and, where K_CB follows from the closing speed
(the paper's law without kcb), within the speeds the paper gives K_CB for
(:data:`~fem_racket.contact.constants.KCB_SPEED_RANGE`): the closing speed v_in + v_r(x) of a
rigid swing is linear in x, so the slowest and the fastest point of the grid bind. Refused naming
the racket's speed at that impact point, as the library names it; not at the swing's reference
point, which need not be struck.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from fem_racket.studies.map_options import MapPlay, map_grid

__all__ = ["check_swing_at", "check_swing_points"]


def check_swing_points(
    frame: Any,
    play: MapPlay,
    contact: Mapping[str, Any] | None = None,
    points: Sequence[float] = (),
) -> None:
    """Refuse, before any work, the swing of ``play`` (ball speed [m/s], swing) on ``frame``
    (a FrameMesh or FrameModel) where the library refuses it at one of the impact points of
    the map's grid (``play.positions`` [x/L]) or of ``points`` [x/L] (compare's single
    impact): at the slowest and the fastest of them (:func:`check_swing_at`)."""
    if play.racket_speed == 0.0:
        return  # at rest: the ball's speed alone, checked with the play
    x = np.concatenate([map_grid(play.positions), np.asarray(points, dtype=float)])
    check_swing_at(frame, play.speed, play.swing(_length(frame)), x, contact)


def check_swing_at(
    frame: Any,
    speed: float,
    swing: Any,
    positions: Any,
    contact: Mapping[str, Any] | None = None,
) -> None:
    """Refuse ``swing`` (a Swing) with a ball at ``speed`` [m/s] on ``frame`` (a FrameMesh or
    FrameModel) where the library refuses it at one of ``positions`` [x/L]: at the slowest and
    the fastest of them. ``contact``: the ball's mass and the ball/string law, as
    :meth:`ImpactProblem.build` takes them (default: the paper's law and ball)."""
    from fem_racket.impact.problem import ImpactProblem

    x = np.asarray(positions, dtype=float)
    v_r = swing.speed_at(x * _length(frame))
    if not np.any(v_r):
        return  # at rest: the ball's speed alone, checked by the study
    for k in sorted({int(np.argmin(v_r)), int(np.argmax(v_r))}):
        ImpactProblem.build(
            frame, position=float(x[k]), speed=speed, swing=swing, **dict(contact or {})
        )


def _length(frame: Any) -> float:
    """The racket's length [m] of a FrameMesh or FrameModel."""
    from fem_racket.frame.model import FrameModel

    return float((frame.mesh if isinstance(frame, FrameModel) else frame).length)
