"""``--law NAME`` and each law's parameters, shared by the commands that run an impact.

The names are :data:`fem_racket.contact.presets.LAW_NAMES`: ``linear`` (the paper's, from
--kcb and --zeta), the families ``hunt-crossley``, ``hysteretic`` and ``series`` (their defaults
overridden by their options) and the calibrated presets such as ``kawazoe-1997-nonlinear``.
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from fem_racket.cli.options.runfile import option_name
from fem_racket.validation import InputError, show

if TYPE_CHECKING:
    from fem_racket.contact.law import ContactLaw

__all__ = ["add_law_options", "law_from_args"]


def add_law_options(parser: argparse.ArgumentParser, *, swept: bool = False) -> None:
    """--law and one option per declared family parameter (``--hc-alpha``, ``--k1`` ...: the
    registry's, :mod:`fem_racket.contact.registry`); ``swept``: each takes sweep values (a
    number, a comma list or start:stop:num[:log]) as text. The registry (its laws' classes, with
    numpy) is imported here, when a command taking a law builds its parser."""
    from fem_racket.contact.registry import LAW_NAMES, family_parameters

    g = parser.add_argument_group("contact law")
    g.add_argument(
        "--law",
        default="linear",
        choices=LAW_NAMES,
        help="ball/string law: linear (the paper's K_CB, zeta; default), a family with its "
        "options below, or a calibrated preset",
    )
    for family, declared in family_parameters().items():
        for p in declared:
            g.add_argument(
                p.option,
                dest=p.name,
                type=str if swept else float,
                default=None,
                metavar="VALUES" if swept else "X",
                help=f"{family}: {p.name} [{p.unit}]{', swept or fixed' if swept else ''} "
                f"(default {p.default:.4g}; allowed {p.interval()})",
            )


def law_from_args(args: argparse.Namespace) -> ContactLaw | None:
    """The law the options describe (None: the paper's linear law from --kcb and --zeta);
    --kcb or --zeta with another law is refused (that law would ignore them), named as the user
    gave it (a run file's ``contact.kcb_n_m``, ``zeta`` or ``clamped_cor`` by its key); likewise
    a run file's law parameter the law does not take (``contact.hc_alpha_s_m`` with a preset)."""
    from fem_racket.contact.presets import FAMILIES, check_linear_options, get_law, law_parameters

    name = getattr(args, "law", "linear")
    kcb, zeta = getattr(args, "kcb", None), getattr(args, "zeta", None)
    if name != "linear":
        for dest in ("kcb", "zeta"):
            if dest in getattr(args, "file_options", {}) and getattr(args, dest) is not None:
                raise InputError(
                    f"{option_name(args, dest)} is not allowed with contact law {show(name)}: "
                    "it sets the paper's linear law's K_CB and zeta only"
                )
    check_linear_options(name, kcb=kcb, zeta=zeta)
    params = law_parameters(vars(args))
    family = FAMILIES.get(name)
    takes = sorted(p.name for p in family.declared) if family is not None else []
    why = f"must be one of {takes}" if takes else "it takes no law parameter (a preset)"
    if name == "linear":
        why = "it takes no law parameter (the paper's law is built from kcb and zeta)"
    for dest in getattr(args, "file_options", {}):
        if params.get(dest) is not None and dest not in takes:  # named by its run-file key
            raise InputError(
                f"{option_name(args, dest)} is not allowed with law {show(name)}: {why}"
            )
    return get_law(name, **params)
