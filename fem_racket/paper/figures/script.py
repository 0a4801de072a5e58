"""The shared start of the figure scripts in ``scripts/``: :func:`figure_main` parses, computes
and writes one of the paper's figures; :func:`figure_script_options` starts a script that draws
its own figure."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from fem_racket.io.figure_files import DEFAULT_DPI, FIGURE_FORMATS
from fem_racket.outputs import OutputError
from fem_racket.validation import InputError

__all__ = ["figure_main", "figure_script_options"]


def figure_main(
    key: str,
    description: str,
    argv: Sequence[str] | None,
    default_out: str,
    runtime: str = "",
) -> list[Path]:
    """Run figure ``key`` with options ``--out DIR --quick --overwrite --format --dpi``; return
    the files. ``runtime`` (e.g. ``"~3 s here; --quick ~2 s"``) ends the ``--help`` text.

    Bad input (a destination that cannot be written included) prints one line on stderr and
    exits with code 2; an output that cannot be written during the run (a full disk) one line
    and code 1, nothing left behind.
    """
    from fem_racket.paper.figures import make_figure

    ap = argparse.ArgumentParser(
        description=description, epilog=f"Run time: {runtime}." if runtime else None
    )
    ap.add_argument(
        "--out", default=default_out, metavar="DIR", help=f"output folder (default {default_out}/)"
    )
    ap.add_argument(
        "--quick", action="store_true", help="coarse grids (for tests; numbers approximate)"
    )
    ap.add_argument("--overwrite", action="store_true", help="replace existing files")
    ap.add_argument(
        "--format",
        default="png",
        choices=FIGURE_FORMATS,
        help="figure format (default png; svg and pdf are vector)",
    )
    ap.add_argument(
        "--dpi",
        type=float,
        default=DEFAULT_DPI,
        help=f"resolution [dots per inch] of a PNG (default {DEFAULT_DPI})",
    )
    args = ap.parse_args(argv)
    try:
        _, paths = make_figure(
            key,
            args.out,
            quick=args.quick,
            overwrite=args.overwrite,
            fmt=args.format,
            dpi=args.dpi,
        )
    except InputError as exc:
        print(f"{Path(sys.argv[0]).name}: error: {exc}", file=sys.stderr)
        raise SystemExit(2) from None
    except OutputError as exc:
        print(f"{Path(sys.argv[0]).name}: error: {exc.strerror}", file=sys.stderr)
        raise SystemExit(1) from None
    for p in paths:
        print(p)
    return paths


def figure_script_options(
    description: str, default_out: str, argv: Sequence[str] | None
) -> argparse.Namespace:
    """The options of a script drawing one figure of its own, parsed from ``argv``: ``--out
    FILE`` (default ``default_out``), ``--quick``, ``--overwrite`` and ``--dpi N`` (default
    :data:`~fem_racket.io.figure_files.DEFAULT_DPI`). Selects matplotlib's Agg backend (the
    scripts only write files), so the script imports ``matplotlib.pyplot`` after this call."""
    import matplotlib

    matplotlib.use("Agg")
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--out", default=default_out)
    p.add_argument("--quick", action="store_true")
    p.add_argument("--overwrite", action="store_true")
    p.add_argument("--dpi", type=float, default=DEFAULT_DPI)
    return p.parse_args(argv)
