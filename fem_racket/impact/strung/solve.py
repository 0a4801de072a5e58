"""An :class:`~fem_racket.impact.problem.ImpactProblem` with a string bed, by a solver.

The strung racket (:mod:`.point`) is solved by the methods of
:func:`fem_racket.impact.strung.impact.strung_impact`: ``exact`` (the linear ball: the
``kawazoe-1997-ball`` or a :class:`~fem_racket.contact.linear.LinearContact`; every mode, no
options), ``general`` (any ball law; ``tolerance``) and ``cvode`` (any ball law; ``rtol``,
``atol``); ``auto`` picks ``exact`` for the linear ball and ``general`` otherwise. On the
linear ball, ``general`` stepped too coarsely (100-200 steps per contact: h omega_p >= 1 on the
bed's light pseudo-mode at ~46 kHz) cannot follow the bed's answer to the dashpot's jump
c V_B0 at contact and ends the contact at a false early zero (the kawazoe-1997-ball clamped at
20 m/s: 0.09-0.21 ms against 4.53 ms); its vouch (:mod:`fem_racket.impact.general.vouch`: a
contact shorter than a quarter of the estimate starts again on the time found, the steps
doubled until the COR converges) catches it, and the answer agrees with the exact one
(``tests/impact/strung/test_general_on_bed.py``).
The histories have a fixed number of samples over the contact, and every frame mode is used,
so the other options are refused in one line, as is ``bdf``.
"""

from __future__ import annotations

from typing import Any

from fem_racket.impact.settings import SolverOptions
from fem_racket.impact.strung.impact import StrungImpact, simulate_strung
from fem_racket.validation import InputError, show

__all__ = ["STRUNG_OPTIONS", "check_strung", "solve_strung"]

#: The solver options each method takes on the strung racket.
STRUNG_OPTIONS = {"exact": (), "general": ("tolerance",), "cvode": ("rtol", "atol")}


def check_strung(problem: Any, method: str, options: SolverOptions) -> None:
    """Refuse, in one line, what ``method`` with ``options`` cannot do on the strung
    ``problem``."""
    if method not in STRUNG_OPTIONS:
        raise InputError(
            f"solver = {method!r} is not allowed with a string bed: must be one of "
            f"{', '.join(STRUNG_OPTIONS)}"
        )
    law = problem.ball_law()
    if method == "exact" and law.name != "linear":
        raise InputError(
            f"solver = 'exact' is not allowed with a string bed and ball law {law.name!r}: it "
            "takes the linear ball; use 'general' or 'cvode'"
        )
    if problem.strings.stretch:
        if method != "cvode":
            raise InputError(
                f"solver = {method!r} is not allowed with the strings' stretch: the stretching "
                "bed is integrated by 'cvode'"
            )
        if law.state is not None:
            raise InputError(
                f"law = {law.name!r} is not allowed with the strings' stretch: it takes a ball "
                "law without an internal state (linear, hunt-crossley)"
            )
    for key, value in options.given().items():
        if key not in STRUNG_OPTIONS[method]:
            takes = ", ".join(STRUNG_OPTIONS[method]) or "none"
            raise InputError(
                f"{key} = {show(value)} is not allowed with a string bed and solver {method!r}: "
                f"it takes {takes} (every frame mode is used; the histories have their own "
                "samples)"
            )


def solve_strung(problem: Any, method: str, options: SolverOptions) -> StrungImpact:
    """The strung ``problem`` by ``method`` (checked by :func:`check_strung`)."""
    check_strung(problem, method, options)
    return simulate_strung(
        problem.model,
        problem.strings,
        position=problem.impact.position,
        offset=problem.offset,
        speed=problem.impact.speed,
        ball_mass=problem.ball.mass,
        law=problem.ball_law(),
        solver=method,
        **options.given(),
    )
