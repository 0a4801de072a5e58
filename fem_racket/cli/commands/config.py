"""``fem-racket config``: print an annotated example run file, or check one.

``config --example`` prints a TOML run file that runs as is (the paper's standard case) followed
by the commented-out tables of every command that reads run files; ``config --check run.toml``
checks every table and prints the settings each command would take from it.
"""

from __future__ import annotations

import argparse
from pathlib import PurePath
from typing import Any

from fem_racket.cli.common import add_output_options
from fem_racket.cli.options.runfile import config_values, file_options
from fem_racket.io.config import example_config, load_config, toml_value
from fem_racket.io.config_keys import COMMAND_TABLES
from fem_racket.validation import InputError


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``config`` command."""
    p = sub.add_parser("config", help="print an example run file (TOML) or check one")
    what = p.add_mutually_exclusive_group(required=True)
    what.add_argument("--example", action="store_true", help="print an annotated example")
    what.add_argument(
        "--check", metavar="TOML", help="check a run file and print its settings (no default)"
    )
    add_output_options(p, what="output file for the --example run file, TOML")
    p.set_defaults(func=run)


def _commands() -> dict[str, argparse.ArgumentParser]:
    """Sub-commands that take ``--config``: name -> parser."""
    from fem_racket.cli import build_parser

    parser = build_parser()
    subs = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {
        name: p for name, p in subs.choices.items() if any(a.dest == "config" for a in p._actions)
    }


def _placeholder(action: argparse.Action) -> str:
    if action.default is None or action.default == argparse.SUPPRESS:
        return f"<{action.metavar or action.dest.upper()}>"
    if isinstance(action.default, PurePath):
        return toml_value(str(action.default))
    return toml_value(action.default)


def command_tables() -> str:
    """Commented-out TOML tables of the commands that read run files, with their defaults."""
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
    commands = _commands()
    cfg = load_config(path)
    out = [f"{path}: ok"]
    for name, sub in commands.items():
        try:
            values = config_values(sub, name, cfg)
        except InputError as exc:
            raise InputError(f"{path}: {exc}") from None
        used = file_options(sub).keys() | {a.dest for a in sub._actions}
        used |= {"segments", "mesh"}
        shown = {k: v for k, v in values.items() if k in used}
        listed = ", ".join(f"{k} = {_show(v)}" for k, v in shown.items())
        out.append(f"[{name}] {listed or '(all defaults)'}")
    known = {COMMAND_TABLES.get(n, n) for n in commands}
    for table in cfg.tables:
        if table not in known:
            out.append(f"[{table}] not checked: no command reads it in this version")
    return "\n".join(out) + "\n"


def _show(value: Any) -> str:
    if isinstance(value, tuple) and value and hasattr(value[0], "EI"):
        return f"{len(value)} segments"
    if isinstance(value, PurePath):
        value = str(value)
    return toml_value(value)


def run(args: argparse.Namespace) -> int:
    """Print (or write with ``--out``) the example, or check a file."""
    if args.check:
        print(_check(args.check), end="")
        return 0
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
