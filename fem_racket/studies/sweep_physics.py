"""The sweep's string-bed and oblique-ball axes: what they combine with, and their cases.

``string_tension`` [N] and ``pattern`` (issue 25) put a string bed
(:class:`~fem_racket.strings.bed.StringBed`, the paper's racket strung at 246 N with 16 x 19
nylon unless given) on every case: the bed replaces the lumped K_CB and the ball strikes it with
its own law (the ``kawazoe-1997-ball`` unless ``law`` is given). ``angle`` [deg], ``spin``
[rpm] and ``friction`` (issue 26), and the ball's ``ball_inertia`` (I/(m R^2)), ``ball_radius``
[m] and the contact's ``compliance_ratio`` (eta^2), make every case an oblique, spinning ball
(:class:`~fem_racket.impact.incidence.Incidence`; its defaults, angle 0, spin 0 and friction
0.4, unless given), solved as its normal impact at V cos(angle) and the tangential contact over
it; ``side_angle`` [deg] (-90..90, the path out of the plane of the long axis) and
``side_spin`` [rpm] (about the long axis's direction) make it a 3-D one, as ``simulate
--side-angle/--side-spin`` (normal speed V cos(side) cos(angle); with both 0 the impact in the
plane, bit for bit). A string bed takes an oblique ball in the plane of the long axis, as
``simulate --string-tension ... --angle ...`` does. What the problems refuse (a string bed on a
swinging racket, a ball crossing the face of a strung one ...) is refused here for the whole
grid, in one line, before any work.

The contact regime of an oblique impact (``slide``, ``grip``, ``slide-grip-slide`` ...: the
phases in order) is a number in the dataset (:func:`regime_code`): the count of phases, negative
when the first is a grip (1: slide, 3: slide-grip-slide, -1: grip), with CF ``flag_values`` and
``flag_meanings`` naming the codes present.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.incidence_idle import refuse_idle_contact
from fem_racket.impact.problem_checks import bed_coordinates
from fem_racket.strings.bed import StringBed
from fem_racket.strings.options import check_tension
from fem_racket.studies.grid_values import OBLIQUE_AXES, STRING_AXES, pattern_label
from fem_racket.validation import InputError, show

__all__ = [
    "LATERAL_AXES",
    "OBLIQUE_AXES",
    "STRING_AXES",
    "case_beds",
    "case_incidences",
    "check_physics",
    "fixed_label",
    "given",
    "regime_code",
    "regime_label",
]

#: The axes that take the ball across the face (out of the plane of the long axis).
LATERAL_AXES = ("side_angle", "side_spin")
#: The Incidence field of each oblique axis.
INCIDENCE_FIELD = {a: a for a in OBLIQUE_AXES} | {"ball_radius": "radius"}


def given(values: dict[str, Any], names: tuple[str, ...]) -> list[str]:
    """The ``names`` with a value in ``values``."""
    return [n for n in names if values.get(n) is not None]


def _nonzero(values: dict[str, Any], name: str) -> bool:
    return bool(np.any(np.atleast_1d(values[name]) != 0.0))


def check_physics(values: dict[str, Any], length: float) -> None:
    """Refuse, in one line, a string-bed or oblique axis with what it cannot combine with.

    ``values``: the sweep's parameter values; ``length``: the racket's length [m] (the string
    bed's head is placed on it). The solver and its options on the strung racket are the
    solver's to refuse (:func:`fem_racket.impact.strung.solve.check_strung`, asked on the
    sweep's first case before it runs: :func:`fem_racket.studies.cases.check_first_case`).
    """
    refuse_idle_contact({n: values.get(n) for n in OBLIQUE_AXES})  # as simulate's
    strings = given(values, STRING_AXES)
    if not strings:
        return
    what = f"with {strings[0]} (a string bed)"
    for name in given(values, LATERAL_AXES):
        if _nonzero(values, name):
            raise InputError(
                f"{name} = {show(values[name])} is not allowed {what}: the oblique impact on the "
                "bed is modelled in the plane of the long axis only (as simulate's)",
                parameter=name,
                value=values[name],
            )
    lumped = "the bed replaces the lumped K_CB (give the ball's own law with law)"
    for name in ("kcb", "zeta"):
        if values[name] is not None:
            raise InputError(f"{name} is not allowed {what}: {lumped}")
    # an offset is the solver's and the problem's to check (struck off-axis as simulate's)
    if _nonzero(values, "racket_speed"):
        why = "the strung racket is free and at rest"
        raise InputError(
            f"racket_speed = {show(values['racket_speed'])} is not allowed {what}: {why}",
            parameter="racket_speed",
            value=values["racket_speed"],
        )
    if values.get("string_tension") is not None:
        codes = np.atleast_1d(1619 if values.get("pattern") is None else values["pattern"])
        beds = [StringBed(mains=int(c) // 100, crosses=int(c) % 100) for c in codes]
        for tension in np.atleast_1d(values["string_tension"]).tolist():
            check_tension("string_tension", tension, beds)  # too soft a bed: before any work
    bed = StringBed()  # every point struck on the bed, as the problem checks it
    offsets = np.atleast_1d(0.0 if values.get("offset") is None else values["offset"])
    for x in np.atleast_1d(values["position"]):
        for y in offsets:
            bed_coordinates(bed, float(x), float(y), length, bed.head_centre)


def case_beds(p: dict[str, Any], n: int) -> tuple[StringBed, ...] | None:
    """The string beds of ``n`` cases with parameter values ``p`` (None: no bed)."""
    if not given(p, STRING_AXES):
        return None
    base = StringBed()
    tension = p["string_tension"]
    tension = np.broadcast_to(base.tension_n if tension is None else tension, n)
    code = p["pattern"]
    code = np.broadcast_to(100 * base.mains + base.crosses if code is None else code, n)
    return tuple(
        StringBed(tension_n=float(t), mains=int(c) // 100, crosses=int(c) % 100)
        for t, c in zip(tension, code, strict=True)
    )


def case_incidences(p: dict[str, Any], n: int) -> tuple[Incidence, ...] | None:
    """The incidences of ``n`` cases with parameter values ``p`` (None: head-on)."""
    if not given(p, OBLIQUE_AXES):
        return None
    base = Incidence()
    fields = [INCIDENCE_FIELD[k] for k in OBLIQUE_AXES]
    cols = [
        np.broadcast_to(getattr(base, f) if p[k] is None else p[k], n)
        for k, f in zip(OBLIQUE_AXES, fields, strict=True)
    ]
    return tuple(
        Incidence(**{f: float(v) for f, v in zip(fields, values, strict=True)})
        for values in zip(*cols, strict=True)
    )


def regime_code(label: str) -> float:
    """The number of a contact regime (module docstring); NaN for none (a failed case)."""
    if not label:
        return np.nan
    phases = label.split("-")
    return float(len(phases) if phases[0] == "slide" else -len(phases))


def regime_label(code: float) -> str:
    """The contact regime of a :func:`regime_code`."""
    first, other = ("slide", "grip") if code > 0 else ("grip", "slide")
    return "-".join(first if k % 2 == 0 else other for k in range(int(abs(code))))


def fixed_label(name: str, value: Any) -> Any:
    """A fixed value as an attribute: a pattern by its label."""
    return pattern_label(value) if name == "pattern" else value
