"""Short text and HTML forms of the result objects, for terminals and notebooks.

Every result type (an impact, a frame model, its modes, a refinement study, a reproduction)
shows what a user needs at a glance instead of its arrays: ``repr`` is one line of
:func:`short_repr`, and ``_repr_html_`` (Jupyter's rich display) a small table of
:func:`html_table`.

Every text made from numbers (CSV cells, TOML and JSON values, messages) goes through
:func:`plain` first: numpy 2 writes a scalar's ``repr`` as ``np.float64(0.5)``, and JSON
takes ``np.int64`` and ``np.bool_`` for strings, where Python writes ``0.5``, ``8`` and
``true``.
"""

from __future__ import annotations

import html
import math
from collections.abc import Iterable, Sequence

__all__ = ["html_table", "number", "plain", "short_repr", "span"]


def plain(value: object) -> object:
    """``value`` with every numpy scalar and array (at any depth of dicts, lists and tuples)
    as the Python numbers, bools and lists it holds; anything else unchanged.

    ``repr`` of the result is Python's: ``np.float64(0.5)`` becomes ``0.5`` (the same float,
    bit for bit), ``np.int64(8)`` ``8`` and ``np.bool_(True)`` ``True``."""
    if isinstance(value, dict):
        return {plain(k): plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        items = [plain(v) for v in value]
        if isinstance(value, list):
            return items
        return type(value)(*items) if hasattr(value, "_fields") else type(value)(items)
    if type(value).__module__.partition(".")[0] == "numpy" and hasattr(value, "tolist"):
        return value.tolist()  # type: ignore[union-attr]
    return value


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
