"""How an impact is solved: the options a solver binds when it is made (:class:`SolverOptions`).

Every option has one meaning across the solvers that take it; a solver refuses, in one line,
an option it does not use (:mod:`fem_racket.impact.solvers`). An option left out takes the
solver's default (:data:`DEFAULTS`), so "given" and "default" can be told apart.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

from fem_racket.frame.constants import DEFAULT_MODES
from fem_racket.impact.constants import BASES, DEFAULT_TOLERANCE
from fem_racket.impact.reduction import check_tolerance
from fem_racket.impact.system import MAX_OUTPUT_TIMES
from fem_racket.validation import InputError, check_choice, check_integer, check_positive, show

__all__ = ["BASES", "DEFAULTS", "UNSET", "Settings", "SolverOptions", "check_time_limit"]


class _Unset:
    """An option left out (its solver's default applies)."""

    def __repr__(self) -> str:
        return "UNSET"


UNSET: Any = _Unset()


@dataclass(frozen=True)
class Settings:
    """The options a solver runs with (every one resolved).

    Attributes
    ----------
    tolerance : float or None
        COR tolerance choosing the modes (and the general integrator's steps); None: every
        mode.
    modes : int or None
        Flexible modes kept (a plain truncation); None: all.
    basis : {"modal", "physical"}
        Frame coordinates of the ODE solvers.
    rtol, atol : float
        Tolerances of the ODE solvers.
    output_step : float or None
        Spacing of the output times [s]; None: only t = 0 and t_c (no histories).
    t_max : float or None
        Give up if the ball has not separated by then [s]; None: 20 x the eq 11 estimate.
    """

    tolerance: float | None = DEFAULT_TOLERANCE
    modes: int | None = DEFAULT_MODES
    basis: str = "modal"
    rtol: float = 1e-10
    atol: float = 1e-12
    output_step: float | None = 1e-5
    t_max: float | None = None


#: The defaults of every option.
DEFAULTS = Settings()


def _checked(name: str, value: Any) -> Any:
    """``value`` of option ``name`` checked (types and ranges that do not depend on a solver)."""
    if name == "tolerance":
        return check_tolerance(value)
    if name == "modes":
        return None if value is None else check_integer("modes", value)
    if name == "basis":
        return check_choice("basis", value, BASES)
    if name in ("rtol", "atol"):
        return check_positive(name, value)
    if value is None:  # output_step, t_max
        return None
    unit = "s"
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise InputError(
            f"{name} = {show(value)} {unit} is not allowed: must be a number > 0",
            parameter=name,
            value=value,
        )
    return check_positive(name, value, unit)


@dataclass(frozen=True)
class SolverOptions:
    """Options given to a solver; those left :data:`UNSET` take the defaults.

    The fields are those of :class:`Settings`.
    """

    tolerance: Any = UNSET
    modes: Any = UNSET
    basis: Any = UNSET
    rtol: Any = UNSET
    atol: Any = UNSET
    output_step: Any = UNSET
    t_max: Any = UNSET

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if value is not UNSET:
                object.__setattr__(self, f.name, _checked(f.name, value))

    @classmethod
    def names(cls) -> tuple[str, ...]:
        """The option names."""
        return tuple(f.name for f in fields(cls))

    def given(self) -> dict[str, Any]:
        """The options given (not left out)."""
        return {n: getattr(self, n) for n in self.names() if getattr(self, n) is not UNSET}

    def settings(self, **defaults: Any) -> Settings:
        """Every option resolved: given, else ``defaults``, else :data:`DEFAULTS`."""
        values = {**defaults, **self.given()}
        return Settings(**values)


def check_time_limit(settings: Settings, t_est: float, steps: int | None, solver: str) -> None:
    """Refuse ``settings.t_max`` [s] when the times a solver lays out up to it (before it
    allocates them) would be more than :data:`~fem_racket.impact.system.MAX_OUTPUT_TIMES`.

    Those times are the output times (``output_step``) and, with or without them, the solver's
    own grid of ``steps`` per contact time (estimated ``t_est`` [s], eq 11; None: no grid, its
    work does not grow with t_max). The finer of the two binds, and the message names it.
    """
    t_max = settings.t_max
    output = math.inf if settings.output_step is None else settings.output_step
    grid = math.inf if steps is None else t_est / steps
    step = min(output, grid)
    if t_max is None or t_max / step <= MAX_OUTPUT_TIMES:  # as the output times are counted
        return
    if output <= grid:
        raise InputError(
            f"t_max = {show(t_max)} s is not allowed: at most {MAX_OUTPUT_TIMES:.0e} output "
            f"times of output_step = {show(output)} s, so t_max <= "
            f"{MAX_OUTPUT_TIMES * output:.3g} s "
            "(or a larger output_step)",
            parameter="t_max",
            value=t_max,
        )
    raise InputError(
        f"t_max = {show(t_max)} s is not allowed: at most {MAX_OUTPUT_TIMES:.0e} time steps of "
        f"{grid:.3g} s (solver {solver!r} takes {steps} per contact time, {t_est:.3g} s by "
        f"eq 11), so t_max <= {MAX_OUTPUT_TIMES * grid:.3g} s",
        parameter="t_max",
        value=t_max,
    )
