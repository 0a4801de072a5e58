"""Catalogue targets on the command line (``customise``, ``closest``): ``--swing-weight 330``
or a range ``--swing-weight 320:335``, likewise ``--balance``, ``--twist-weight``, ``--mass``
(and, for ranking only, ``--f1`` and ``--stiffness-ra``), and ``--places``."""

from __future__ import annotations

import argparse
from typing import Any

from fem_racket.frame.clock import PLACES
from fem_racket.frame.specs import KG_CM2
from fem_racket.studies.customise import Target
from fem_racket.validation import InputError, work_begins

__all__ = [
    "RANKED",
    "TARGETS",
    "add_target_options",
    "places_of",
    "target_summary",
    "targets_from_args",
]

#: Targets lead can meet: dest -> (metavar, help, factor to SI, JSON key).
TARGETS = {
    "swing_weight": (
        "KG_CM2",
        "swing weight about 0.10 m from the butt [kg cm^2]",
        KG_CM2,
        "swing_weight_kg_cm2",
    ),
    "balance": ("M", "balance point from the butt [m]", 1.0, "balance_m"),
    "twist_weight": (
        "KG_CM2",
        "twistweight, polar moment about the long axis [kg cm^2]",
        KG_CM2,
        "twist_weight_kg_cm2",
    ),
    "mass": ("KG", "mass [kg]", 1.0, "mass_kg"),
}
#: Targets only ranked on (closest).
RANKED = {
    "f1": ("HZ", "first free-free frequency [Hz]", 1.0, "f1_hz"),
    "stiffness_ra": ("RA", "stiffness [RA]", 1.0, "stiffness_ra"),
}


#: The target value meaning "as the racket is now".
KEEP = "keep"


def _range(text: str) -> tuple[float, float] | str:
    """``VALUE``, ``LOW:HIGH`` -> (low, high), or ``keep``."""
    if str(text).strip() == KEEP:
        return KEEP
    try:
        values = [float(w) for w in str(text).split(":")]
    except ValueError:
        values = []
    if len(values) not in (1, 2):
        raise argparse.ArgumentTypeError(f"{text!r} must be a value or a range LOW:HIGH")
    return values[0], values[-1]


def add_target_options(parser: argparse.ArgumentParser, *, ranked: bool = False) -> None:
    """The target options (with ``ranked``: also --f1 and --stiffness-ra) and --places."""
    g = parser.add_argument_group("targets (at least one)")
    for dest, (metavar, text, _, _) in {**TARGETS, **(RANKED if ranked else {})}.items():
        g.add_argument(
            "--" + dest.replace("_", "-"),
            type=_range,
            default=None,
            metavar=metavar,
            help=f"{text}: a value, LOW:HIGH"
            + ("" if ranked else " or keep (as it is)")
            + " (default: free)",
        )
    g.add_argument(
        "--places",
        default=",".join(PLACES),
        metavar="LIST",
        help="comma list of places the lead may go: " + ", ".join(PLACES) + " or distances "
        f"from the butt in m (default {','.join(PLACES)})",
    )


def targets_from_args(args: argparse.Namespace, now: Any = None) -> dict[str, Target]:
    """dest -> :class:`Target` (SI) of every target option given; ``keep`` is the value of
    ``now`` (the racket's :class:`~fem_racket.frame.catalogue.Catalogue`)."""
    out = {}
    for dest, (_, _, factor, _) in {**TARGETS, **RANKED}.items():
        value = getattr(args, dest, None)
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
        names = [d for d in {**TARGETS, **RANKED} if hasattr(args, d)]
        raise InputError(
            "targets = none is not allowed: give at least one of "
            + ", ".join("--" + d.replace("_", "-") for d in names)
        )
    return out


def places_of(args: argparse.Namespace) -> list[str]:
    """The --places list."""
    return [p.strip() for p in args.places.split(",") if p.strip()]


def target_summary(targets: dict[str, Target]) -> dict[str, list[float]]:
    """JSON-ready [low, high] of each target, units in the keys."""
    spec = {**TARGETS, **RANKED}
    return {spec[k][3]: [t.low / spec[k][2], t.high / spec[k][2]] for k, t in targets.items()}
