"""The content of a paper figure (:class:`FigureData`) and its description (:class:`FigureSpec`)."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

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
    law : str
        The contact law the figure was drawn with (its name); ``""`` for the paper's linear
        K_CB.
    """

    name: str
    title: str
    tables: dict[str, dict[str, np.ndarray]]
    values: dict[str, float] = field(default_factory=dict)
    law: str = ""


@dataclass(frozen=True)
class FigureSpec:
    """A paper figure: its file stem, table names, compute function and plot function name.

    ``compute(quick, law)`` draws it with the paper's linear K_CB when ``law`` is None, else with
    that :class:`~fem_racket.contact.law.ContactLaw`. ``law_skip``, when not empty, says why the
    figure has no meaning under another law (it is then not drawn with one).
    """

    name: str
    tables: tuple[str, ...]
    compute: Callable[[bool, Any], FigureData]
    plot: str
    law_skip: str = ""
