"""Progress bars for long work, one library for the whole project (tqdm, on stderr).

Every long loop of the library (a sweep's impacts, a refinement's meshes, the paper's figures,
the frames of an animation or a VTK series, the nodes of many modes) takes ``progress``:

- ``None`` (the library's default): a bar when stderr is a terminal, none otherwise (pipes,
  logs, notebooks, tests);
- ``True``: always a bar (e.g. in a notebook); ``False``: never (the CLI's ``--quiet``).

The bar is written to stderr, so stdout stays clean for tables and JSON.
"""

from __future__ import annotations

import sys
from collections.abc import Iterable
from typing import Any

__all__ = ["progress_bar"]


def progress_bar(
    iterable: Iterable[Any] | None = None,
    *,
    total: int | None = None,
    desc: str | None = None,
    unit: str = "it",
    enabled: bool | None = None,
) -> Any:
    """A tqdm bar over ``iterable`` (or a manual one with ``total``), shown per ``enabled``.

    Parameters
    ----------
    iterable : iterable, optional
        Items to iterate over; the bar advances by one per item.
    total : int, optional
        Number of steps (default: ``len(iterable)`` when it has one).
    desc : str, optional
        Label before the bar.
    unit : str
        What one step is (``"frame"``, ``"mesh"``, ``"figure"``).
    enabled : bool or None
        True: show; False: hide; None: show only when stderr is a terminal.
    """
    from tqdm import tqdm

    if enabled is None:
        enabled = sys.stderr.isatty()
    return tqdm(
        iterable,
        total=total,
        desc=desc,
        unit=unit,
        disable=not enabled,
        dynamic_ncols=True,
        leave=False,
        file=sys.stderr,
    )
