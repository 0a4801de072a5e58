"""Keyword options of the studies as small frozen dataclasses, checked with a "did you mean".

A study's public function keeps its keywords (``sweep(position="0.55:0.95:9", speed=...)``)
through a thin wrapper taking ``**options``; :func:`take` sorts them into the study's option
dataclasses by field name and refuses, in one line naming the closest known name, one that
none of them has (as :func:`fem_racket.simulate` refuses an unknown option).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from dataclasses import fields
from typing import Any

from fem_racket.validation import InputError

__all__ = ["field_names", "take"]


def field_names(cls: type) -> tuple[str, ...]:
    """The field names of dataclass ``cls``."""
    return tuple(f.name for f in fields(cls))


def take(options: dict[str, Any], what: str, *classes: type, extra: Iterable[str] = ()) -> tuple:
    """``options`` sorted into ``classes`` (one instance each, in order) and a dict of the
    ``extra`` names given; any other name is refused, e.g. ``speeds is not an option of
    racket_map: did you mean 'speed'?``."""
    extra = tuple(extra)
    known = [n for cls in classes for n in field_names(cls)] + list(extra)
    for key in options:
        if key not in known:
            near = difflib.get_close_matches(key, known, n=1)
            hint = f"did you mean {near[0]!r}?" if near else f"must be one of {', '.join(known)}"
            raise InputError(f"{key} is not {what}: {hint}")
    out = [cls(**{k: options[k] for k in field_names(cls) if k in options}) for cls in classes]
    return (*out, {k: options[k] for k in extra if k in options})
