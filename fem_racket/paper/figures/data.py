"""The content of a paper figure (:class:`FigureData`) and its description (:class:`FigureSpec`)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

__all__ = ["FigureData", "FigureSpec"]


@dataclass(frozen=True, eq=False)
class FigureData:
    """Computed content of one paper figure.

    Attributes
    ----------
    name : str
        File stem, e.g. ``"fig08_cor_position"``.
    title : str
        Plot title, with the paper's figure number.
    tables : dict of str to dict of str to ndarray
        Tables by name; each maps a column name with its unit (``"time [s]"``) to a 1-D array,
        all of one length.
    values : dict of str to float
        Scalars drawn from the data, for the report (names carry units, e.g. ``"..._hz"``).
    """

    name: str
    title: str
    tables: dict[str, dict[str, np.ndarray]]
    values: dict[str, float] = field(default_factory=dict)


@dataclass(frozen=True)
class FigureSpec:
    """A paper figure: its file stem, table names, compute function and plot function name."""

    name: str
    tables: tuple[str, ...]
    compute: Callable[[bool], FigureData]
    plot: str
