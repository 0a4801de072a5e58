"""Where a design study's designs run, on the command line (``optimize``, ``sensitivity``):
--backend, --workers, --scheduler, --seed, and --quiet (no progress bar)."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from fem_racket.cli.options.drawing import progress_of
from fem_racket.cli.options.fields import options_from_args
from fem_racket.studies.backends import BACKENDS

if TYPE_CHECKING:
    from fem_racket.studies.design.options import ExecutionOptions

__all__ = ["add_run_options", "execution_from_args"]


def add_run_options(parser: argparse.ArgumentParser) -> None:
    """Where designs run: --backend, --workers, --scheduler, --seed."""
    g = parser.add_argument_group("execution")
    g.add_argument(
        "--backend",
        choices=BACKENDS,
        default=None,
        help="serial, processes or dask (default: processes for batches of 8+ designs)",
    )
    g.add_argument("--workers", type=int, default=None, help="processes (default: all cores)")
    g.add_argument(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help="Dask scheduler tcp://HOST:PORT (default none)",
    )
    g.add_argument(
        "--seed",
        type=int,
        default=1,
        help="random seed: an integer from 0 to 4294967295 (default 1); optimize "
        "takes it with differential-evolution and nsga2",
    )


def execution_from_args(args: argparse.Namespace) -> ExecutionOptions:
    """Where the designs run (--backend, --workers, --scheduler) and whether a progress bar
    shows (``--quiet``)."""
    from fem_racket.studies.design.options import ExecutionOptions

    return options_from_args(args, ExecutionOptions, progress=progress_of(args))
