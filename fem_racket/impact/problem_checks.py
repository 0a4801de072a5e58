"""The checks of an :class:`~fem_racket.impact.problem.ImpactProblem` that concern its structure
(a clamped head), its contact law, its hand, its string bed and its impact point's offset: each
refuses, in one line, a field the rest of the problem cannot use. The problem is typed ``Any``
here: importing its class would make an import cycle (it calls these). The bed's check lives
here, not in the string bed's room (:mod:`fem_racket.impact.strung`), so that the problem, a
base module of impact/, does not import a method's room; the room takes :func:`bed_coordinates`
from here."""

from __future__ import annotations

from dataclasses import fields as dataclass_fields
from typing import Any

import numpy as np

from fem_racket.contact.bed_ball import KAWAZOE_BALL
from fem_racket.contact.law import ContactLaw
from fem_racket.contact.presets import check_linear_options, get_law
from fem_racket.frame.hand import check_grip
from fem_racket.frame.model import FrameModel
from fem_racket.frame.torsion import check_off_axis
from fem_racket.impact.clamped import CENTRE, ClampedHead
from fem_racket.impact.closing import check_kcb_closing
from fem_racket.impact.incidence import check_incidence, check_kcb_normal
from fem_racket.impact.incidence_idle import refuse_idle_incidence
from fem_racket.impact.offaxis import check_offsets
from fem_racket.impact.swing import check_swing_speeds
from fem_racket.strings.bed import StringBed
from fem_racket.strings.point import DEFAULT_REFINE
from fem_racket.strings.reach import on_bed, strike_interval
from fem_racket.validation import InputError, show

__all__ = [
    "check_build_options",
    "bed_coordinates",
    "check_held",
    "check_law",
    "check_offset",
    "check_strings",
    "check_structure",
    "named_law",
    "refuse_separation",
]

#: Why the lumped K_CB's options (kcb, zeta, the linear law) are refused with a string bed.
LUMPED = "the bed replaces the lumped K_CB (give the ball's own law as law)"


def check_build_options(options: dict[str, Any], problem_class: type) -> None:
    """Refuse an option of ``ImpactProblem.build`` that is none of its own nor a field of
    ``problem_class`` after structure, impact, ball and law (which ``build`` makes), and a
    head-on, spinless incidence's contact parameters (:func:`refuse_idle_incidence`)."""
    own = ["elements", "position", "speed", "ball_mass", "law", "hand", "shock_window"]
    fields = [f.name for f in dataclass_fields(problem_class)][4:]
    for key in options:
        if key not in fields:
            raise InputError(
                f"{key} is not an option of ImpactProblem.build: must be one of "
                f"{', '.join(own + fields)}"
            )
    refuse_idle_incidence(options.get("incidence"))


def named_law(law: Any, strings: Any) -> ContactLaw | None:
    """``law`` (a ContactLaw, a law's name or None) as a ContactLaw, None for the paper's linear
    law; that law named with a string bed (``strings`` not None) is refused as kcb and zeta are:
    its K_CB is the ball and strings together."""
    if law == "linear" and strings is not None:
        raise InputError(
            f"law = 'linear' is not allowed with a string bed: {LUMPED}",
            parameter="law",
            value=law,
        )
    return get_law(law) if isinstance(law, str) else law


def check_law(problem: Any) -> ContactLaw:
    """Refuse a ``law`` that is not a ContactLaw, or options the law cannot use (one line).
    Returns the law referred to the problem's ball (:meth:`ContactLaw.for_ball`: a
    LinearContact keeps K_CB and C_CB, its zeta becomes that ball's, as its settings state)."""
    if not isinstance(problem.law, ContactLaw):
        raise InputError(f"law = {problem.law!r} is not allowed: must be a ContactLaw or None")
    check_linear_options(problem.law, kcb=problem.kcb, zeta=problem.zeta)
    bed = isinstance(problem.structure, ClampedHead) and problem.structure.strings is not None
    if problem.law is KAWAZOE_BALL and problem.strings is None and not bed:
        raise InputError(
            "law = 'kawazoe-1997-ball' is not allowed without a string bed: it is the "
            "ball's own law, fitted in series with the bed (give strings, e.g. "
            "--string-tension)"
        )
    refuse_separation(problem.law, problem.separation)
    return problem.law.for_ball(problem.ball.mass)


def refuse_separation(law: ContactLaw, separation: str | None) -> None:
    """Refuse a ``separation`` (any but None) under ``law``, another law than the paper's."""
    if separation is not None:
        raise InputError(
            f"separation = {show(separation)} is not allowed with contact law "
            f"{show(law.name)}: the law ends contact by its own condition ({law.end})"
        )


def check_offset(problem: Any) -> None:
    """Refuse a lateral ``offset`` [m] off the long axis with a hand (the held racket does not
    twist), or one off the head outline (on a string bed: checked against the bed's head)."""
    if problem.offset == 0.0:
        return
    if problem.held:
        raise InputError(
            f"offset = {show(problem.offset)} m is not allowed with a hand: the held racket "
            "is struck on its long axis (it does not twist)",
            parameter="offset",
            value=problem.offset,
        )
    if problem.strings is None:  # on the bed: checked against the bed's head
        check_offsets(problem.model, problem.impact.position, problem.offset)


def check_held(problem: Any) -> None:
    """Refuse what a racket held in a hand cannot take (a nonlinear law, mode velocities, a
    separation other than the paper's) and a grip off the handle (one line)."""
    if problem.law is not None:
        raise InputError(
            f"law = {show(problem.law.name)} is not allowed with a hand: the held racket takes "
            "the paper's linear law (kcb, zeta)"
        )
    if problem.frame_velocity is not None:
        raise InputError(
            "frame_velocity is not allowed with a hand: give the racket's motion as a swing"
        )
    if problem.separation is not None:
        raise InputError(
            f"separation = {show(problem.separation)} is not allowed with a hand: the held "
            "racket ends contact by the spring deflection (the paper's criterion)"
        )
    check_grip(problem.structure.hand, problem.model.mesh.length)


def check_structure(problem: Any) -> None:
    """Refuse a structure that is not a FrameModel, a HeldRacket or a ClampedHead, and on a
    :class:`~fem_racket.impact.clamped.ClampedHead` what does not apply to a head that does not
    move, struck head-on at its centre (one line)."""
    if not (isinstance(problem.structure, FrameModel | ClampedHead) or problem.held):
        raise InputError(
            f"structure = {problem.structure!r} is not allowed: must be a FrameModel, a "
            "HeldRacket or a ClampedHead"
        )
    if not problem.clamped:
        return
    why = {
        "swing": "it does not move",
        "frame_velocity": "it does not move",
        "strings": "give the bed to the ClampedHead (ClampedHead(strings))",
        "incidence": "it is struck head-on",
    }
    for name, reason in why.items():
        if getattr(problem, name) is not None:
            raise InputError(f"{name} is not allowed with a clamped head: {reason}")
    if problem.offset != 0.0:
        raise InputError(
            f"offset = {show(problem.offset)} m is not allowed with a clamped head: it is struck "
            "at its centre",
            parameter="offset",
            value=problem.offset,
        )
    if problem.impact.position != CENTRE:
        raise InputError(
            f"position = {show(problem.impact.position)} x/L is not allowed with a clamped head: "
            f"it is struck at its centre (leave the position at {CENTRE}, the default)",
            parameter="position",
            value=problem.impact.position,
        )


def bed_coordinates(
    bed: StringBed,
    position: float,
    lateral_m: float,
    frame_length_m: float,
    centre: float,
    refine: int = DEFAULT_REFINE,
) -> np.ndarray:
    """The impact point on the bed [m, from the head's centre], checked to lie on the head: the
    ball's contact disk on the bed meshed with ``refine`` refinements
    (:mod:`fem_racket.strings.reach`), else refused naming the offsets reachable at
    ``position`` and the positions reachable on the axis."""
    point = np.array([(position - centre) * frame_length_m, lateral_m])
    if on_bed(bed, point, refine):
        return point
    x_lo, x_hi = strike_interval(bed, np.zeros(2), np.array([1.0, 0.0]), refine)
    axis = _inward(centre + x_lo / frame_length_m, centre + x_hi / frame_length_m, 3)
    axis = f"positions {axis} x/L on the axis"
    where = f"position = {show(position)} x/L"
    disk = f"the ball's contact disk (radius {bed.load_radius_m:g} m) must lie on the head"
    y_lo, y_hi = strike_interval(bed, np.array([point[0], 0.0]), np.array([0.0, 1.0]), refine)
    if y_lo > y_hi:
        named = where if lateral_m == 0.0 else f"{where}, offset = {show(lateral_m)} m"
        raise InputError(f"{named} is not allowed with the string bed: {disk}: {axis}")
    reach = (
        f"|offset| <= {np.floor(min(-y_lo, y_hi) * 1e4) / 1e4:.4f} m"
        if abs(y_lo + y_hi) <= 1e-12
        else f"offset {_inward(y_lo, y_hi, 4)} m"
    )
    raise InputError(
        f"offset = {show(lateral_m)} m at {where} is not allowed with the string bed: {disk}: "
        f"{reach} at that position ({axis})",
        parameter="offset",
        value=lateral_m,
    )


def _inward(lo: float, hi: float, digits: int) -> str:
    """``"lo to hi"`` rounded inward to ``digits`` decimals (every printed value allowed)."""
    s = 10.0**digits
    return f"{np.ceil(lo * s) / s:.{digits}f} to {np.floor(hi * s) / s:.{digits}f}"


def check_strings(problem: Any) -> None:
    """Refuse, in one line, what an impact problem with a string bed cannot take: a hand, a
    racket moving before impact, the lumped K_CB's kcb and zeta, a point off the head."""
    if not isinstance(problem.strings, StringBed):
        raise InputError(f"strings = {problem.strings!r} is not allowed: must be a StringBed")
    at_rest = "the strung racket is free and at rest"
    refused = {
        "hand": (problem.held, at_rest),
        "swing": (problem.swing is not None, at_rest),
        "frame_velocity": (problem.frame_velocity is not None, at_rest),
        "kcb": (problem.kcb is not None, LUMPED),
        "zeta": (problem.zeta is not None, LUMPED),
    }
    for key, (given, why) in refused.items():
        if given:
            raise InputError(f"{key} is not allowed with a string bed: {why}")
    bed = problem.strings
    offset = float(problem.offset)
    L = problem.model.mesh.length
    bed_coordinates(bed, problem.impact.position, offset, L, bed.head_centre)
    if offset != 0.0:
        check_off_axis(problem.model.mesh, f"offset = {show(offset)} m")


def check_swing(problem: Any) -> None:
    """A swing (if any) not combined with a frame velocity, moving no point of the racket faster
    than the racket speed's bound; its ball and strings close at the impact point and, where
    K_CB follows from that closing speed (the paper's law without kcb, no string bed), within
    the speeds the paper gives K_CB for: refused naming the racket's speed at the impact
    point."""
    if problem.swing is None:
        return
    if problem.frame_velocity is not None:
        raise InputError("swing and frame_velocity cannot be combined: give one")
    check_swing_speeds(problem.swing, problem.model.mesh.length)
    closing = problem.closing_speed  # ball and strings must close, under any law
    if problem.law is None and problem.kcb is None and problem.strings is None:
        name = "racket speed at the impact point"
        check_kcb_closing(problem.impact.speed, problem.racket_speed, closing, name)


def check_oblique(problem: Any) -> None:
    """The incidence (:func:`~fem_racket.impact.incidence.check_incidence`) and, where K_CB
    follows from its normal speed (the paper's law without kcb, no string bed, the racket at
    rest), that speed within the speeds the paper gives K_CB for, named as the angle."""
    check_incidence(problem.incidence, strung=problem.strings is not None)
    inc = problem.incidence
    if inc is not None and inc.lateral and problem.model is not None and not problem.held:
        # the racket's yaw under a ball across the face needs its polar moment
        lateral = ("side_angle", "deg") if inc.side_angle != 0.0 else ("side_spin", "rpm")
        check_off_axis(
            problem.model.mesh, f"{lateral[0]} = {show(getattr(inc, lateral[0]))} {lateral[1]}"
        )
    own_kcb = problem.law is not None or problem.kcb is not None or problem.strings is not None
    moving = problem.swing is not None or problem.frame_velocity is not None
    if problem.incidence is not None and not (own_kcb or moving):
        check_kcb_normal(problem.incidence, problem.impact.speed)
