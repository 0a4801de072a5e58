"""Lead tape on the command line: ``--add-mass LOCATION:GRAMS`` (repeatable) on every command
that takes a racket, or a run file's ``[[frame.lead]]`` tables (``place``, ``mass_g``).

``--add-mass 3/9:10 --add-mass 0.32:5`` puts 10 g at 3 and 9 o'clock (5 g each side) and 5 g at
0.32 m from the butt (:mod:`fem_racket.frame.lead`; places :data:`fem_racket.frame.clock.PLACES`).
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from fem_racket.frame.constants import PLACES
from fem_racket.validation import InputError

if TYPE_CHECKING:
    from fem_racket.frame.lead import Lead
    from fem_racket.frame.mesh import FrameMesh
    from fem_racket.frame.segments import Frame

__all__ = ["add_lead_option", "leads_of", "with_lead"]


def _lead(text: str) -> Lead:
    from fem_racket.frame.lead import parse_lead

    try:
        return parse_lead(text)
    except InputError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


class _Append(argparse.Action):
    """Collect every use of the option (argparse's ``append`` would extend a run file's list)."""

    def __call__(self, parser, namespace, values, option_string=None) -> None:  # noqa: D102
        old = getattr(namespace, self.dest, None)
        setattr(namespace, self.dest, (old if isinstance(old, list) else []) + [values])


def add_lead_option(group: Any) -> None:
    """``--add-mass LOCATION:GRAMS`` (repeatable) on a parser or an argument group."""
    group.add_argument(
        "--add-mass",
        dest="add_mass",
        action=_Append,
        type=_lead,
        default=None,
        metavar="LOCATION:GRAMS",
        help="lead tape: GRAMS at LOCATION, one of " + ", ".join(PLACES) + " (clock places on "
        "a ~645 cm^2 head; 3/9, 2/10, 4/8 put half on each side) or a distance from the butt "
        "in m; repeatable: --add-mass 3/9:10 --add-mass 0.32:5 (default: none)",
    )


def leads_of(args: argparse.Namespace) -> list[Lead]:
    """The leads the options (or the run file's ``[[frame.lead]]``) give."""
    return list(getattr(args, "add_mass", None) or [])


def with_lead(frame: Frame | FrameMesh, args: argparse.Namespace, elements: int) -> Any:
    """``frame`` with the options' leads (a :class:`Frame` meshed with ``elements`` cells
    first); ``frame`` itself when there are none."""
    from fem_racket.frame.head import DEFAULT_HEAD
    from fem_racket.frame.lead import add_lead
    from fem_racket.frame.mesh import frame_mesh
    from fem_racket.frame.segments import Frame

    leads = leads_of(args)
    if not leads:
        return frame
    mesh = frame_mesh(frame, elements) if isinstance(frame, Frame) else frame
    return add_lead(mesh, leads, DEFAULT_HEAD.on_frame(mesh.length))
