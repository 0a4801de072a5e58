"""Keyword options of the studies as small frozen dataclasses, checked with a "did you mean".

A study's public function keeps its keywords (``sweep(position="0.55:0.95:9", speed=...)``)
through a thin wrapper taking ``**options``; :func:`take` sorts them into the study's option
dataclasses by field name and refuses, in one line naming the closest known name, one that
none of them has (as :func:`fem_racket.simulate` refuses an unknown option). A field whose
default factory is itself such a dataclass (a group of options shared by several studies, e.g.
:class:`~fem_racket.studies.map_options.MapPlay`) is filled from the same keywords: its fields
stand in its place.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from dataclasses import Field, fields, is_dataclass
from typing import Any

from fem_racket.validation import InputError

__all__ = ["field_names", "take"]


def _group(f: Field) -> type | None:
    """The option dataclass field ``f`` holds (its default factory), or None."""
    g = f.default_factory
    return g if isinstance(g, type) and is_dataclass(g) else None


def field_names(cls: type) -> tuple[str, ...]:
    """The option names of dataclass ``cls``: its field names, a group's (:func:`_group`) in
    its place."""
    out: list[str] = []
    for f in fields(cls):
        group = _group(f)
        out.extend(field_names(group) if group else [f.name])
    return tuple(out)


def _made(cls: type, options: dict[str, Any]) -> Any:
    """``cls`` with the ``options`` that are its fields (its groups made likewise)."""
    kw: dict[str, Any] = {}
    for f in fields(cls):
        group = _group(f)
        if group:
            kw[f.name] = _made(group, options)
        elif f.name in options:
            kw[f.name] = options[f.name]
    return cls(**kw)


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
    out = [_made(cls, options) for cls in classes]
    return (*out, {k: options[k] for k in extra if k in options})
