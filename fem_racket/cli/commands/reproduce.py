"""``fem-racket reproduce``: every figure of the paper, its data, and REPRODUCTION.md; with
``--law NAME`` the figures redrawn with a contact law and its report, in their own folder.

Compute every figure of the paper, write its data (CSV) and figure (PNG, SVG or PDF) into --out,
and write the side-by-side report --report (image links relative to it). Files an earlier run
wrote are replaced (recognised by their provenance); any other existing file needs --overwrite.
With --law NAME the figures are drawn with that contact law instead of the paper's linear K_CB
and the report says which of the paper's conclusions (1)-(4) still hold and how the contact times
compare with the paper's 6-3 ms. About 15 s on a quiet 2-core machine (--law
kawazoe-1997-nonlinear: about 20 s), several times that under load.
"""

from __future__ import annotations

import argparse
import time

from fem_racket.cli.common import add_config_option, run_parameters
from fem_racket.cli.options.drawing import add_figure_options, add_quiet_option, progress_of
from fem_racket.cli.options.laws import add_law_options, law_from_args
from fem_racket.paper.constants import DEFAULT_OUT, DEFAULT_REPORT


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``reproduce`` command's options."""
    p.add_argument(
        "--out",
        default=None,
        metavar="DIR",
        help=f"output folder for figures and data (default {DEFAULT_OUT}/, with --law "
        f"{DEFAULT_OUT}/NAME/)",
    )
    p.add_argument(
        "--report",
        default=None,
        metavar="FILE",
        help=f"output file: the Markdown report (default {DEFAULT_REPORT} in the current folder, "
        f"with --law {DEFAULT_REPORT} in --out)",
    )
    p.add_argument("--quick", action="store_true", help="coarse grids (~8 s; for tests)")
    p.add_argument(
        "--overwrite",
        action="store_true",
        help="also replace existing files this command did not write (its own are replaced anyway)",
    )
    add_law_options(p)
    add_figure_options(p)
    add_quiet_option(p)
    # The paper's parameters are fixed: only [reproduce] (and output.overwrite) apply.
    add_config_option(p, private=("out",))


def run(args: argparse.Namespace) -> int:
    """Run the reproduction and print one line per figure and the verdict counts."""
    from fem_racket.paper.reproduce import reproduce

    law = law_from_args(args)
    out, report = args.out, args.report = _destinations(args)  # recorded as used
    t0 = time.perf_counter()
    result = reproduce(
        out,
        report,
        quick=args.quick,
        overwrite=args.overwrite,
        parameters=run_parameters(args),
        fmt=args.format or "png",
        dpi=args.dpi,
        progress=progress_of(args),
        law=law,
    )
    total = time.perf_counter() - t0
    print(f"{'figure':<10} {'time [s]':>9}  files")
    for key, sec in result.seconds.items():
        names = [p.name for p in result.files if p.name.startswith(key[:5])]
        print(f"{key:<10} {sec:>9.2f}  {', '.join(names)}")
    counts = result.counts()
    if law is None:
        print(
            f"wrote {report} ({len(result.claims)} statements: {counts['agrees']} agree, "
            f"{counts['differs']} differ, {counts['not checkable']} not checkable)"
        )
    else:
        held = sum(c.verdict == "agrees" for c in result.claims[:4])
        print(f"wrote {report} ({held} of the paper's 4 conclusions hold under {args.law})")
    print(f"wrote {out}/ ({len(result.files)} files; {total:.1f} s in all)")
    return 0


def _destinations(args: argparse.Namespace) -> tuple[str, str]:
    """--out and --report, defaulted (:func:`fem_racket.paper.config_reproduce.destinations`)."""
    from fem_racket.paper.config_reproduce import destinations

    return destinations(args.law, args.out, args.report)
