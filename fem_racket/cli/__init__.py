"""Command-line interface ``fem-racket``: thin wrappers that parse, call the library, print.

Each sub-command lives in its own module exposing ``register(subparsers)``; the parser sets
``args.func(args) -> int``. Bad input prints one line to stderr and exits with code 2. When the
reader of the output goes away (``fem-racket modes | head -1``) the command stops quietly with
exit code 141 (128 + SIGPIPE, what a Unix tool killed by SIGPIPE returns), files it wrote
already being complete.
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
from collections.abc import Sequence

from fem_racket.cli import (
    config,
    fit,
    map,
    modes,
    optimize,
    refine,
    reproduce,
    sensitivity,
    simulate,
    sweep,
    vtk,
)
from fem_racket.cli.common import OneLineErrorParser, apply_config
from fem_racket.validation import InputError
from fem_racket.version import __version__

__all__ = ["main"]

#: Sub-command modules, in the order ``--help`` lists them.
COMMANDS = (simulate, modes, sweep, map, fit, vtk, refine, reproduce, optimize, sensitivity, config)


def build_parser() -> argparse.ArgumentParser:
    """The top-level parser with every sub-command registered."""
    parser = OneLineErrorParser(
        prog="fem-racket",
        description="Finite-element simulation of a tennis ball striking a racket frame "
        "(Kawazoe & Kanda 1997).",
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    parser.add_argument("-v", "--verbose", action="store_true", help="log progress to stderr")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for module in COMMANDS:
        module.register(sub)
    return parser


#: Exit code when stdout's reader has gone (128 + SIGPIPE, as the shell reports a killed tool).
EXIT_BROKEN_PIPE = 141


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; returns the exit code (0 ok, 2 bad input, 141 output pipe closed)."""
    try:
        code = _run(argv)
        sys.stdout.flush()  # a closed pipe shows here, not at interpreter exit
        return code
    except BrokenPipeError:
        try:  # later writes (the interpreter's final flush) go nowhere
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
        except (OSError, ValueError):  # stdout without a file descriptor (e.g. captured)
            pass
        return EXIT_BROKEN_PIPE


def _run(argv: Sequence[str] | None) -> int:
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on usage errors, 0 on --help
        return int(exc.code or 0)
    logging.basicConfig(
        level=logging.INFO if args.verbose else logging.WARNING, format="%(message)s"
    )
    try:
        args = apply_config(parser, argv, args)
        return int(args.func(args))
    except InputError as exc:
        print(f"fem-racket {args.command}: error: {exc}", file=sys.stderr)
        return 2
