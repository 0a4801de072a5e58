"""The run keys of ``[simulate]``, ``[sweep]``, ``[map]``, ``[refine]``, ``[vtk]`` and
``[animate]``: where the command writes, how it prints (and, for ``sweep``, where its cases
run), read by the run file's methods as the commands read them.

A key the command refuses is refused by its method too, with the same words (its type: a flag
true or false, an integer, a text, an array; a suffix or format the command does not write; keys
that contradict each other), and a key the command does not have is not a key of its table
(:data:`RUN_KEYS`). The methods :meth:`RunConfig.simulate`, ``.sweep``, ``.map`` and ``.refine``
write no file: a destination's state (a file already there) is not checked for them.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from fem_racket.io.config_tables import Option, choice, flag, integer, number, text, texts
from fem_racket.io.figure_files import FIGURE_FORMATS
from fem_racket.validation import InputError

__all__ = ["RUN_KEYS", "run_keys"]

#: The run keys of each command's table (its options there that do not change what it
#: computes): key -> conversion, as the command's parser converts them.
_DRAWING: dict[str, Option] = {"out": text, "overwrite": flag, "quiet": flag}
RUN_KEYS: dict[str, dict[str, Option]] = {
    "simulate": {"out": text, "overwrite": flag, "json": flag},
    "vtk": _DRAWING,
    "animate": _DRAWING,
    "sweep": {"out": text, "overwrite": flag, "restart": flag, "serial": flag,
              "workers": integer, "scheduler": text, "quiet": flag, "json": flag},
    "map": {"out": texts, "overwrite": flag, "no_files": flag, "json": flag},
    "refine": {"csv": text, "plot": text, "format": choice(FIGURE_FORMATS), "dpi": number,
               "overwrite": flag, "no_files": flag, "json": flag, "quiet": flag},
}  # fmt: skip


def _refine(o: Mapping[str, Any]) -> None:
    """The plot's suffix, its format and resolution, as ``fem-racket refine`` checks them."""
    from fem_racket.io.figure_files import DEFAULT_DPI, check_dpi, figure_format

    fmt = o.get("format")
    plot = figure_format(o["plot"]) if "plot" in o else None  # its suffix
    if plot is not None and fmt is not None and plot != fmt:
        raise InputError(
            f"format = {fmt!r} is not allowed with --plot '{o['plot']}': give one of them, "
            "or a --plot ending in ." + fmt
        )
    check_dpi(o.get("dpi", DEFAULT_DPI))


def run_keys(name: str, table: Mapping[str, Any]) -> dict[str, Any]:
    """The run keys of the command table ``name`` (``[vtk]`` for export-vtk), its keys ``table``
    (``-`` as ``_``) converted and checked as the command checks them: key -> value."""
    kinds = RUN_KEYS[name]
    o = {k: conv(f"{name}.{k}", table[k]) for k, conv in kinds.items() if k in table}
    if name == "map":
        from fem_racket.io.map_files import map_targets

        if o.get("no_files") and o.get("out"):
            raise InputError("no_files = True is not allowed with --out: give one of them")
        map_targets(o.get("out", []))  # their suffixes
    elif name == "refine":
        _refine(o)
    return o
