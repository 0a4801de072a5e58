"""The library's options objects from the parsed options: the fields of a small frozen dataclass
(:class:`~fem_racket.studies.sweep_options.SweepSolving`, ``RefineOptions``, the design
study's groups ...) read from the argparse namespace by their names, once per command, instead
of a chain of ``field=args.field`` keywords restated in each command."""

from __future__ import annotations

import argparse
from dataclasses import fields
from typing import Any

__all__ = ["fields_from_args", "options_from_args"]


def fields_from_args(args: argparse.Namespace, cls: type, **given: Any) -> dict[str, Any]:
    """Keyword arguments of the dataclass ``cls``: each of its fields the parsed options hold
    under the same name (its argparse dest), then ``given`` (fields an option names otherwise,
    or values the command computes), which win."""
    values = {f.name: getattr(args, f.name) for f in fields(cls) if hasattr(args, f.name)}
    return values | given


def options_from_args(args: argparse.Namespace, cls: type, **given: Any) -> Any:
    """The dataclass ``cls`` made from the parsed options (see :func:`fields_from_args`)."""
    return cls(**fields_from_args(args, cls, **given))
