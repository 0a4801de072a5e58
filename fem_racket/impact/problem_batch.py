"""Many impact problems as arrays: :class:`ProblemBatch` and its outcome :class:`BatchOutcome`.

A sweep, a map or a refinement asks for thousands of impacts that differ only in numbers: the
frame (one of a few assembled models, each scaled by a factor on every EI), the impact point
x/L and its lateral offset, the ball's speed and mass, the paper's K_CB and zeta or a contact
law's parameters, and the racket's rigid swing. A :class:`ProblemBatch` states them as arrays
of one value per case; case ``i`` is the :class:`~fem_racket.impact.problem.ImpactProblem`
:meth:`ProblemBatch.problem` returns, so a batch means exactly what its problems mean. A solver
(:meth:`fem_racket.impact.solvers.Solver.solve_many`) answers a batch with a
:class:`~fem_racket.impact.batch_outcome.BatchOutcome` (arrays of one value per case, NaN where
a case failed), choosing how: the exact solver by the batched engine (by the held racket's modal
path with a hand), the general solver by one call of the general integrator over every case, the
ODE solvers case by case.

The swing enters as each case's rigid racket motion :class:`~fem_racket.impact.swing.Swing`
(butt speed and turning rate towards the ball); the impact point then moves at
v_r = v + omega x.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball
from fem_racket.contact.presets import check_linear_options
from fem_racket.frame.hand import Hand
from fem_racket.frame.model import FrameModel
from fem_racket.impact.batch_outcome import BatchOutcome
from fem_racket.impact.constants import SEPARATION_EVENTS
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.problem import HeldRacket, Impact, ImpactProblem
from fem_racket.impact.problem_checks import refuse_separation
from fem_racket.impact.swing import Swing
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError, check_choice, show

__all__ = ["BatchOutcome", "ProblemBatch"]  # BatchOutcome: from .batch_outcome

#: The fields of one value per case (or one shared), besides the swing.
_PER_CASE = ("position", "speed", "frame", "ei_factor", "offset", "ball_mass", "kcb", "zeta")


def _column(name: str, value: Any, n: int, dtype: Any = float) -> np.ndarray:
    arr = np.asarray(value, dtype=dtype)
    if arr.ndim > 1 or (arr.ndim == 1 and arr.size != n):
        raise InputError(f"{name} of {arr.size} values is not allowed: must be one or {n} values")
    return np.broadcast_to(arr, (n,))


@dataclass(frozen=True, eq=False, repr=False)
class ProblemBatch:
    """Impact problems as arrays (module docstring); every per-case field is a number (shared)
    or an array of one value per case.

    Parameters
    ----------
    models : tuple of FrameModel
        The frames struck.
    frame : int or array of int
        Index into ``models`` of each case's frame.
    position : array
        Impact points x/L.
    speed : array
        Ball speeds V_B0 [m/s] towards the racket.
    ei_factor : array
        Factor on every EI of the case's frame (1: the model as it is).
    offset : array
        Lateral offsets of the impact points from the long axis [m].
    ball_mass : array
        m_B [kg].
    kcb, zeta : array or None
        The paper's law: K_CB [N/m] (None: from the closing speed) and damping ratio (None:
        clamped COR 0.83). Only with ``law`` None.
    law : ContactLaw or None
        Another contact law, its parameters numbers or arrays of one value per case.
    separation : {"displacement", "force"} or None
        End of contact of the paper's law (None: the paper's).
    swing : array, shape (n, 2), or None
        Each case's rigid racket motion (butt speed [m/s], turning rate [rad/s]) towards the
        ball; at rest when None.
    peak_force : bool
        Whether the outcome holds the largest contact force (the engine computes it only when
        asked), and with a hand the largest grip force.
    strings : sequence of StringBed, or None
        Each case's string bed (:attr:`ImpactProblem.strings`); None: the lumped K_CB.
    incidence : sequence of Incidence, or None
        Each case's oblique, spinning ball (:attr:`ImpactProblem.incidence`); None: head-on.
    hand : Hand or None
        Every frame held in this hand (:class:`~fem_racket.impact.problem.HeldRacket`); None:
        free rackets. Only with the paper's law, on the long axis, head-on and unstrung.
    shock_window : float or None
        Window of the held racket's shock measures [s] (its default when None); with a hand.
    """

    models: tuple[FrameModel, ...]
    position: Any
    speed: Any
    frame: Any = 0
    ei_factor: Any = 1.0
    offset: Any = 0.0
    ball_mass: Any = Ball().mass
    kcb: Any = None
    zeta: Any = None
    law: ContactLaw | None = None
    separation: str | None = None
    swing: Any = None
    peak_force: bool = False
    strings: Any = None
    incidence: Any = None
    hand: Hand | None = None
    shock_window: float | None = None

    def __post_init__(self) -> None:
        models = tuple(self.models)
        if not models or not all(isinstance(m, FrameModel) for m in models):
            raise InputError("models is not allowed: must be one or more FrameModels")
        object.__setattr__(self, "models", models)
        per_case = [getattr(self, k) for k in _PER_CASE if getattr(self, k) is not None]
        n = max(int(np.size(v)) for v in per_case)
        if self.swing is not None:
            n = max(n, int(np.size(self.swing)) // 2)
        for objects in (self.strings, self.incidence):
            n = max(n, 0 if objects is None else len(tuple(objects)))
        set_ = object.__setattr__
        set_(self, "position", _column("position", self.position, n))
        for name in ("speed", "ei_factor", "offset", "ball_mass"):
            set_(self, name, _column(name, getattr(self, name), n))
        frame = _column("frame", self.frame, n, np.int64)
        if n and (frame.min() < 0 or frame.max() >= len(models)):
            raise InputError(f"frame is not allowed: must index the {len(models)} models")
        set_(self, "frame", frame)
        if self.law is not None:
            if not isinstance(self.law, ContactLaw):
                raise InputError(f"law = {self.law!r} is not allowed: must be a ContactLaw")
            refuse_separation(self.law, self.separation)  # as a problem refuses it
            check_linear_options(self.law, kcb=self.kcb, zeta=self.zeta)
        for name in ("kcb", "zeta"):
            if getattr(self, name) is not None:
                set_(self, name, _column(name, getattr(self, name), n))
        if self.separation is not None:
            check_choice("separation", self.separation, SEPARATION_EVENTS)
        if self.swing is not None:
            swing = np.asarray(self.swing, dtype=float)
            set_(self, "swing", np.broadcast_to(swing, (n, 2)))
        for name, kind in (("strings", StringBed), ("incidence", Incidence)):
            value = getattr(self, name)
            if value is None:
                continue
            value = tuple(value)
            if len(value) != n or not all(isinstance(v, kind) for v in value):
                raise InputError(f"{name} is not allowed: must be {n} {kind.__name__}s, one a case")
            set_(self, name, value)
        if self.hand is not None or self.shock_window is not None:
            self._check_held()

    def _check_held(self) -> None:
        """Refuse what a hand cannot take (one line); each frame's first case checked as its
        problem (the grip on the handle, :func:`~fem_racket.impact.problem_checks.check_held`)."""
        if self.hand is None:
            raise InputError(
                f"shock_window = {show(self.shock_window)} s is not allowed without a hand: "
                "give a hand",
                parameter="shock_window",
                value=self.shock_window,
            )
        if not isinstance(self.hand, Hand):
            raise InputError(f"hand = {self.hand!r} is not allowed: must be a Hand")
        for name in ("law", "strings", "incidence"):
            if getattr(self, name) is not None:
                raise InputError(f"{name} is not allowed in a ProblemBatch with a hand")
        if np.any(self.offset != 0.0):
            raise InputError("offset is not allowed in a ProblemBatch with a hand: on the axis")
        for k in np.unique(self.frame):
            self.problem(int(np.flatnonzero(self.frame == k)[0]))

    @property
    def held(self) -> bool:
        """True when the frames are held in a hand."""
        return self.hand is not None

    @property
    def per_case(self) -> bool:
        """True when the cases carry a string bed or an incidence (solved one by one)."""
        return self.strings is not None or self.incidence is not None

    @classmethod
    def of(cls, problem: ImpactProblem, **per_case: Any) -> ProblemBatch:
        """Copies of ``problem`` that differ in ``per_case`` fields (numbers or arrays;
        ``strings`` and ``incidence`` sequences of one object per case)."""
        if problem.frame_velocity is not None:
            raise InputError(
                "problem is not allowed in a ProblemBatch: it takes a racket at rest or "
                "swinging (no frame_velocity)"
            )
        swing = problem.swing
        fields: dict[str, Any] = {
            "position": problem.impact.position,
            "speed": problem.impact.speed,
            "offset": problem.offset,
            "ball_mass": problem.ball.mass,
            "kcb": problem.kcb,
            "zeta": problem.zeta,
            "law": problem.law,
            "separation": problem.separation,
            "swing": None if swing is None else (swing.velocity, swing.omega),
        }
        fields.update(per_case)
        n = max(
            [int(np.size(v)) for k, v in fields.items() if k in _PER_CASE and v is not None]
            + [len(per_case.get(k, ())) for k in ("strings", "incidence")]
        )
        for name in ("strings", "incidence"):
            if name not in per_case and getattr(problem, name) is not None:
                fields[name] = (getattr(problem, name),) * n
        if problem.held:
            fields.update(hand=problem.structure.hand, shock_window=problem.structure.shock_window)
        return cls((problem.model,), **fields)

    def __len__(self) -> int:
        return int(self.position.size)

    def __repr__(self) -> str:
        law = "linear (paper)" if self.law is None else self.law.name
        held = " held in a hand" if self.held else ""
        return f"ProblemBatch({len(self)} cases on {len(self.models)} frames{held}; law {law})"

    # -- what the cases are -----------------------------------------------------------------

    @property
    def linear(self) -> bool:
        """True under the paper's linear law."""
        return self.law is None

    def lengths(self) -> np.ndarray:
        """Each case's frame length [m]."""
        return np.array([m.mesh.length for m in self.models])[self.frame]

    def racket_speed(self) -> np.ndarray:
        """v_r: each case's impact point's speed towards the ball before impact [m/s]."""
        if self.swing is None:
            return np.zeros(len(self))
        x = self.position * self.lengths()
        return self.swing[:, 0] + self.swing[:, 1] * x  # Swing.speed_at, case by case

    def case_law(self, i: int) -> ContactLaw | None:
        """The contact law of case ``i`` (its parameters' values for that case)."""
        if self.law is None:
            return None
        law = self.law
        per_case = {
            p.field: float(getattr(law, p.field)[i])
            for p in law.declared
            if np.ndim(getattr(law, p.field)) == 1
        }
        return replace(law, **per_case) if per_case else law

    def problem(self, i: int, model: FrameModel | None = None) -> ImpactProblem:
        """Case ``i`` as an :class:`ImpactProblem`; ``model``: its frame already scaled by
        ``ei_factor[i]`` (to reuse it), else scaled here."""
        if model is None:
            base, f = self.models[self.frame[i]], float(self.ei_factor[i])
            model = base if f == 1.0 else base.scaled(f)
        swing = None
        if self.swing is not None and np.any(self.swing[i] != 0.0):
            swing = Swing(float(self.swing[i, 0]), float(self.swing[i, 1]))
        if self.hand is not None:
            model = HeldRacket(model, self.hand, self.shock_window)
        return ImpactProblem(
            model,
            Impact(float(self.position[i]), float(self.speed[i])),
            Ball(float(self.ball_mass[i])),
            self.case_law(i),
            kcb=None if self.kcb is None else float(self.kcb[i]),
            zeta=None if self.zeta is None else float(self.zeta[i]),
            separation=self.separation,
            swing=swing,
            strings=None if self.strings is None else self.strings[i],
            offset=float(self.offset[i]),
            incidence=None if self.incidence is None else self.incidence[i],
        )
