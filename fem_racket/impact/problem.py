"""What is struck, where, by what, moving how: :class:`ImpactProblem` (and :class:`Impact`).

An impact problem states everything about one impact that does not depend on how it is solved:

- the structure: a free frame (:class:`~fem_racket.frame.model.FrameModel`), a frame held in a
  hand (:class:`HeldRacket`) or a clamped head (:class:`~fem_racket.impact.clamped.ClampedHead`);
- the impact point x/L and the ball's speed V_B0 [m/s] towards the racket (:class:`Impact`),
  and the point's lateral offset from the long axis [m] (off axis the frame also twists,
  :mod:`fem_racket.impact.offaxis`; checked against the head outline);
- the ball (:class:`~fem_racket.contact.linear.Ball`) and the contact law: the paper's linear
  compound ball/string spring (``law=None``; K_CB from ``kcb`` or the closing speed, ζ from
  ``zeta`` or the clamped COR 0.83, eqs 1-4) or any :class:`~fem_racket.contact.law.ContactLaw`;
- the end of contact for the paper's law (``separation``; any other law brings its own);
- the racket's motion before impact: a rigid swing, or initial velocities of its modes;
- the string bed (``strings``, a :class:`~fem_racket.strings.bed.StringBed`): None keeps the
  paper's lumped K_CB; a bed replaces it, and ``law`` is then the ball's own law (the
  ``kawazoe-1997-ball`` when None), acting on the bed (:mod:`fem_racket.impact.strung`);
- an oblique, spinning ball (``incidence``; None: head-on; :mod:`fem_racket.impact.oblique`).

It is immutable and validated once, when made; a field that does not apply to the rest of the
problem (K_CB under a nonlinear law, a hand with a nonlinear law) is refused in one line, never
ignored. How the problem is solved (method, tolerances, output times) belongs to a solver
(:mod:`fem_racket.impact.solvers`).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any

from fem_racket.contact.bed_ball import kawazoe_ball
from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.frame.hand import Hand
from fem_racket.frame.model import FrameModel
from fem_racket.impact.clamped import ClampedHead
from fem_racket.impact.closing import closing_speed
from fem_racket.impact.constants import SEPARATION_EVENTS
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.model_cache import frame_model
from fem_racket.impact.problem_checks import (
    check_build_options,
    check_held,
    check_law,
    check_oblique,
    check_offset,
    check_strings,
    check_structure,
    check_swing,
    named_law,
)
from fem_racket.impact.swing import Swing
from fem_racket.strings.bed import StringBed
from fem_racket.validation import (
    InputError,
    check_choice,
    check_finite,
    check_positive,
    check_range,
    show,
)

__all__ = ["HeldRacket", "Impact", "ImpactProblem"]


@dataclass(frozen=True)
class Impact:
    """Where and how fast the ball strikes.

    Parameters
    ----------
    position : float
        Impact point as x/L from the grip end, in [0, 1].
    speed : float
        Ball speed V_B0 [m/s] towards the stationary frame, > 0.
    """

    position: float
    speed: float

    def __post_init__(self) -> None:
        object.__setattr__(
            self, "position", check_range("position", self.position, 0.0, 1.0, unit="x/L")
        )
        object.__setattr__(self, "speed", check_positive("speed", self.speed, "m/s"))


@dataclass(frozen=True, eq=False)
class HeldRacket:
    """A frame held in a hand on its grip (:mod:`fem_racket.impact.held`).

    Parameters
    ----------
    model : FrameModel
        The frame.
    hand : Hand
        The hand: mass, grip span, stiffness and damping (every default an assumption).
    shock_window : float or None
        Window T of the handle-shock measures from the start of contact [s]
        (:mod:`fem_racket.impact.held.shock`); its default when None.
    """

    model: FrameModel
    hand: Hand
    shock_window: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.model, FrameModel):
            raise InputError(f"model = {self.model!r} is not allowed: must be a FrameModel")
        if not isinstance(self.hand, Hand):
            raise InputError(f"hand = {self.hand!r} is not allowed: must be a Hand")


@dataclass(frozen=True, eq=False, repr=False)
class ImpactProblem:
    """One impact, stated once (module docstring).

    Parameters
    ----------
    structure : FrameModel, HeldRacket or ClampedHead
        What is struck: a free frame, a frame held in a hand, or a clamped head.
    impact : Impact
        Impact point x/L and ball speed V_B0 [m/s].
    ball : Ball
        The ball (m_B [kg]).
    law : ContactLaw or None
        The ball/string law; None: the paper's linear spring-dashpot. A LinearContact is held
        referred to ``ball`` (its K_CB and C_CB, that ball's zeta: ``LinearContact.for_ball``).
    kcb : float or None
        K_CB [N/m] of the paper's law; from the closing speed through the paper's three points
        when None. Only with the paper's law.
    zeta : float or None
        Damping ratio of the paper's law; 0.0592 (clamped COR 0.83) when None. Only with the
        paper's law.
    separation : {"displacement", "force"} or None
        End of contact of the paper's law (None: "displacement", the paper's). Any other law
        ends contact by its own condition, so it is refused there.
    swing : Swing or None
        The racket's rigid motion before impact; at rest when None.
    frame_velocity : (v, omega) or array or None
        Initial racket motion as the centre of gravity's speed and the turning rate, or the
        free-free modes' velocities (:func:`fem_racket.impact.law_impact.modal_velocity`).
    strings : StringBed or None
        The string bed; None: the paper's lumped K_CB (unchanged). With a bed the racket is
        free and at rest, K_CB and zeta do not apply, and ``law`` is the ball's own law.
    offset : float
        Lateral offset of the impact point from the long axis [m] (0: on it, the paper's). The
        point must lie on the head outline (:class:`~fem_racket.frame.head.HeadOutline`) and
        the frame needs torsion data (cell data GJ and rhoIp); not with a hand.
    incidence : Incidence or None
        An oblique, spinning ball; ``impact`` gives its full speed. None: head-on, no spin.
    """

    structure: FrameModel | HeldRacket | ClampedHead
    impact: Impact = field(default_factory=lambda: Impact(0.75, 20.0))
    ball: Ball = field(default_factory=Ball)
    law: ContactLaw | None = None
    kcb: float | None = None
    zeta: float | None = None
    separation: str | None = None
    swing: Swing | None = None
    frame_velocity: Any = None
    strings: StringBed | None = None
    offset: float = 0.0
    incidence: Incidence | None = None

    def __post_init__(self) -> None:
        check_structure(self)
        if self.separation is not None:
            check_choice("separation", self.separation, SEPARATION_EVENTS)
        if self.law is not None:
            object.__setattr__(self, "law", check_law(self))
        else:  # the paper's K_CB and zeta, checked once
            LinearContact.for_speed(
                self.impact.speed, kcb=self.kcb, zeta=self.zeta, ball_mass=self.ball.mass
            )
        check_swing(self)
        if self.held:
            check_held(self)
        if self.strings is not None:
            check_strings(self)
        object.__setattr__(self, "offset", check_finite("offset", self.offset, "m"))
        check_offset(self)
        check_oblique(self)

    def ball_law(self) -> ContactLaw:
        """The ball's own law on the string bed: ``law``, or the ``kawazoe-1997-ball``."""
        if self.law is not None:
            return self.law
        return kawazoe_ball(self.ball.mass, self.separation or "displacement")

    @classmethod
    def build(cls, frame: Any = None, *, elements: int | None = None, **fields: Any):
        """A problem on ``frame`` (a Frame, FrameMesh or FrameModel; the standard racket when
        None), meshed with ``elements`` cells (20 by default; not with a FrameModel, which is
        meshed already). ``fields``: ``position``, ``speed``, ``ball_mass``, ``law`` (a
        ContactLaw or a law's name), ``hand`` and the fields of the class."""
        if isinstance(frame, FrameModel) and elements is not None:
            raise InputError(
                f"elements = {show(elements)} is not allowed with a FrameModel: it is meshed "
                "already (give a Frame or a FrameMesh to mesh)"
            )
        model = frame_model(frame, 20 if elements is None else elements)
        impact = Impact(fields.pop("position", 0.75), fields.pop("speed", 20.0))
        mass = fields.pop("ball_mass", None)
        ball = Ball() if mass is None else Ball(mass)
        law = named_law(fields.pop("law", None), fields.get("strings"))
        hand = fields.pop("hand", None)
        window = fields.pop("shock_window", None)
        if hand is None and window is not None:
            raise InputError(
                f"shock_window = {show(window)} s is not allowed without a hand: give a hand"
            )
        check_build_options(fields, cls)
        structure = model if hand is None else HeldRacket(model, hand, window)
        return cls(structure, impact, ball, law, **fields)

    # -- views --------------------------------------------------------------------------------

    @property
    def held(self) -> bool:
        """True when the racket is held in a hand."""
        return isinstance(self.structure, HeldRacket)

    @property
    def clamped(self) -> bool:
        """True when the head is clamped (no frame moves)."""
        return isinstance(self.structure, ClampedHead)

    @property
    def model(self) -> FrameModel | None:
        """The frame model (of the held racket too); None on a clamped head, which has no frame
        (its bed's modes are the solvers', :mod:`fem_racket.impact.clamped_solve`)."""
        if self.clamped:
            return None
        return self.structure.model if self.held else self.structure

    @property
    def linear(self) -> bool:
        """True under the paper's linear law."""
        return self.law is None

    @property
    def moving(self) -> bool:
        """True when the racket moves before impact."""
        return self.swing is not None or self.frame_velocity is not None

    @property
    def racket_speed(self) -> float:
        """Speed of the racket's impact point towards the ball before impact [m/s]."""
        if self.swing is None:
            return 0.0
        return float(self.swing.speed_at(self.impact.position * self.model.mesh.length))

    @property
    def closing_speed(self) -> float:
        """Ball speed relative to the racket's impact point [m/s] (refused when <= 0)."""
        return closing_speed(self.impact.speed, self.racket_speed)

    def contact(self) -> LinearContact:
        """The paper's law at the closing speed (K_CB [N/m], zeta)."""
        return LinearContact.for_speed(
            self.closing_speed,
            kcb=self.kcb,
            zeta=self.zeta,
            ball_mass=self.ball.mass,
            separation=self.separation or "displacement",
        )

    def replace(self, **changes: Any) -> ImpactProblem:
        """A copy with ``changes`` (validated again)."""
        return replace(self, **changes)

    def __repr__(self) -> str:
        law = "linear (paper)" if self.law is None else self.law.name
        if self.clamped:
            return f"ImpactProblem({self.structure!r}; {self.impact.speed:.4g} m/s; law {law})"
        where = "held" if self.held else "free"
        if self.strings is not None and self.law is None:
            law = "kawazoe-1997-ball"
        motion = "at rest"
        if self.swing is not None:
            motion = f"swinging {self.racket_speed:.3g} m/s"
        elif self.frame_velocity is not None:
            motion = "moving"
        bed = ""
        if self.strings is not None:
            bed = f"; strings {self.strings.pattern} at {self.strings.tension_n:.4g} N"
        if self.incidence is not None:  # oblique
            bed += f"; {self.incidence.angle:.4g} deg, {self.incidence.spin:.4g} rpm"
        return (
            f"ImpactProblem({where} frame, {self.model.mesh.n_elements} elements; "
            f"x = {self.impact.position:.4g} L, "
            + (f"y = {self.offset:.4g} m, " if self.offset else "")
            + f"{self.impact.speed:.4g} m/s; "
            f"ball {self.ball.mass:.4g} kg; law {law}; {motion}{bed})"
        )
