"""Catalogue targets from text (``customise``, ``closest``, on the command line and in a run
file's table): a value ``330``, a range ``320:335`` or ``keep`` (as the racket is now), in the
command's units (kg cm^2, m, kg, Hz, RA), as :class:`~fem_racket.studies.customise.Target` in SI.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from fem_racket.studies.customise import Target
from fem_racket.studies.targets import KEEP, RANKED, TARGETS
from fem_racket.validation import InputError, work_begins

__all__ = [
    "KEEP",
    "RANKED",
    "TARGETS",
    "parse_target",
    "place_list",
    "target_summary",
    "targets_from",
]


def parse_target(text: Any) -> tuple[float, float] | str:
    """``VALUE``, ``LOW:HIGH`` (the command's units) -> (low, high), or :data:`KEEP`.

    Raises
    ------
    ValueError
        For anything else, saying what is allowed.
    """
    if str(text).strip() == KEEP:
        return KEEP
    try:
        values = [float(w) for w in str(text).split(":")]
    except ValueError:
        values = []
    if len(values) not in (1, 2):
        raise ValueError(f"{text!r} must be a value or a range LOW:HIGH")
    return values[0], values[-1]


def targets_from(values: Mapping[str, Any], now: Any = None) -> dict[str, Target]:
    """dest -> :class:`Target` (SI) of every target ``values`` gives (parsed by
    :func:`parse_target`, None: not given); ``keep`` is the value of ``now`` (the racket's
    :class:`~fem_racket.frame.catalogue.Catalogue`).

    Raises
    ------
    InputError
        For ``keep`` without a value, a range not 0 < LOW <= HIGH, or no target at all (after
        :func:`~fem_racket.validation.work_begins`: targets may come with the command line).
    """
    out = {}
    for dest, (_, _, factor, _) in {**TARGETS, **RANKED}.items():
        value = values.get(dest)
        if value is None:
            continue
        if value == KEEP:
            held = None if now is None else getattr(now, dest)
            if held is None:
                why = "this racket has no value for it" if now is not None else "give a value"
                raise InputError(f"{dest.replace('_', '-')} = keep is not allowed here: {why}")
            out[dest] = Target(held, held)
            continue
        try:
            out[dest] = Target(value[0] * factor, value[1] * factor)
        except InputError:
            raise InputError(
                f"{dest.replace('_', '-')} = {value[0]:g}:{value[1]:g} is not allowed: "
                "need 0 < LOW <= HIGH"
            ) from None
    if not out:
        work_begins()  # targets may come with the command line; a run file's checks end here
        names = [d for d in {**TARGETS, **RANKED} if d in values]
        raise InputError(
            "targets = none is not allowed: give at least one of "
            + ", ".join("--" + d.replace("_", "-") for d in names)
        )
    return out


def place_list(text: str) -> list[str]:
    """The places of a comma list (``"12,3/9,handle"``)."""
    return [p.strip() for p in text.split(",") if p.strip()]


def target_summary(targets: Mapping[str, Target]) -> dict[str, list[float]]:
    """JSON-ready [low, high] of each target, units in the keys."""
    spec = {**TARGETS, **RANKED}
    return {spec[k][3]: [t.low / spec[k][2], t.high / spec[k][2]] for k, t in targets.items()}
