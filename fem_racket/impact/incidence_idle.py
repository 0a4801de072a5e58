"""The tangential contact's parameters on a head-on, spinless ball: refused, never ignored.

With the ball's path along the face normal and no spin (:data:`COMPONENTS` all zero) no
tangential force acts, so friction, the ball's inertia and radius and the compliance ratio
(:class:`~fem_racket.impact.incidence.Incidence`) change nothing: given, they are refused in one
line, alike by ``simulate``, ``sweep``, the run file and the command line.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from fem_racket.impact.incidence import Incidence
from fem_racket.validation import InputError, show

__all__ = ["COMPONENTS", "CONTACT_FIELDS", "refuse_idle_contact", "refuse_idle_incidence"]

#: The incidence's components: any of them nonzero makes the ball oblique or spinning.
COMPONENTS = ("angle", "spin", "side_angle", "side_spin")
#: The tangential contact's parameters (the Incidence's fields): on a head-on, spinless ball no
#: tangential force acts, so they change nothing.
CONTACT_FIELDS = ("friction", "ball_inertia", "radius", "compliance_ratio")


def refuse_idle_contact(values: Mapping[str, Any]) -> None:
    """Refuse a tangential contact parameter given without an oblique or spinning ball: it would
    change nothing (never silently ignored).

    Parameters
    ----------
    values : mapping
        What the caller was given, by its names: :data:`COMPONENTS` ([deg], [rpm]; a number or
        a sweep's values) and the contact parameters (any other name: friction [-], I/(m R^2)
        [-], ball radius [m], compliance ratio [-]); None: not given.
    """
    import numpy as np  # here: ``fem-racket simulate --help`` imports this module, not numpy

    for name in COMPONENTS:
        value = values.get(name)
        if value is not None and np.any(np.asarray(value, dtype=float) != 0.0):
            return
    for name, value in values.items():
        if name not in COMPONENTS and value is not None:
            raise InputError(
                f"{name} = {show(value)} is not allowed without an oblique or spinning ball: "
                "give angle, spin (or their side components)",
                parameter=name,
                value=value,
            )


def refuse_idle_incidence(incidence: object) -> None:
    """:func:`refuse_idle_contact` for an :class:`Incidence` (a contact parameter counts as given
    away from its default); anything else passes (:func:`check_incidence` refuses it)."""
    if isinstance(incidence, Incidence):
        default = Incidence()
        values = {n: getattr(incidence, n) for n in (*COMPONENTS, *CONTACT_FIELDS)}
        given = {n: v for n, v in values.items() if n in COMPONENTS or v != getattr(default, n)}
        refuse_idle_contact(given)
