"""Run files on the command line: ``--config run.toml`` for any command.

A command adopts run files with one call to ``add_config_option(p)`` (re-exported
by :mod:`fem_racket.cli.common`). ``cli.main`` calls :func:`apply_config` once after parsing; it
fills every option the command line did not give from the file. Precedence: command line > the
command's own table (``[sweep]``, ``[vtk]`` for export-vtk ..., see
:data:`fem_racket.io.config_keys.COMMAND_TABLES`) > the core tables (``[frame]``, ``[impact]``
...) > built-in defaults. The command's table takes its long options as keys
(``--power-fraction`` -> ``power_fraction``), converted and checked as on the command line;
options the core tables own (``--speed`` is ``impact.speed_m_s``) are refused there with a
pointer to the core key, unless the command declares them its ``own`` (sweep's grids) or
``private`` (refine's list of element counts; the ``out`` of commands writing another kind of
file than simulate's JSON), see :func:`add_config_option`. A command takes from the core tables
only what it has options for; a command computing impacts refuses a key of the impact's tables
or of ``[solver]`` it has no option for (:mod:`fem_racket.io.config_unused`). ``--config`` is
given once, and a frame from both the file and the command line is refused
(:mod:`fem_racket.cli.options.runfile_clash`).
"""

from __future__ import annotations

import argparse
import difflib
import sys
from collections.abc import Callable, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from fem_racket.cli.options.once import refuse_repeated
from fem_racket.cli.options.runfile_clash import OneFile, refuse_frame_clash
from fem_racket.validation import InputError, show

if TYPE_CHECKING:
    from fem_racket.io.config import RunConfig

__all__ = [
    "add_config_option",
    "apply_config",
    "config_values",
    "file_options",
    "given_options",
    "option_name",
]

#: Options that never come from a run file.
_NOT_FROM_FILE = frozenset({"help", "config", "version"})


def add_config_option(
    parser: argparse.ArgumentParser,
    *,
    own: Iterable[str] = (),
    private: Iterable[str] = (),
    convert: Mapping[str, Callable[[str, Any], Any]] | None = None,
    requires: Iterable[str] = (),
) -> None:
    """Give a command ``--config run.toml``; :func:`apply_config` does the rest.

    Parameters
    ----------
    own : iterable of str
        Options (argparse dests) a core table also sets that the command's own table may set
        too, in the command's form (``sweep``: ``speed = [20, 30, 40]`` besides
        ``impact.speed_m_s``). The core value still applies when the command's table is silent.
    private : iterable of str
        Options only the command's table sets: the core tables' value is not used by this
        command (``refine``'s ``elements`` is a list of counts, not ``frame.elements``; the
        ``out`` of a command writing a folder or another kind of file is not ``output.out``).
    convert : mapping, optional
        dest -> ``f(dotted_key, value)`` checking and converting a table value instead of the
        option's own conversion (e.g. arrays for sweep grids); raise :class:`InputError`.
    requires : iterable of str
        Options (dests) the command cannot run without (``fit``'s targets): ``config --check``
        checks the command only when the file's table for it is there.
    """
    parser.add_argument(
        "--config",
        action=OneFile,
        metavar="TOML",
        default=None,
        help="run file (see `fem-racket config --example`); command-line options override it "
        "(default: none)",
    )
    private = frozenset(private)
    parser.config_own = frozenset(own) | private  # type: ignore[attr-defined]
    parser.config_private = private  # type: ignore[attr-defined]
    parser.config_convert = dict(convert or {})  # type: ignore[attr-defined]
    parser.config_requires = tuple(requires)  # type: ignore[attr-defined]


def _subparser(parser: argparse.ArgumentParser, command: str) -> argparse.ArgumentParser:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            return action.choices[command]
    raise LookupError(command)  # pragma: no cover - build_parser always adds sub-commands


def file_options(sub: argparse.ArgumentParser) -> dict[str, argparse.Action]:
    """A command's options that its run-file table may set: dest -> action."""
    from fem_racket.io.config_unused import CORE_ONLY

    own = getattr(sub, "config_own", frozenset())
    return {
        a.dest: a
        for a in sub._actions
        if a.option_strings
        and a.dest not in _NOT_FROM_FILE
        and (a.dest not in CORE_ONLY or a.dest in own)
        and a.default is not argparse.SUPPRESS
    }


def _core_values(
    sub: argparse.ArgumentParser, cfg: RunConfig, given: Iterable[str] = ()
) -> dict[str, Any]:
    """dest -> value of the core tables that this command uses: only its own options (a frame
    file also where it has --mesh), less its private ones. A mesh file ``given`` on the command
    line replaces the file's frame (preset, EI1, EI2, segments), and with a mesh file from
    either ``frame.elements`` does not apply: the mesh fixes the cells."""
    dests = {a.dest for a in sub._actions}
    if "mesh" in dests:
        dests.add("segments")
    dests -= getattr(sub, "config_private", frozenset())
    values = {k: v for k, v in cfg.defaults().items() if k in dests}
    if "mesh" in set(given):
        for dest in ("ei1", "ei2", "segments"):
            values.pop(dest, None)
    if "mesh" in values or "mesh" in set(given):
        values.pop("elements", None)
    return values


class _Given(argparse.Namespace):
    """A namespace that claims to hold every option, so argparse fills in no defaults."""

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        return _Given


def _explicit(sub: argparse.ArgumentParser, argv: Sequence[str], command: str) -> set[str]:
    """The dests the command line sets explicitly (parsed again with no defaults); an option
    given twice with two values is refused (:func:`.once.refuse_repeated`)."""
    rest = list(argv)[list(argv).index(command) + 1 :]
    refuse_repeated(sub, rest)
    ns, _ = sub.parse_known_args(rest, namespace=_Given())
    return set(vars(ns))


def _coerce(action: argparse.Action, value: Any, where: str) -> Any:
    """A run-file value for ``action``, checked as the command line would check it."""
    opt = action.option_strings[-1]
    if action.nargs == 0:  # flags: store_true / store_false / store_const
        if not isinstance(value, bool):
            raise InputError(
                f"{where} = {show(value)} is not allowed: must be true or false ({opt})"
            )
        if isinstance(action.const, bool):
            return action.const if value else not action.const
        return action.const if value else action.default
    many = action.nargs in ("+", "*") or isinstance(action.nargs, int)
    if many:
        if not isinstance(value, list):
            raise InputError(f"{where} = {show(value)} is not allowed: must be an array ({opt})")
        items = [_coerce_one(action, v, where) for v in value]
        # A list option whose type takes comma lists ("5,10") gives a list per item: flatten.
        return [x for v in items for x in (v if isinstance(v, list) else [v])]
    return _coerce_one(action, value, where)


def _coerce_one(action: argparse.Action, value: Any, where: str) -> Any:
    opt = action.option_strings[-1]
    if isinstance(value, (dict, list)) or isinstance(value, bool):
        raise InputError(
            f"{where} = {show(value)} is not allowed: must be a value like {opt} takes"
        )
    convert = action.type or str
    try:
        if convert is int and isinstance(value, float):
            raise ValueError("must be an integer")
        out = convert(value if isinstance(value, str) or convert in (int, float) else str(value))
    except (TypeError, ValueError, argparse.ArgumentTypeError) as exc:
        raise InputError(f"{where} = {show(value)} is not allowed: {exc} ({opt})") from None
    if action.choices is not None and out not in action.choices:
        options = ", ".join(map(str, action.choices))
        raise InputError(f"{where} = {show(value)} is not allowed: must be one of {options}")
    return out


def config_values(
    sub: argparse.ArgumentParser, command: str, cfg: RunConfig, given: Iterable[str] = ()
) -> dict[str, Any]:
    """dest -> value from the run file for one command: core tables, then the command's table
    (``given``: the options the command line sets)."""
    from fem_racket.io.config_keys import COMMAND_TABLES
    from fem_racket.io.config_unused import refuse_core_only

    values = _core_values(sub, cfg, given)
    table = COMMAND_TABLES.get(command, command)
    options = file_options(sub)
    convert = getattr(sub, "config_convert", {})
    for key, value in cfg.table(table).items():
        where = f"{table}.{key}"
        dest = key.replace("-", "_")
        if dest not in options:
            refuse_core_only(where, dest)
            near = difflib.get_close_matches(dest, list(options), n=1, cutoff=0.6)
            hint = f"did you mean '{near[0]}'?" if near else ""
            allowed = ", ".join(sorted(options)) or "(none)"
            raise InputError(
                f"{where} is not a known key: {hint} allowed: {allowed}".replace(":  ", ": ")
            )
        if dest in convert:
            values[dest] = convert[dest](where, value)
        else:
            values[dest] = _coerce(options[dest], value, where)
    return values


def apply_config(
    parser: argparse.ArgumentParser, argv: Sequence[str] | None, args: argparse.Namespace
) -> argparse.Namespace:
    """Record the options ``argv`` gives explicitly (``args.explicit_options``) and fill the
    others from ``--config`` when one is given.

    Called once by :func:`fem_racket.cli.main` after parsing.
    """
    from fem_racket.io.config import load_config
    from fem_racket.io.config_named import command_keys
    from fem_racket.io.config_unused import refuse_unused

    argv = sys.argv[1:] if argv is None else list(argv)
    sub = _subparser(parser, args.command)
    given = _explicit(sub, argv, args.command)
    args.explicit_options = given
    args.file_options = {}
    path = getattr(args, "config", None)
    if not path:
        return args
    cfg = load_config(path)
    args.config_raw = {f"{t}.{k}": v for t, ks in cfg.values.items() for k, v in ks.items()}
    args.config_raw.update({f"{t}.{k}": v for t, ks in cfg.tables.items() for k, v in ks.items()})
    try:
        values = config_values(sub, args.command, cfg, given)
        dests = {a.dest for a in sub._actions} - getattr(sub, "config_private", frozenset())
        dests |= {"segments"} if "mesh" in dests else set()
        refuse_unused(cfg, args.command, dests, given)
    except InputError as exc:
        raise InputError(f"{path}: {exc}") from None
    keys = command_keys(cfg, args.command)
    refuse_frame_clash(cfg, values, given, keys, path)
    defaults = {a.dest: a.default for a in sub._actions}
    for dest, value in values.items():
        if dest not in given:
            setattr(args, dest, value)
            if dest not in defaults or value != defaults[dest]:  # a default changes nothing
                args.file_options[dest] = keys.get(dest, dest)
    return args


def option_name(args: argparse.Namespace, dest: str) -> str:
    """How the user set option ``dest``, for a message: ``--kcb 30000`` on the command line, or
    ``contact.kcb_n_m = 30000 (run.toml)`` from a run file."""
    value = show(getattr(args, dest, None))
    key = getattr(args, "file_options", {}).get(dest)
    if key is not None:
        raw = getattr(args, "config_raw", {}).get(key)
        return f"{key} = {show(raw if raw is not None else value)} ({args.config})"
    return f"--{dest.replace('_', '-')} {value}"


def given_options(args: argparse.Namespace) -> set[str]:
    """The options the user set: on the command line, or in the run file to other than the
    default (argparse dests; a file's key at its default changes nothing).

    A check of the form "X is not allowed with Y" asks this, so that a run file's key is refused
    where the same option on the command line would be (never silently ignored).
    """
    return set(getattr(args, "explicit_options", ())) | set(getattr(args, "file_options", ()))
