"""Options of the commands that draw figures or run long: ``--format``, ``--dpi``, ``--quiet``.

- ``--format png|svg|pdf`` and ``--dpi N`` (default 150): every command that draws a figure
  (``reproduce``, ``refine``), as the figure scripts (:mod:`fem_racket.io.figure_files`);
- ``--quiet``: no progress bar on stderr (there is none anyway when stderr is not a terminal;
  :mod:`fem_racket.progress`).
"""

from __future__ import annotations

import argparse

from fem_racket.io.figure_files import DEFAULT_DPI, FIGURE_FORMATS

__all__ = ["add_figure_options", "add_quiet_option", "progress_of"]


def add_figure_options(group: argparse._ArgumentGroup, what: str = "figures") -> None:
    """``--format`` and ``--dpi`` of the ``what`` a command draws."""
    group.add_argument(
        "--format",
        default=None,
        choices=FIGURE_FORMATS,
        help=f"format of the {what}: png, or svg and pdf (vector) (default png)",
    )
    group.add_argument(
        "--dpi",
        type=float,
        default=DEFAULT_DPI,
        metavar="N",
        help=f"resolution of the {what} [dots per inch], 50..1200 (default {DEFAULT_DPI})",
    )


def add_quiet_option(group: argparse._ArgumentGroup | argparse.ArgumentParser) -> None:
    """``--quiet``: no progress bar."""
    group.add_argument(
        "--quiet", action="store_true", help="no progress bar on stderr (shown on a terminal)"
    )


def progress_of(args: argparse.Namespace) -> bool | None:
    """The library's ``progress`` argument: False with ``--quiet``, else None (a bar when stderr
    is a terminal)."""
    return False if getattr(args, "quiet", False) else None
