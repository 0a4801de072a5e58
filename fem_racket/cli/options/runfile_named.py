"""Run-file values in the commands' messages: where an option was set (:func:`where_set`) and
a library refusal of a core table's value named by its dotted key (:func:`named_by_file`; the
renaming itself: :mod:`fem_racket.io.config_named`). The values come from
:func:`fem_racket.cli.options.runfile.apply_config` (``args.file_options``)."""

from __future__ import annotations

import argparse

from fem_racket.validation import InputError

__all__ = ["named_by_file", "where_set"]


def where_set(args: argparse.Namespace, dest: str) -> str:
    """Where option ``dest`` was set, for a message: ``--mesh`` on the command line, or
    ``frame.mesh (run.toml)`` from a run file."""
    key = getattr(args, "file_options", {}).get(dest)
    if key is None:
        return f"--{dest.replace('_', '-')}"
    return f"{key} ({args.config})"


def named_by_file(exc: InputError, args: argparse.Namespace, *, source: bool = True) -> InputError:
    """A library refusal of a value the run file's core tables set (not the command line),
    naming its dotted key and (``source``) the file
    (:func:`fem_racket.io.config_named.named_by_key`); else ``exc``."""
    from fem_racket.io.config_keys import CORE_KEYS
    from fem_racket.io.config_named import named_by_key

    # a core table's key (a command table's value is refused as the command's option)
    keys = {
        d: k for d, k in getattr(args, "file_options", {}).items() if k.split(".")[0] in CORE_KEYS
    }
    if not keys:
        return exc

    return named_by_key(exc, keys, vars(args), args.config if source else None)
