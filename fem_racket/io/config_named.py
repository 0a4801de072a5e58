"""A library refusal of a value that came from a run file, named by the file's key.

The library checks a value once, where it is used, and names it as its parameter (``speed =
1000.0 m/s is not allowed: must lie in [1, 100]``). When that value came from a run file, the
error names the file and its dotted key instead (``run.toml: impact.speed_m_s = 1000.0 m/s is
not allowed: must lie in [1, 100]``), as the README's run-file convention promises; the bound
stays where the library keeps it (no copy here). The refusal says which parameter and value it
refused (``parameter`` and ``value`` of :class:`~fem_racket.validation.InputError`, set by the
library's checks); the parameter is the file's key when its name is the key's argparse dest
(spaces for underscores: ``string tension`` is ``string_tension``, set by ``strings.tension_n``)
or one of :data:`ALIASES`, and the refused value is the file's number (or its grid of numbers:
a map's ``positions``, as the command parsed it). A command table's grid (:data:`GRIDS`) is
read by one parser, :func:`grid_value`, for the command (``--config``) and for
:meth:`~fem_racket.io.config.RunConfig.map` alike: a number, an array of numbers or a string as
the command line takes it, refused while parsed by its key too.
"""

from __future__ import annotations

import functools
import math
import numbers
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from typing import Any

from fem_racket.validation import InputError, show

__all__ = [
    "ALIASES",
    "GRIDS",
    "command_keys",
    "core_keys_named",
    "file_keys",
    "grid_value",
    "keys_named",
    "named_by_key",
    "named_by_table",
]

#: A command table's grids (``[map]``'s) -> the sweep parameter whose values they are: text or
#: arrays, compared with the library's refused values as the command parses them.
GRIDS = {"positions": "position", "offsets": "offset"}
#: Parameter names of the library's checks that are not their key's dest (spaces as
#: underscores) -> the dest.
ALIASES = {
    "radius": "ball_radius",
    "shock_window": "hand_shock_window",
    "racket_speed_at_the_impact_point": "racket_speed",
}


def grid_value(where: str, value: Any) -> Any:
    """A command table's grid (``map.positions``, ``map.offsets``: :data:`GRIDS`) from a run
    file, as it is: a number, an array of numbers or a string as on the command line
    (``'0.5:1.0:200'``, ``'0.6,0.7'``), counted before any array is made (at most
    :data:`~fem_racket.studies.map_options.MAX_MAP_POINTS`); its values are checked where the
    command and :meth:`~fem_racket.io.config.RunConfig.map` parse it, a refusal named by its key
    (:func:`named_by_table`). The ``convert`` of the command's ``--config``
    (:func:`fem_racket.cli.options.runfile.add_config_option`): one reading for both."""
    from fem_racket.studies.grid_values import value_count
    from fem_racket.studies.map_options import MAX_MAP_POINTS

    array = isinstance(value, list) and all(
        isinstance(v, numbers.Real) and not isinstance(v, bool) for v in value
    )
    if isinstance(value, bool) or not (isinstance(value, (int, float, str)) or array):
        raise InputError(
            f"{where} = {show(value)} is not allowed: must be a number, an array of numbers or "
            "a string like '0.5:1.0:200'",
            parameter=where,
            value=value,
        )
    count = value_count(value)
    if count > MAX_MAP_POINTS:
        raise InputError(
            f"{where} = {count} values is not allowed: a map takes at most {MAX_MAP_POINTS} "
            "points (positions x offsets)",
            parameter=where,
            value=count,
        )
    return value


def file_keys(values: Mapping[str, Mapping[str, Any]]) -> dict[str, str]:
    """dest -> the dotted key setting it, from a run file's core tables (table -> key ->
    value); ``frame.ei1_n_m2`` wins over ``frame.preset``, which sets the same dest."""
    from fem_racket.io.config_keys import CORE_KEYS

    out: dict[str, str] = {}
    for table, keys in values.items():
        for key in keys:
            dest = CORE_KEYS[table][key].dest
            if dest is not None and not (key == "preset" and "ei1_n_m2" in keys):
                out[dest] = f"{table}.{key}"
    return out


def command_keys(cfg: Any, command: str) -> dict[str, str]:
    """dest -> the dotted key of the run file ``cfg`` (a RunConfig) setting it for ``command``:
    the core tables' (:func:`file_keys`), then the command's own table's, which win (its keys
    are its long options: ``--power-fraction`` is ``map.power_fraction``)."""
    from fem_racket.io.config_keys import COMMAND_TABLES

    keys = file_keys(cfg.values)
    table = COMMAND_TABLES.get(command, command)
    keys.update({k.replace("-", "_"): f"{table}.{k}" for k in cfg.table(table)})
    return keys


def _grid(x: Any) -> bool:
    """Whether ``x`` is a grid's values (a list, tuple or 1-D array)."""
    return isinstance(x, (list, tuple)) or getattr(x, "ndim", None) == 1


def _same(refused: Any, value: Any) -> bool:
    """Whether the number the library refused is the file's number ``value``, or the grid it
    refused the file's grid (the same values, in order: a map's ``positions``)."""
    if _grid(refused) and _grid(value):
        import numpy as np

        try:
            a, b = (np.asarray(x, dtype=float) for x in (refused, value))
        except (TypeError, ValueError):  # not numbers
            return False
        return a.shape == b.shape and bool(np.array_equal(a, b))
    if any(isinstance(x, bool) or not isinstance(x, numbers.Real) for x in (refused, value)):
        return False
    return math.isclose(refused, value, rel_tol=1e-9, abs_tol=0.0) or refused == value


def named_by_key(
    exc: InputError, keys: Mapping[str, str], values: Mapping[str, Any], source: Any
) -> InputError:
    """``exc`` with its parameter named by the run-file key that set it, or ``exc`` itself.

    Parameters
    ----------
    exc : InputError
        A library refusal naming its parameter and value (``parameter`` and ``value``).
    keys : mapping
        dest -> dotted key, for the values that came from the file.
    values : mapping
        dest -> value as the library got it.
    source : path-like or None
        The run file, named before the key (not when None: the caller names it).
    """
    if exc.parameter is None:
        return exc
    name = exc.parameter.replace(" ", "_")
    dest = ALIASES.get(name, name)
    if dest not in keys or not _same(exc.value, values.get(dest)):
        return exc
    return exc.named(keys[dest], "" if source is None else f"{source}: ")


def named_by_table(
    exc: InputError, keys: Mapping[str, str], values: Mapping[str, Any], source: Any
) -> InputError:
    """:func:`named_by_key` for the values of a command's own table (``run.toml:
    map.positions = 3 values is not allowed ...``): ``keys`` dest -> dotted key, ``values``
    dest -> the value as the file gives it; a grid (:data:`GRIDS`) parsed as the command
    parses it: its parsing's own refusal (``position = 'a,b' is not allowed ...``, or a value of
    it out of range) is named by the grid's key too."""
    from fem_racket.studies.grid_values import as_values

    keys, values = dict(keys), dict(values)
    for dest, name in GRIDS.items():
        if dest in keys:
            try:
                values[dest] = as_values(name, values[dest])
            except InputError as parse:  # the refusal itself, or not this grid's
                if str(parse) == str(exc):
                    return parse.named(keys[dest], "" if source is None else f"{source}: ")
                del keys[dest]
    return named_by_key(exc, keys, values, source)


@contextmanager
def keys_named(cfg: Any, table: str | None = None) -> Iterator[None]:
    """Re-raise a library refusal of a value of the core tables of the run file ``cfg`` naming
    its key (see :func:`named_by_key`); not of one the command's ``table`` sets (a sweep's grid
    is refused as the grid, as on the command line)."""
    try:
        yield
    except InputError as exc:
        own = {k.replace("-", "_") for k in cfg.table(table)} if table else set()
        keys = {d: k for d, k in file_keys(cfg.values).items() if d not in own}
        named = named_by_key(exc, keys, cfg.defaults(), cfg.source)
        if named is exc:
            raise
        raise named from None


def core_keys_named(method: Callable[..., Any]) -> Callable[..., Any]:
    """Decorate the ``method`` of a RunConfig named after its command (``export_vtk`` for
    ``export-vtk``) so that it runs under :func:`keys_named` with the command's table
    (:data:`~fem_racket.io.config_keys.COMMAND_TABLES`): its refusal of a core table's value
    names the key, as the command's."""
    command = method.__name__.replace("_", "-")

    @functools.wraps(method)
    def named(self: Any, *args: Any, **kwargs: Any) -> Any:
        from fem_racket.io.config_keys import COMMAND_TABLES

        with keys_named(self, COMMAND_TABLES[command]):
            return method(self, *args, **kwargs)

    return named
