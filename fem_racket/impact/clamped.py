"""A clamped head: the ball against a head that does not move as a whole (:class:`ClampedHead`),
and the outcome of such an impact (:class:`ClampedImpact`).

The paper's clamped-frame targets (K_CB(V) and the clamped COR 0.83, eqs 1-4) and the ITF's
ball on concrete are impacts on a fixed support; the contact laws are calibrated on them
(:mod:`fem_racket.studies.calibrate`), and the ball of the string bed is fitted on the bed
clamped at its edge (:mod:`fem_racket.studies.bed_ball`). A :class:`ClampedHead` is the
structure of such an :class:`~fem_racket.impact.problem.ImpactProblem`:

- without strings, a rigid support: no mode of its own, the contact law alone between the ball
  and an immovable surface;
- with a :class:`~fem_racket.strings.bed.StringBed`, the bed on a clamped frame (its edge fixed;
  :func:`fem_racket.impact.strung.point.clamped_point`), struck at the head's centre: its
  membrane modes, no rigid mode (built by the solvers,
  :func:`fem_racket.impact.clamped_solve.head_modes`: this module, a base of impact/, imports no
  room of it).

The ball strikes the head's centre: the problem's impact position (x/L along a frame) does not
apply and is left at the problem's default :data:`CENTRE`; no swing, hand, offset or incidence
(:func:`fem_racket.impact.problem_checks.check_structure`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError

__all__ = ["CENTRE", "ClampedHead", "ClampedImpact"]

#: The impact position a clamped head's problem carries: ImpactProblem's default (x/L does not
#: apply to a clamped head, module docstring).
CENTRE = 0.75


@dataclass(frozen=True, eq=False)
class ClampedHead:
    """A head held fixed: a rigid support, or a string bed clamped at its edge (module
    docstring).

    Parameters
    ----------
    strings : StringBed or None
        The bed; None: a rigid support.
    """

    strings: StringBed | None = None

    def __post_init__(self) -> None:
        if self.strings is not None and not isinstance(self.strings, StringBed):
            raise InputError(f"strings = {self.strings!r} is not allowed: must be a StringBed")

    def __repr__(self) -> str:
        if self.strings is None:
            return "clamped head (rigid support)"
        s = self.strings
        return f"clamped head, strings {s.pattern} at {s.tension_n:.4g} N"


@dataclass(frozen=True, eq=False)
class ClampedImpact:
    """The outcome of an impact on a :class:`ClampedHead`.

    Attributes
    ----------
    speed : float
        Ball speed V_B0 [m/s] towards the head.
    cor : float
        -v_B(t_c) / V_B0.
    contact_time : float
        t_c [s].
    time, deflection, force : ndarray or None
        The contact's histories at the general integrator's steps: time [s], the ball/string
        law's deflection [m] and force [N]; None from the exact solution.
    """

    speed: float
    cor: float
    contact_time: float
    time: np.ndarray | None = None
    deflection: np.ndarray | None = None
    force: np.ndarray | None = None

    def summary(self) -> dict[str, float]:
        """The scalar results, units in the keys."""
        return {"speed_m_s": self.speed, "cor": self.cor, "contact_time_s": self.contact_time}
