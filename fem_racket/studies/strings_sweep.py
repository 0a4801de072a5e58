"""The string bed's tension and pattern as study axes: apparent COR and contact time.

For each pattern (mains x crosses) and tension per string, the ``kawazoe-1997-ball``
(:data:`fem_racket.impact.strung.BALL_STIFFNESS`, :data:`~fem_racket.impact.strung.BALL_ZETA`)
strikes the free strung racket at rest (:mod:`fem_racket.impact.strung`), solved by the exact
engine (every mode). The bed's modes are computed once per pattern (a tension only scales them,
:mod:`fem_racket.strings.membrane`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.impact.strung import BALL_STIFFNESS, BALL_ZETA, strung_point
from fem_racket.impact.strung_impact import strung_engine
from fem_racket.strings.bed import StringBed, parse_pattern
from fem_racket.validation import check_positive

__all__ = ["COLUMNS", "tension_sweep"]

#: Columns of :func:`tension_sweep`'s rows (units in the names).
COLUMNS = (
    "mains [-]",
    "crosses [-]",
    "tension [N]",
    "cor [-]",
    "contact time [s]",
    "stringbed stiffness [N/m]",
    "first bed frequency [Hz]",
)


def tension_sweep(
    tensions: Sequence[float],
    patterns: Sequence[str],
    *,
    position: float = 0.74,
    speed: float = 30.0,
    ball_mass: float = 0.057,
    model: FrameModel | None = None,
    bed: StringBed | None = None,
) -> np.ndarray:
    """Rows of :data:`COLUMNS`, one per (pattern, tension).

    Parameters
    ----------
    tensions : sequence of float
        Tensions per string [N].
    patterns : sequence of str
        ``"16x19"``-style patterns.
    position : float
        Impact point x/L (on the head's axis).
    speed : float
        Ball speed [m/s].
    ball_mass : float
        m_B [kg].
    model : FrameModel, optional
        The racket (the paper's standard one, 20 elements, when None).
    bed : StringBed, optional
        Head size, string and load radius (its tension and pattern are replaced).
    """
    check_positive("speed", speed, "m/s")
    model = FrameModel.build(None, 20) if model is None else model
    base = StringBed() if bed is None else bed
    rows = []
    for pattern in patterns:
        mains, crosses = parse_pattern(pattern)
        for tension in tensions:
            b = replace(base, tension_n=float(tension), mains=mains, crosses=crosses)
            point = strung_point(model, b, position)
            out = strung_engine(point, BALL_STIFFNESS, BALL_ZETA, ball_mass, speed, tolerance=None)
            rows.append(
                (
                    mains,
                    crosses,
                    float(tension),
                    float(out.cor),
                    float(out.contact_time),
                    point.bed_stiffness,
                    float(point.bed_frequencies_hz[0]),
                )
            )
    return np.array(rows, dtype=float)
