"""``--law NAME`` and each law's parameters, shared by the commands that run an impact.

The names are :data:`fem_racket.contact.presets.LAW_NAMES`: ``linear`` (the paper's, from
--kcb and --zeta), the families ``hunt-crossley``, ``hysteretic`` and ``series`` (their defaults
overridden by their options) and the calibrated presets such as ``kawazoe-1997-nonlinear``.
"""

from __future__ import annotations

import argparse

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.presets import FAMILY_PARAMETERS, LAW_NAMES, get_law, law_parameters

__all__ = ["add_law_options", "law_from_args"]


def add_law_options(parser: argparse.ArgumentParser, *, swept: bool = False) -> None:
    """--law and one option per family parameter (``--hc-alpha``, ``--k1`` ...); ``swept``:
    each takes sweep values (a number, a comma list or start:stop:num[:log]) as text."""
    g = parser.add_argument_group("contact law")
    g.add_argument(
        "--law",
        default="linear",
        choices=LAW_NAMES,
        help="ball/string law: linear (the paper's K_CB, zeta; default), a family with its "
        "options below, or a calibrated preset",
    )
    for family, spec in FAMILY_PARAMETERS.items():
        for name, (unit, default) in spec.items():
            g.add_argument(
                f"--{name.replace('_', '-')}",
                dest=name,
                type=str if swept else float,
                default=None,
                metavar="VALUES" if swept else "X",
                help=f"{family}: {name} [{unit}]{', swept or fixed' if swept else ''} "
                f"(default {default:.4g})",
            )


def law_from_args(args: argparse.Namespace) -> ContactLaw | None:
    """The law the options describe (None: the paper's linear law from --kcb and --zeta)."""
    return get_law(getattr(args, "law", "linear"), **law_parameters(vars(args)))
