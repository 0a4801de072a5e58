"""Contact laws by name: the families with default parameters, and calibrated presets.

``get_law(name, **params)`` builds a law from a family name (``hunt-crossley``, ``hysteretic``,
``series``) with any parameter overridden, or returns a named preset (which takes no
parameters). ``linear`` is the paper's spring-dashpot, built by
:func:`fem_racket.simulate` from K_CB and zeta, so it maps to None here.

Defaults and presets come from ``fem-racket calibrate`` (:mod:`fem_racket.studies.calibrate`):

- ``kawazoe-1997-nonlinear``: the hysteretic power law fitted, with one parameter set, to the
  paper's clamped contact times (4.53, 3.35, 2.60 ms at 20, 30, 40 m/s, m_B = 0.057 kg) and
  clamped COR 0.83 at 20-40 m/s; it meets every target (contact times within 1.7 %, COR within
  1e-5).
- ``itf-ball``: a Hunt-Crossley ball on a rigid surface fitted to the ITF rules (e = 0.745 at
  7.06 m/s, 0.65 cm under 80.1 N); its COR falls with speed, as measured by Haake, Carre &
  Goodwill (2003). A ball alone, not ball + strings: use it for ball-on-surface studies.
- the family defaults: ``hunt-crossley`` and ``series`` are their families' best fits to the
  paper's targets (neither meets them all: see the module docstrings and the README),
  ``hysteretic`` is ``kawazoe-1997-nonlinear``.
"""

from __future__ import annotations

from typing import Any

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import LinearContact
from fem_racket.contact.parameters import check_values
from fem_racket.contact.registry import (
    FAMILIES,
    LAW_NAMES,
    LAW_PARAMETERS,
    PRESETS,
    LiveView,
)
from fem_racket.validation import InputError, check_choice, show

__all__ = [
    "FILE_KEYS",
    "LAW_NAMES",
    "PRESETS",
    "check_linear_options",
    "family_law",
    "law_named",
    "get_law",
    "law_parameters",
]

#: Parameter -> its key in a run file's [contact] table and in JSON outputs (units in the key,
#: as :meth:`ContactLaw.describe` writes them) (live, from the declarations).
FILE_KEYS = LiveView(lambda: {name: p.key for name, (_, p) in LAW_PARAMETERS.items()})


def get_law(name: str, **params: Any) -> ContactLaw | None:
    """The law called ``name`` with ``params`` (None values ignored) overriding its defaults.

    Returns None for ``"linear"`` (the paper's law, built from K_CB and zeta by ``simulate``).
    """
    check_choice("law", name, LAW_NAMES)
    given = {k: v for k, v in params.items() if v is not None}
    if name == "linear" or name in PRESETS:
        if given:
            raise InputError(
                f"law parameters {sorted(given)} are not allowed with law {show(name)}: "
                f"{'it is built from kcb and zeta' if name == 'linear' else 'it is a preset'}"
            )
        return None if name == "linear" else PRESETS[name]
    declared = FAMILIES[name].declared
    for key in given:
        if key not in {p.name for p in declared}:
            raise InputError(
                f"law parameter {key} is not allowed with law {show(name)}: must be one of "
                f"{sorted(p.name for p in declared)}"
            )
    values = {p.name: p.check(given.get(p.name, p.default)) for p in declared}
    return FAMILIES[name].from_values(values)


def law_parameters(values: dict[str, Any]) -> dict[str, Any]:
    """The family parameters found in ``values`` (e.g. parsed options), None where not given."""
    return {k: values.get(k) for k in sorted(LAW_PARAMETERS)}


def family_law(name: str, values: dict[str, Any]) -> ContactLaw:
    """The law of family ``name`` from every one of its parameters (declared names): numbers,
    or arrays with one value per case for a batch (every law works elementwise). Every value
    and combination is checked (one line naming the first bad case)."""
    check_choice("law", name, tuple(FAMILIES))
    cls = FAMILIES[name]
    check_values(name, cls.declared, cls.conditions, values)
    return cls.from_values(values)


def _preset_name(law: Any) -> str | None:
    """The preset ``law`` is (given by its name or as the preset's own object), else None."""
    if isinstance(law, str):
        return law if law in PRESETS else None
    return next((name for name, preset in PRESETS.items() if preset is law), None)


def law_named(law: Any) -> str:
    """``law`` (a law, or its name) as a message names it: as given, with its family when it is
    a preset (``'itf-ball' (hunt-crossley preset)``, also for the preset's own object)."""
    preset = _preset_name(law)
    if preset is not None:
        return f"{show(preset)} ({PRESETS[preset].name} preset)"
    return show(law if isinstance(law, str) else law.name)


def check_linear_options(law: Any, **options: Any) -> None:
    """Refuse the paper's linear-law options (``kcb``, ``zeta``: not None) with a law ``law``
    (a law, or its name) that fixes its own parameters: any law object (a LinearContact too: it
    holds its K_CB and zeta) and any name but ``"linear"``; None or ``"linear"`` is the paper's
    law, built from them. One line naming the first option given, its value and the law as
    given (:func:`law_named`)."""
    given = [(key, value) for key, value in options.items() if value is not None]
    if not given or law is None or (isinstance(law, str) and law == "linear"):
        return
    named, why = law_named(law), "kcb and zeta set the paper's linear law only"
    if _preset_name(law) is not None:
        why += " (a preset fixes its own parameters)"
    elif isinstance(law, LinearContact):  # the paper's law, as an object: named with its values
        named = law.label()
        why = "the law object fixes K_CB and zeta (give them to LinearContact, or omit law)"
    else:
        why += " (this law has its own parameters)"
    key, value = given[0]
    raise InputError(
        f"{key} = {show(value)} is not allowed with contact law {named}: {why}",
        parameter=key,
        value=value,
    )
