"""The contact laws by name: one registry of law families and calibrated presets.

A law family is one module (a :class:`~fem_racket.contact.law.ContactLaw` dataclass declaring
its parameters, :mod:`fem_racket.contact.parameters`) plus one line here::

    register(HuntCrossley)

Everything else derives from the registry: ``--law`` and each parameter's option
(:mod:`fem_racket.cli.options.laws`), the run file's ``[contact]`` keys
(:mod:`fem_racket.io.config_keys`), the sweep axes (:mod:`fem_racket.studies.grid_values`), the
JSON keys and the calibration (:mod:`fem_racket.studies.calibrate`). The views below
(:data:`FAMILIES`, :data:`PRESETS`, :data:`LAW_NAMES`, :data:`LAW_PARAMETERS`) read the registry
whenever they are used, so a law registered later (a script's own, or a test's) appears in all
of them.

``linear`` is the paper's law (:class:`~fem_racket.contact.linear.LinearContact`, built from
K_CB and zeta by :func:`fem_racket.simulate`): a name of :data:`LAW_NAMES`, not a family (its
parameters are the paper's ``--kcb``/``--zeta``); a calibrated linear law is a preset of it
(``kawazoe-1997-ball``: the ball alone, in series with a string bed).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterator, Mapping, Sequence
from types import MappingProxyType
from typing import Any

from fem_racket.contact.bed_ball import KAWAZOE_BALL
from fem_racket.contact.hunt_crossley import HuntCrossley
from fem_racket.contact.hysteretic import Hysteretic
from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import LinearContact
from fem_racket.contact.parameters import LawParameter
from fem_racket.contact.series import SeriesBallString

__all__ = [
    "FAMILIES",
    "LAW_NAMES",
    "LAW_PARAMETERS",
    "LiveView",
    "PRESETS",
    "family_parameters",
    "register",
    "register_preset",
    "unregister",
]

_FAMILIES: dict[str, type[ContactLaw]] = {}
_PRESETS: dict[str, ContactLaw] = {}

#: Family name -> law class (read-only, live).
FAMILIES: Mapping[str, type[ContactLaw]] = MappingProxyType(_FAMILIES)
#: Preset name -> law (read-only, live).
PRESETS: Mapping[str, ContactLaw] = MappingProxyType(_PRESETS)


class LiveView(Mapping):
    """A read-only mapping rebuilt from the registry on every use."""

    def __init__(self, build: Callable[[], dict[str, Any]]) -> None:
        self._build = build

    def __getitem__(self, key: str) -> Any:
        return self._build()[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._build())

    def __len__(self) -> int:
        return len(self._build())

    def __repr__(self) -> str:
        return repr(self._build())


class _Names(Sequence):
    """Every name ``--law`` accepts: ``linear``, the families, the presets (live)."""

    def _names(self) -> tuple[str, ...]:
        return ("linear", *_FAMILIES, *_PRESETS)

    def __getitem__(self, i: Any) -> Any:
        return self._names()[i]

    def __len__(self) -> int:
        return len(self._names())

    def __repr__(self) -> str:
        return repr(self._names())


#: Every name ``--law`` accepts (live).
LAW_NAMES: Sequence[str] = _Names()


def family_parameters() -> dict[str, tuple[LawParameter, ...]]:
    """Family name -> its declared parameters."""
    return {name: cls.declared for name, cls in _FAMILIES.items()}


#: Parameter name -> (family, :class:`LawParameter`) over every family (live).
LAW_PARAMETERS: Mapping[str, tuple[str, LawParameter]] = LiveView(
    lambda: {p.name: (f, p) for f, params in family_parameters().items() for p in params}
)


def register(cls: type[ContactLaw]) -> type[ContactLaw]:
    """Add the law family ``cls`` under ``cls.name`` (usable as a class decorator).

    Raises
    ------
    ValueError
        If the name is taken, or a parameter's name or key is another law's, or names no
        dataclass field of ``cls``.
    """
    if not cls.name or cls.name in LAW_NAMES:
        raise ValueError(f"law name {cls.name!r} is empty or taken")
    taken = {p.name for p in LinearContact.declared} | set(LAW_PARAMETERS)
    keys = {p.key for p in LinearContact.declared}
    keys |= {p.key for _, p in LAW_PARAMETERS.values()}
    fields = {f.name for f in dataclasses.fields(cls)}
    for p in cls.declared:
        if p.name in taken or p.key in keys or p.field not in fields:
            raise ValueError(
                f"law {cls.name!r}: parameter {p.name!r} (key {p.key!r}, field {p.field!r}) "
                "is another law's or names no field"
            )
        taken.add(p.name)
        keys.add(p.key)
    _FAMILIES[cls.name] = cls
    return cls


def register_preset(name: str, law: ContactLaw) -> None:
    """Add a named, calibrated law of a registered family or of the linear law."""
    if not name or name in LAW_NAMES or law.name not in (*_FAMILIES, "linear"):
        raise ValueError(f"preset name {name!r} is empty or taken, or its family unknown")
    _PRESETS[name] = law


def unregister(name: str) -> None:
    """Remove the family or preset ``name`` (a family with its presets)."""
    _FAMILIES.pop(name, None)
    _PRESETS.pop(name, None)
    for preset in [k for k, law in _PRESETS.items() if law.name == name]:
        del _PRESETS[preset]


# -- the built-in laws: one line each ------------------------------------------------------
register(HuntCrossley)
register(Hysteretic)
register(SeriesBallString)
# presets (:mod:`fem_racket.contact.presets` says where they come from)
register_preset("kawazoe-1997-nonlinear", Hysteretic(3.182e15, 8.816e16, 8.913))
register_preset("itf-ball", HuntCrossley(3.978e5, 1.690, 0.07212))
register_preset("kawazoe-1997-ball", KAWAZOE_BALL)
