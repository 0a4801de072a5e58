"""Command-line interface ``fem-racket``: thin wrappers that parse, call the library, print.

Each sub-command is a :class:`~fem_racket.cli.parser.Command` of
:data:`fem_racket.cli.commands.COMMANDS` (its name and summary) whose module adds its options
and runs it; the parser sets ``args.func(args) -> int``.
Whatever goes wrong ends in one line on stderr, never a traceback:

======  ==========================================================================================
exit    when
======  ==========================================================================================
0       done
1       a fault during the run: an output could not be written (no space left, I/O error), or
        standard output failed (``> /dev/full``); no partial output is left
2       bad input: a value, a run file, a mesh file or a destination (checked before any work)
130     interrupted by SIGINT (Ctrl-C); 143 by SIGTERM: the same cleanup (temporaries removed,
        worker processes ended, a sweep's checkpoint kept: the line says how many cases it holds);
        no output is moved into place after the signal
141     the reader of standard output went away before everything was written
        (``fem-racket modes | head -1``); files already written are complete
======  ==========================================================================================

Standard output closed (``fem-racket modes >&-``) is refused before any work (exit 2).
"""

from __future__ import annotations

import argparse
import atexit
import gc
import logging
import os
import sys
from collections.abc import Sequence
from typing import Any

from fem_racket.cli.commands import COMMANDS
from fem_racket.cli.options.runfile import apply_config
from fem_racket.cli.options.runfile_named import named_by_file
from fem_racket.cli.parser import OneLineErrorParser
from fem_racket.cli.signals import (
    GuardedStdout,
    StdoutFault,
    Terminated,
    received,
    signal_handlers,
    silence_stdout,
)
from fem_racket.outputs import OutputError
from fem_racket.validation import InputError, show

__all__ = ["main"]


def _command_named(argv: Sequence[str]) -> str | None:
    """The sub-command ``argv`` runs: its first word that is not a top-level option, if that is
    a command's name (the top-level options take no value)."""
    for word in argv:
        if word == "--":
            return None
        if not word.startswith("-"):
            return word if word in COMMANDS else None
    return None


class _Version(argparse.Action):
    """``--version``: print ``fem-racket VERSION`` and exit 0; the version (installed metadata,
    slow to import) is looked up only then."""

    def __init__(self, option_strings: Sequence[str], dest: str, **kwargs: Any) -> None:
        super().__init__(option_strings, dest=argparse.SUPPRESS, nargs=0, **kwargs)

    def __call__(self, parser: argparse.ArgumentParser, *args: Any) -> None:
        from fem_racket.version import __version__

        print(f"{parser.prog} {__version__}")
        parser.exit()


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The top-level parser.

    Every sub-command is registered in full, unless ``argv`` (the arguments about to be parsed)
    is given: then only the command it names, so a command starts without importing the others'
    libraries; naming none (``--help``, a mistyped name or none), every command by its name and
    summary only, without importing any command's module.
    """
    parser = OneLineErrorParser(
        prog="fem-racket",
        description="Finite-element simulation of a tennis ball striking a racket frame "
        "(Kawazoe & Kanda 1997).",
    )
    parser.add_argument("--version", action=_Version, help="show the version and exit")
    parser.add_argument("-v", "--verbose", action="store_true", help="log progress to stderr")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    named = None if argv is None else _command_named(argv)
    if named:
        COMMANDS[named].add(sub)
    else:
        for command in COMMANDS.values():
            command.add(sub, full=argv is None)
    for command in sub.choices.values():  # -v also after the command name
        command.add_argument(
            "-v",
            "--verbose",
            action="store_true",
            default=argparse.SUPPRESS,
            help="log progress to stderr",
        )
    return parser


#: Exit codes besides 0 (see the module docstring).
EXIT_FAULT, EXIT_INPUT, EXIT_SIGINT, EXIT_BROKEN_PIPE, EXIT_SIGTERM = 1, 2, 130, 141, 143


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; returns the exit code (see the module docstring). Run as the command
    (``argv`` None: the console script, ``python -m fem_racket``), its process ends without
    the collector's passes over every object (:func:`_end_lightly`)."""
    if argv is None:
        atexit.register(_end_lightly)
    if sys.stdout is None:  # started with stdout closed: Python has no stream for it
        print(
            "fem-racket: error: standard output is closed: give it a file, a pipe or /dev/null "
            "(> /dev/null)",
            file=sys.stderr,
        )
        return EXIT_INPUT
    stream = sys.stdout
    sys.stdout = GuardedStdout(stream)
    try:
        with signal_handlers():
            code = _run(argv)
            sys.stdout.flush()  # a closed pipe or a full device shows here, not at exit
            if received and code not in (EXIT_SIGINT, EXIT_SIGTERM):  # Python dropped it
                return _interrupted(received[0](), "fem-racket")
            return code
    except StdoutFault as fault:
        sys.stdout = stream
        silence_stdout()
        if isinstance(fault.__cause__, BrokenPipeError):
            return EXIT_BROKEN_PIPE
        why = getattr(fault.__cause__, "strerror", None) or str(fault.__cause__)
        print(f"fem-racket: error: cannot write to standard output: {why}", file=sys.stderr)
        return EXIT_FAULT
    finally:
        sys.stdout = stream


def _pin_blas() -> None:
    """Once the arguments are parsed, before any work: numpy's BLAS on one thread
    (:func:`fem_racket.studies.executors.pin_blas_threads`; importing that module loads numpy and
    its BLAS first, which the limit needs). Not before: ``--help`` and a usage error need no
    numpy."""
    from fem_racket.studies.executors import pin_blas_threads

    pin_blas_threads()


def _end_lightly() -> None:
    """At the command's exit: collect the garbage left once, then freeze every object for the
    garbage collector. Python's teardown clears the modules as before (atexit handlers, files
    closed and flushed), but its repeated full collections no longer walk numba's and scipy's
    objects (after a law sweep, measured at load 6-7: 0.23-0.25 s CPU, 0.02 s frozen)."""
    gc.collect()
    gc.freeze()


def _describe(exc: OSError) -> str:
    """One line for an ``OSError``: the path it concerns and the reason."""
    why = exc.strerror or str(exc) or type(exc).__name__
    if exc.filename is not None and not isinstance(exc, OutputError):
        return f"{show(os.fsdecode(exc.filename))}: {why}"
    return why


def _run(argv: Sequence[str] | None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    parser = build_parser(argv)
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on usage errors, 0 on --help
        return int(exc.code or 0)
    _pin_blas()
    handler = logging.StreamHandler()
    handler.setFormatter(_NoteFormatter(f"fem-racket {args.command}"))
    logging.basicConfig(level=logging.INFO if args.verbose else logging.WARNING, handlers=[handler])
    prog = f"fem-racket {args.command}"
    try:
        args = apply_config(parser, argv, args)
        return int(args.func(args))
    except InputError as exc:
        _say(exc, f"{prog}: error: {named_by_file(exc, args)}")
        return EXIT_INPUT
    except OSError as exc:
        _say(exc, f"{prog}: error: {_describe(exc)}")
        return EXIT_FAULT
    except KeyboardInterrupt as exc:
        return _interrupted(exc, prog)
    except Exception:
        if received:  # the signal's exception became another on its way out (VTK's module
            # loader turns one raised during `import pyvista` into an ImportError)
            return _interrupted(received[0](), prog)
        raise


def _interrupted(exc: KeyboardInterrupt, prog: str) -> int:
    """Say so in one line; the exit code of the signal."""
    name = "SIGTERM" if isinstance(exc, Terminated) else "SIGINT"
    _say(exc, f"{prog}: interrupted by {name}; no partial output is left")
    return EXIT_SIGTERM if isinstance(exc, Terminated) else EXIT_SIGINT


class _NoteFormatter(logging.Formatter):
    """Log records as the commands' notes: ``fem-racket CMD: note: ...`` for warnings."""

    def __init__(self, prog: str) -> None:
        super().__init__()
        self.prog = prog

    def format(self, record: logging.LogRecord) -> str:
        """One line: the command, ``note:`` for a warning, the message."""
        kind = "note: " if record.levelno >= logging.WARNING else ""
        return f"{self.prog}: {kind}{record.getMessage()}"


def _say(exc: BaseException, line: str) -> None:
    """Print ``line`` and the exception's notes (e.g. a sweep's checkpoint) as one line."""
    notes = [" ".join(n.split()) for n in getattr(exc, "__notes__", ())]
    print("; ".join([line, *notes]), file=sys.stderr)
