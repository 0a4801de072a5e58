"""A run file's arrays of tables (``[[frame.segments]]``, ``[[frame.lead]]``): each a non-empty
array whose every item is a table with every one of its keys and no other; checked here, item by
item, before each item's values are (:mod:`fem_racket.io.config_keys`,
:mod:`fem_racket.io.config_lead`)."""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping, Sequence
from typing import Any

from fem_racket.validation import InputError, show

__all__ = ["table_array"]


def table_array(
    name: str,
    value: Any,
    keys: Sequence[str],
    unknown: Callable[[Mapping[str, Any], str], None],
    each: str,
) -> Iterator[tuple[str, dict[str, Any]]]:
    """The items of the array of tables ``value`` (the dotted key ``name``), each with its
    place (``name[i]``), once it is a table holding every one of ``keys``.

    Parameters
    ----------
    unknown : callable
        ``unknown(item, where)`` raises for a key of an item not in ``keys``.
    each : str
        Why a missing key is refused (``"each lead needs both"``).

    Raises
    ------
    InputError
        For an empty array or none, an item not a table, an unknown key or a missing one.
    """
    listed = f"{', '.join(keys[:-1])} and {keys[-1]}"
    if not isinstance(value, list) or not value:
        raise InputError(
            f"{name} is not allowed: must be a non-empty array of tables with {listed}"
        )
    for i, item in enumerate(value):
        where = f"{name}[{i}]"
        if not isinstance(item, dict):
            raise InputError(
                f"{where} = {show(item)} is not allowed: must be a table with {listed}"
            )
        unknown(item, where)
        missing = [k for k in keys if k not in item]
        if missing:
            raise InputError(f"{where} is missing {', '.join(missing)} ({each})")
        yield where, item
