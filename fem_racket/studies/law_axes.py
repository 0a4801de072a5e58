"""Contact-law parameters as sweep axes: each parameter of a law family fixed or swept.

A family law (:data:`fem_racket.contact.presets.FAMILY_PARAMETERS`: ``hunt-crossley``,
``hysteretic``, ``series``) has named parameters (``hc_exponent``, ``k1``, ...; the command
line's ``--hc-exponent`` and the run file's ``contact.hc_exponent``). In a sweep each of them
takes one value (fixed) or several (a dimension), like the impact's parameters
(:mod:`fem_racket.studies.grid`). Every law works elementwise on arrays, so a batch of cases
with different parameter values is one law whose parameters are arrays of one value per case
(:func:`case_law`): the general integrator advances them together.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.presets import FAMILY_PARAMETERS, FILE_KEYS, family_law, get_law
from fem_racket.validation import InputError, show

__all__ = [
    "LAW_DESCRIPTIONS",
    "case_law",
    "check_law_value",
    "family_of",
    "law_values",
    "owner",
    "sweep_law_values",
]

#: Law parameter -> description (the equations are in each law's module).
LAW_DESCRIPTIONS = {
    "hc_stiffness": "Hunt-Crossley stiffness k of F = k delta^n (1 + alpha delta')",
    "hc_exponent": "Hunt-Crossley exponent n",
    "hc_alpha": "Hunt-Crossley damping alpha = lambda / k",
    "k1": "hysteretic loading stiffness k1 (F = k1 delta^n)",
    "k2": "hysteretic unloading stiffness k2",
    "hyst_exponent": "hysteretic exponent n",
    "ball_stiffness": "series law: ball stiffness",
    "ball_damping": "series law: ball damping",
    "string_stiffness": "series law: string-bed stiffness k_s",
    "string_cubic": "series law: string-bed cubic stiffness k_3",
}


def owner(name: str) -> str:
    """The family whose parameter ``name`` is."""
    return next(f for f, spec in FAMILY_PARAMETERS.items() if name in spec)


def family_of(law: ContactLaw | None) -> str | None:
    """The family of ``law`` (presets included: ``kawazoe-1997-nonlinear`` is hysteretic);
    None for the paper's linear law and any law without named parameters."""
    name = getattr(law, "name", None)
    return name if name in FAMILY_PARAMETERS else None


def law_values(law: ContactLaw) -> dict[str, Any]:
    """The parameters of a family law by their option names (``hc_exponent`` ...)."""
    by_key = {key: name for name, key in FILE_KEYS.items()}
    return {by_key[k]: v for k, v in law.parameters().items()}


def check_law_value(name: str, value: Any) -> float:
    """One value of the law parameter ``name``, checked as the law checks it (one-line
    :class:`InputError` naming the parameter)."""
    law = get_law(owner(name), **{name: value})
    return float(law_values(law)[name])


def sweep_law_values(law: ContactLaw | None, given: Mapping[str, Any]) -> dict[str, Any]:
    """The law parameters a sweep holds: every parameter of ``law``'s family, ``given`` ones
    (not None) overriding the law's own; {} for a law without named parameters."""
    given = {k: v for k, v in given.items() if v is not None}
    family = family_of(law)
    if family is None:
        if given:
            what = "linear" if law is None else law.name
            raise InputError(
                f"law parameters {sorted(given)} are not allowed with law {show(what)}: must "
                f"be a family with parameters ({', '.join(FAMILY_PARAMETERS)})"
            )
        return {}
    spec = FAMILY_PARAMETERS[family]
    for key in given:
        if key not in spec:
            raise InputError(
                f"law parameter {key} is not allowed with law {show(family)}: must be one of "
                f"{sorted(spec)}"
            )
    own = law_values(law)
    return {k: given.get(k, own[k]) for k in spec}


def case_law(law: ContactLaw | None, values: Mapping[str, Any], n: int | None = None) -> Any:
    """``law`` with its parameters from ``values`` (option names -> a number or one value per
    case); with ``n`` every parameter is an array of n values (a batch). Returns ``law`` itself
    when it has no named parameters."""
    family = family_of(law)
    if family is None:
        return law
    params = {k: values[k] for k in FAMILY_PARAMETERS[family]}
    if n is not None:
        params = {
            k: np.broadcast_to(np.asarray(v, dtype=float), (n,)).copy() for k, v in params.items()
        }
    else:
        params = {k: float(v) for k, v in params.items()}
    return family_law(family, params)
