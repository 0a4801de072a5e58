"""Short text and HTML forms of the result objects, for terminals and notebooks.

Every result type (an impact, a frame model, its modes, a refinement study, a reproduction)
shows what a user needs at a glance instead of its arrays: ``repr`` is one line of
:func:`short_repr`, and ``_repr_html_`` (Jupyter's rich display) a small table of
:func:`html_table`.
"""

from __future__ import annotations

import html
import math
from collections.abc import Iterable, Sequence

__all__ = ["html_table", "number", "short_repr", "span"]


def number(value: float, digits: int = 5) -> str:
    """``value`` to ``digits`` significant digits (``nan`` and ``inf`` as they are)."""
    if value is None:
        return "None"
    value = float(value)
    if not math.isfinite(value):
        return str(value)
    return f"{value:.{digits}g}"


def span(values: Iterable[float], unit: str, digits: int = 5) -> str:
    """``"146 N m^2"`` for equal values, ``"128.48-146 N m^2"`` for a range."""
    vals = [float(v) for v in values]
    low, high = number(min(vals), digits), number(max(vals), digits)
    return f"{low} {unit}" if low == high else f"{low}-{high} {unit}"


def short_repr(name: str, fields: Iterable[tuple[str, str]]) -> str:
    """``Name(key=value, ...)`` from already formatted ``(key, value)`` pairs."""
    return f"{name}(" + ", ".join(f"{k}={v}" for k, v in fields) + ")"


def html_table(
    caption: str, rows: Sequence[Sequence[object]], header: Sequence[str] | None = None
) -> str:
    """A small HTML table (Jupyter's ``_repr_html_``): ``caption`` above, one row per item."""
    esc = html.escape
    out = [f"<table><caption style='text-align:left'><b>{esc(caption)}</b></caption>"]
    if header:
        out.append("<tr>" + "".join(f"<th>{esc(str(h))}</th>" for h in header) + "</tr>")
    for row in rows:
        cells = "".join(f"<td>{esc(str(c))}</td>" for c in row)
        out.append(f"<tr>{cells}</tr>")
    out.append("</table>")
    return "".join(out)
