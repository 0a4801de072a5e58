"""``fem-racket config``: print an annotated example run file, or check one.

``config --example`` prints a TOML run file that runs as is (the paper's standard case) followed
by the commented-out tables of every command that reads run files; ``config --check run.toml``
checks every table and prints the settings each command would take from it.
"""

from __future__ import annotations

import argparse
import contextlib
import io
from pathlib import PurePath
from typing import Any

from fem_racket.cli.common import add_output_options
from fem_racket.cli.options.output import overwrite_of
from fem_racket.cli.options.runfile import apply_config, config_values, file_options
from fem_racket.cli.options.runfile_named import named_by_file
from fem_racket.validation import ChecksPassed, InputError, checks_only, show


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``config`` command's options."""
    what = p.add_mutually_exclusive_group(required=True)
    what.add_argument("--example", action="store_true", help="print an annotated example")
    what.add_argument(
        "--check", metavar="TOML", help="check a run file and print its settings (no default)"
    )
    add_output_options(p, what="output file for the --example run file, TOML")


def _commands() -> dict[str, argparse.ArgumentParser]:
    """Sub-commands that take ``--config``: name -> parser."""
    from fem_racket.cli import build_parser

    parser = build_parser()
    subs = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {
        name: p for name, p in subs.choices.items() if any(a.dest == "config" for a in p._actions)
    }


def _placeholder(action: argparse.Action) -> str:
    from fem_racket.io.config import toml_value

    if action.default is None or action.default == argparse.SUPPRESS:
        return f"<{action.metavar or action.dest.upper()}>"
    if isinstance(action.default, PurePath):
        return toml_value(str(action.default))
    return toml_value(action.default)


def command_tables() -> str:
    """Commented-out TOML tables of the commands that read run files, with their defaults."""
    from fem_racket.io.config_keys import COMMAND_TABLES

    lines = [
        "",
        "# Each command's own options, in a table named after it (keys = its long options).",
        "# They override the tables above for that command only.",
    ]
    for name, p in _commands().items():
        lines += ["", f"# [{COMMAND_TABLES.get(name, name)}]   # fem-racket {name}"]
        for dest, action in file_options(p).items():
            entry = f"{dest} = {_placeholder(action)}"
            about = (action.help or "").split(" (default")[0]
            lines.append(f"# {entry:<26} # {about}")
    return "\n".join(lines) + "\n"


def _check(path: str) -> str:
    from fem_racket.io.config import load_config
    from fem_racket.io.config_keys import COMMAND_TABLES

    commands = _commands()
    cfg = load_config(path)
    known_tables = {COMMAND_TABLES.get(n, n) for n in commands}
    out = [f"{path}: ok"]
    for name, sub in commands.items():
        table = COMMAND_TABLES.get(name, name)
        label = f"[{table}]" if table == name else f"[{table}] (fem-racket {name})"
        try:
            values = config_values(sub, name, cfg)
        except InputError as exc:
            raise InputError(f"{path}: {exc}") from None
        requires = getattr(sub, "config_requires", ())
        if requires and table not in cfg.tables:
            out.append(f"{label} not checked: no [{table}] table ({', '.join(requires)} needed)")
            continue
        # A file with command tables is meant for those commands: another command's refusal
        # is a note; a file without any is checked for every command.
        strict = table in cfg.tables or not known_tables & set(cfg.tables)
        try:
            _dry_run(name, path)
        except InputError as exc:  # a key the command would ignore: a note unless it is meant
            if strict and (table in cfg.tables or "would be ignored" not in str(exc)):
                raise
            out.append(f"{label} not for this command: {str(exc).removeprefix(f'{path}: ')}")
            continue
        used = file_options(sub).keys() | {a.dest for a in sub._actions}
        used |= {"segments", "mesh"}
        shown = {k: v for k, v in values.items() if k in used}
        listed = ", ".join(f"{k} = {_show(v)}" for k, v in shown.items())
        out.append(f"{label} {listed or '(all defaults)'}")
    for table in cfg.tables:
        if table not in known_tables:
            out.append(f"[{table}] not checked: no command reads it in this version")
    return "\n".join(out) + "\n"


def _dry_run(name: str, path: str, operands: tuple[str, ...] = ()) -> None:
    """Run command ``name`` on the run file up to where its work would begin: every check it
    makes (values, combinations, files it would read or write) without the computation.
    ``operands``: what a run file cannot name (the racket list of ``closest``, the set-ups of
    ``compare``), given before ``--config``.

    An output that exists already is not refused here (it is the folder's state, not the file's:
    the command refuses it without --overwrite)."""
    from fem_racket.cli import build_parser

    argv = [name, *operands, "--config", path]
    parser = build_parser(argv)
    args = apply_config(parser, argv, parser.parse_args(argv))
    if hasattr(args, "overwrite"):
        args.overwrite = True
    with checks_only(), contextlib.redirect_stdout(io.StringIO()):
        try:
            args.func(args)
        except ChecksPassed:
            return
        except InputError as exc:
            exc = named_by_file(exc, args, source=False)
            raise InputError(f"{path}: fem-racket {name} would refuse it: {exc}") from None
    raise RuntimeError(f"fem-racket {name} has no end of checks (validation.work_begins)")


def _show(value: Any) -> str:
    from fem_racket.io.config import toml_value

    if isinstance(value, tuple) and value and hasattr(value[0], "EI"):
        return f"{len(value)} segments"
    if isinstance(value, list) and value and hasattr(value[0], "place"):
        return "[" + ", ".join(f'"{lead.label()}"' for lead in value) + "]"
    if isinstance(value, PurePath):
        value = str(value)
    return toml_value(value)


def run(args: argparse.Namespace) -> int:
    """Print (or write with ``--out``) the example, or check a file."""
    from fem_racket.io.config import example_config

    if args.check:
        if args.out:
            raise InputError(
                f"--out {show(args.out)} is not allowed with --check: the check writes nothing"
            )
        overwrite_of(args, False, "--example --out")
        print(_check(args.check), end="")
        return 0
    overwrite_of(args, bool(args.out))
    text = example_config() + command_tables()
    if args.out:
        import json

        from fem_racket.cli.common import print_written, run_parameters, write_text
        from fem_racket.outputs import provenance

        meta = json.dumps(provenance(run_parameters(args)), sort_keys=True)
        write_text(args.out, f"{text}\n# provenance: {meta}\n", overwrite=args.overwrite)
        print_written([args.out])
        return 0
    print(text, end="")
    return 0
