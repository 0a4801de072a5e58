"""Catalogue targets on the command line (``customise``, ``closest``): ``--swing-weight 330``
or a range ``--swing-weight 320:335``, likewise ``--balance``, ``--twist-weight``, ``--mass``
(and, for ranking only, ``--f1`` and ``--stiffness-ra``), and ``--places``."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from fem_racket.frame.constants import PLACES
from fem_racket.studies.targets import RANKED, TARGETS

if TYPE_CHECKING:
    from fem_racket.studies.customise import Target

__all__ = [
    "RANKED",
    "TARGETS",
    "add_target_options",
    "places_of",
    "target_summary",
    "targets_from_args",
]


def _range(text: str) -> tuple[float, float] | str:
    """``VALUE``, ``LOW:HIGH`` -> (low, high), or ``keep``
    (:func:`fem_racket.studies.target_values.parse_target`)."""
    from fem_racket.studies.target_values import parse_target

    try:
        return parse_target(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


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
    from fem_racket.studies.target_values import targets_from

    return targets_from(vars(args), now)


def places_of(args: argparse.Namespace) -> list[str]:
    """The --places list."""
    from fem_racket.studies.target_values import place_list

    return place_list(args.places)


def target_summary(targets: dict[str, Target]) -> dict[str, list[float]]:
    """JSON-ready [low, high] of each target, units in the keys
    (:func:`fem_racket.studies.target_values.target_summary`)."""
    from fem_racket.studies.target_values import target_summary as summary

    return summary(targets)
