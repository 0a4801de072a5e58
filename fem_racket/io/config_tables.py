"""A command's own table of a run file (``[modes]``, ``[fit]``, ``[customise]`` ...) read in
Python as the command reads it: its long options as keys (``--swing-weight`` ->
``swing_weight``), each converted and checked as the command line converts it (a number, an
integer, a flag, a text, a choice, a target ``"320:335"``), an unknown key refused with a "did
you mean", the keys that only say how the command prints (``json``, ``quiet``) taken and
unused. Used by the run file's methods of the commands that compute no impact
(:mod:`fem_racket.io.config_racket`, :mod:`fem_racket.io.config_reports`).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

from fem_racket.io.config_keys import COMMAND_TABLES, reject_unknown
from fem_racket.validation import InputError, show

__all__ = [
    "PRINT_KEYS",
    "Option",
    "choice",
    "flag",
    "integer",
    "number",
    "overwrite_set",
    "table_options",
    "text",
    "texts",
]

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any
#: Table keys that only set how each command prints: the command's own ``--json``/``--quiet``
#: (a key its parser lacks is refused, as ``--config`` refuses it).
PRINT_KEYS = {
    "modes": ("json", "quiet"),
    "fit": ("json",),
    "customise": ("json",),
    "closest": ("json",),
    "compare": ("json",),
    "calibrate": ("json",),
    "reproduce": ("quiet",),
}
#: An option's conversion: (dotted key, raw TOML value) -> the option's value.
Option = Callable[[str, Any], Any]


def _refuse(where: str, value: Any, why: str) -> InputError:
    return InputError(f"{where} = {show(value)} is not allowed: {why}")


def _typed(kind: type, refused: tuple[type, ...], what: str) -> Option:
    """The conversion of an option of ``type=kind``: a TOML value of that kind, or a text
    holding one; ``refused`` kinds (a bool for a number, a float for an integer) refused."""

    def conv(where: str, value: Any) -> Any:
        if isinstance(value, refused) or not isinstance(value, (int, float, str)):
            raise _refuse(where, value, f"must be {what}")
        try:
            return kind(value)
        except ValueError:
            raise _refuse(where, value, f"must be {what}") from None

    return conv


#: A number option (``type=float``).
number = _typed(float, (bool,), "a number")
#: An integer option (``type=int``).
integer = _typed(int, (bool, float), "an integer")


def flag(where: str, value: Any) -> bool:
    """A flag (``action="store_true"``): true or false."""
    if not isinstance(value, bool):
        raise _refuse(where, value, "must be true or false")
    return value


def text(where: str, value: Any) -> str:
    """A text option: a TOML string, or a number written as one (as the command line)."""
    if isinstance(value, (bool, list, dict)):
        raise _refuse(where, value, "must be a value like the option takes")
    return str(value)


def texts(where: str, value: Any) -> list[str]:
    """A list option (``nargs="+"``): an array of texts."""
    if not isinstance(value, list):
        raise _refuse(where, value, "must be an array")
    return [text(where, v) for v in value]


def choice(options: tuple[str, ...]) -> Option:
    """A text among ``options``."""

    def conv(where: str, value: Any) -> str:
        out = text(where, value)
        if out not in options:
            raise _refuse(where, value, f"must be one of {', '.join(options)}")
        return out

    return conv


def table_options(
    cfg: RunConfig,
    command: str,
    options: Mapping[str, tuple[Any, Option]],
    core: Mapping[str, Any] | None = None,
) -> dict[str, Any]:
    """The options of ``command`` from ``cfg``: each option's default, then the core tables'
    values ``core`` gives (argparse dests), then the command's table.

    Parameters
    ----------
    cfg : RunConfig
    command : str
        The command (its table: :data:`~fem_racket.io.config_keys.COMMAND_TABLES`).
    options : mapping
        dest -> (default, conversion) of every option the command's table may set.
    core : mapping, optional
        dest -> value of the core tables' settings the command takes.

    Returns
    -------
    dict
        dest -> value (the command's :data:`PRINT_KEYS` left out).
    """
    table = COMMAND_TABLES.get(command, command)
    own = {k.replace("-", "_"): v for k, v in cfg.table(table).items()}
    reject_unknown(own, [*options, *PRINT_KEYS[command]], table)
    out = {dest: default for dest, (default, _) in options.items()}
    out.update(core or {})
    for dest, value in own.items():
        if dest in options:
            out[dest] = options[dest][1](f"{table}.{dest}", value)
        else:
            flag(f"{table}.{dest}", value)  # json, quiet: checked, how the command prints
    return out


def overwrite_set(cfg: RunConfig, table: str) -> str | None:
    """``KEY = VALUE (FILE)`` of the file's ``overwrite = true`` for the command whose table is
    ``table`` (that table's key, else ``[output]``'s, as ``--config`` takes them), for the
    refusal where the command writes nothing; None when the file leaves it false."""
    own = cfg.table(table)
    key = f"{table}.overwrite" if "overwrite" in own else "output.overwrite"
    value = own["overwrite"] if "overwrite" in own else cfg.defaults().get("overwrite")
    return f"{key} = {show(value)} ({cfg.source})" if value else None
