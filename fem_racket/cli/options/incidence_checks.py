"""The checks of the oblique options of ``fem-racket simulate`` that need the parsed options
(:mod:`fem_racket.cli.options.oblique`): the contact's options without an oblique or spinning
ball, and an angle leaving the ball's normal speed below the paper's K_CB speeds."""

from __future__ import annotations

import argparse

from fem_racket.cli.options.runfile import given_options
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.incidence_idle import COMPONENTS, refuse_idle_contact

__all__ = ["check_normal_speed", "refuse_idle_options"]


def refuse_idle_options(args: argparse.Namespace, fields: dict[str, str]) -> None:
    """Refuse the contact's options given without an oblique or spinning ball
    (:func:`~fem_racket.impact.incidence_idle.refuse_idle_contact`): on the command line at any
    value, in the run file away from the Incidence's default. ``fields``: each oblique option's
    argparse dest -> its Incidence field."""
    cli, default = set(getattr(args, "explicit_options", ())) | set(COMPONENTS), Incidence()
    refuse_idle_contact(
        {
            dest: getattr(args, dest)
            for dest, field in fields.items()
            if dest in cli
            or (dest in given_options(args) and getattr(args, dest) != getattr(default, field))
        }
    )


def check_normal_speed(args: argparse.Namespace, incidence: Incidence) -> None:
    """Refuse an ``--angle`` (or ``--side-angle``) that leaves the ball's normal speed below the
    paper's K_CB range when K_CB follows from it (no --kcb, no --law, no string bed, the
    racket at rest; :func:`~fem_racket.impact.incidence.check_kcb_normal`), before the work."""
    from fem_racket.impact.incidence import check_kcb_normal
    from fem_racket.strings.options import STRING_OPTIONS

    own_kcb = getattr(args, "kcb", None) is not None or getattr(args, "law", None) != "linear"
    bed = any(getattr(args, d, None) not in (None, False) for d in STRING_OPTIONS)
    if not (own_kcb or bed or getattr(args, "racket_speed", 0.0) != 0.0):
        check_kcb_normal(incidence, args.speed)
