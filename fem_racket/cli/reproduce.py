"""``fem-racket reproduce``: every figure of the paper, its data, and REPRODUCTION.md."""

from __future__ import annotations

import argparse
import time

from fem_racket.cli.common import add_config_option, run_parameters
from fem_racket.cli.drawing import add_figure_options, add_quiet_option, progress_of

DEFAULT_OUT = "output/paper"
DEFAULT_REPORT = "REPRODUCTION.md"


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``reproduce`` command."""
    p = sub.add_parser(
        "reproduce",
        help="reproduce every figure of Kawazoe & Kanda (1997) and write REPRODUCTION.md",
        description="Compute every figure of the paper, write its data (CSV) and figure (PNG, "
        "SVG or PDF) into --out, and write the side-by-side report --report (image links "
        "relative to it). Files an earlier run wrote are replaced (recognised by their "
        "provenance); any other existing file needs --overwrite. About 15 s here.",
    )
    p.add_argument(
        "--out",
        default=DEFAULT_OUT,
        metavar="DIR",
        help=f"output folder for figures and data (default {DEFAULT_OUT}/)",
    )
    p.add_argument(
        "--report",
        default=DEFAULT_REPORT,
        metavar="FILE",
        help=f"output file: the Markdown report (default {DEFAULT_REPORT} in the current folder)",
    )
    p.add_argument("--quick", action="store_true", help="coarse grids (~8 s; for tests)")
    p.add_argument(
        "--overwrite",
        action="store_true",
        help="also replace existing files this command did not write (its own are replaced anyway)",
    )
    add_figure_options(p)
    add_quiet_option(p)
    # The paper's parameters are fixed: only [reproduce] (and output.overwrite) apply.
    add_config_option(p, private=("out",))
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Run the reproduction and print one line per figure and the verdict counts."""
    from fem_racket.paper.reproduce import reproduce

    t0 = time.perf_counter()
    result = reproduce(
        args.out,
        args.report,
        quick=args.quick,
        overwrite=args.overwrite,
        parameters=run_parameters(args),
        fmt=args.format or "png",
        dpi=args.dpi,
        progress=progress_of(args),
    )
    total = time.perf_counter() - t0
    print(f"{'figure':<10} {'time [s]':>9}  files")
    for key, sec in result.seconds.items():
        names = [p.name for p in result.files if p.name.startswith(key[:5])]
        print(f"{key:<10} {sec:>9.2f}  {', '.join(names)}")
    counts = result.counts()
    print(
        f"report: {args.report} ({len(result.claims)} statements: {counts['agrees']} agree, "
        f"{counts['differs']} differ, {counts['not checkable']} not checkable)"
    )
    print(f"total: {total:.1f} s, output in {args.out}/")
    return 0
