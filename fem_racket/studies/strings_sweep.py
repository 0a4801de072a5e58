"""The string bed's tension and pattern as study axes: apparent COR and contact time.

For each pattern (mains x crosses) and tension per string, the ``kawazoe-1997-ball``
(:data:`fem_racket.contact.bed_ball.BALL_STIFFNESS`, :data:`~fem_racket.contact.bed_ball.BALL_ZETA`)
strikes the free strung racket at rest (:mod:`fem_racket.impact.strung`), solved exactly
(every mode): the sweep grid's ``string_tension`` and ``pattern`` axes
(:func:`fem_racket.studies.sweep.sweep_result`, as ``fem-racket sweep --string-tension ...
--pattern ...``) as a table. The bed's modes are computed once per pattern (a tension only
scales them, :mod:`fem_racket.strings.membrane`).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from fem_racket.studies.cases import COLUMNS as SWEEP_COLUMNS
from fem_racket.studies.cases import STRUNG_VARIABLES
from fem_racket.studies.grid_values import pattern_code
from fem_racket.studies.sweep import sweep_result

__all__ = ["COLUMNS", "tension_sweep"]

#: Sweep column of each variable.
COLUMN_OF = {name: k for k, name in enumerate(SWEEP_COLUMNS)}

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
) -> np.ndarray:
    """Rows of :data:`COLUMNS`, one per (pattern, tension), from the sweep grid.

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
    """
    r = sweep_result(
        string_tension=list(map(float, tensions)) if len(tensions) > 1 else float(tensions[0]),
        pattern=list(patterns) if len(patterns) > 1 else patterns[0],
        position=position,
        speed=speed,
        ball_mass=ball_mass,
        backend="serial",
    )
    cols = [COLUMN_OF[k] for k in ("cor", "contact_time_s", *STRUNG_VARIABLES)]
    found = {}
    for i in range(r.spec.size):
        case = r.spec.case(i)
        found[(int(case["pattern"]), case["string_tension"])] = r.values[i, cols]
    rows = []
    for pattern in patterns:
        code = pattern_code(pattern)
        for tension in tensions:
            rows.append((code // 100, code % 100, float(tension), *found[(code, float(tension))]))
    return np.array(rows, dtype=float)
