"""List options that take space- or comma-separated values: ``--elements 5 10 20`` or
``--elements 5,10,20`` (the comma lists of ``sweep``), or both mixed."""

from __future__ import annotations

import argparse
from collections.abc import Iterable
from typing import Any

__all__ = ["add_options", "number_list"]


class _NumberList:
    """argparse type: ``"5"`` or ``"5,10,20"`` -> a list of ``item`` (int or float)."""

    def __init__(self, item: type) -> None:
        self.item = item
        self.__name__ = f"{item.__name__} list"

    def __call__(self, text: str) -> list:
        words = str(text).split(",")
        try:
            return [self.item(w.strip()) for w in words]
        except ValueError:
            kind = "an integer" if self.item is int else "a number"
            raise argparse.ArgumentTypeError(
                f"invalid {self.item.__name__} value: {text!r} (each value must be {kind}; "
                "separate values by spaces or commas: 5 10 20 or 5,10,20)"
            ) from None


class _FlattenAction(argparse.Action):
    """Store the values of ``nargs="+"`` options whose type returns lists, as one flat list
    (``--elements 5,10 20`` -> [5, 10, 20]); the default is replaced, not extended."""

    def __call__(self, parser, namespace, values, option_string=None):
        """Set the option to the concatenated lists."""
        setattr(namespace, self.dest, [v for group in values for v in group])


def number_list(item: type = float) -> dict[str, Any]:
    """``add_argument`` keywords for a list option taking space- or comma-separated values
    (``--positions 0.6 0.75`` or ``--positions 0.6,0.75``, as sweep's comma lists)."""
    return {"type": _NumberList(item), "nargs": "+", "action": _FlattenAction}


def add_options(
    group: Any, rows: Iterable[tuple[str, Any, str | None, str]], **common: Any
) -> None:
    """``--name`` (underscores as dashes) for each row ``(name, default, metavar, help)`` of
    ``group``, with the ``add_argument`` keywords ``common`` (``type=float``,
    ``**number_list()``)."""
    for name, default, metavar, text in rows:
        flag = "--" + name.replace("_", "-")
        group.add_argument(flag, default=default, metavar=metavar, help=text, **common)
