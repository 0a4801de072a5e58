"""Contact-law parameters as sweep axes: each parameter of a law family fixed or swept.

A family law (:data:`fem_racket.contact.registry.FAMILIES`: ``hunt-crossley``, ``hysteretic``,
``series`` and any registered later) has named parameters (``hc_exponent``, ``k1``, ...; the
command line's ``--hc-exponent`` and the run file's ``contact.hc_exponent``). In a sweep each of
them takes one value (fixed) or several (a dimension), like the impact's parameters
(:mod:`fem_racket.studies.grid`). Every law works elementwise on arrays, so a batch of cases
with different parameter values is one law whose parameters are arrays of one value per case
(:func:`case_law`): the general integrator advances them together. Each value is checked
against its bounds when parsed, and every combination of the grid against the law's conditions
(k2 >= k1 ...) before any work (:func:`check_law_grid`), as is the law referred to every ball
mass of the grid (:func:`struck_laws`: a LinearContact's zeta is that ball's).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.parameters import check_values
from fem_racket.contact.presets import family_law
from fem_racket.contact.registry import FAMILIES, LAW_PARAMETERS
from fem_racket.validation import InputError, show

__all__ = [
    "case_law",
    "check_law_grid",
    "check_law_value",
    "family_of",
    "law_attributes",
    "struck_laws",
    "sweep_law_values",
]


def family_of(law: ContactLaw | None) -> str | None:
    """The family of ``law`` (presets included: ``kawazoe-1997-nonlinear`` is hysteretic);
    None for the paper's linear law and any law without named parameters."""
    name = getattr(law, "name", None)
    return name if name in FAMILIES else None


def check_law_value(name: str, value: Any) -> float:
    """One value of the law parameter ``name`` checked against its bounds (one-line
    :class:`InputError` naming the parameter); the conditions between parameters are checked
    on the whole grid (:func:`check_law_grid`)."""
    return LAW_PARAMETERS[name][1].check(value)


def struck_laws(law: ContactLaw, ball_mass: Any) -> list[ContactLaw]:
    """``law`` as each ball of ``ball_mass`` [kg] (a number, or the swept values) meets it
    (:meth:`~fem_racket.contact.law.ContactLaw.for_ball`: a LinearContact keeps K_CB and C_CB,
    its zeta that ball's; a ball it damps critically refused in one line, as simulate does)."""
    return [law.for_ball(float(m)) for m in np.atleast_1d(ball_mass)]


def law_attributes(law: ContactLaw, ball_mass: Any) -> dict[str, Any]:
    """The law as it describes itself, keys ``contact_*``, as the balls of ``ball_mass`` [kg]
    meet it (:func:`struck_laws`): a value that differs between swept ball masses is listed,
    one per ball mass in their order."""
    each = [struck.describe() for struck in struck_laws(law, ball_mass)]
    return {
        f"contact_{k}": v if all(d[k] == v for d in each) else [d[k] for d in each]
        for k, v in each[0].items()
    }


def check_law_grid(law: ContactLaw | None, values: Mapping[str, Any]) -> None:
    """Check every combination of the law parameters in ``values`` (a number or a 1-D array of
    swept values each) against the law's bounds and conditions, and the law referred to every
    ball mass given (:func:`struck_laws`), before any work; a one-line :class:`InputError`
    names the first case that fails (e.g. k2 < k1)."""
    if law is not None and values.get("ball_mass") is not None:
        struck_laws(law, values["ball_mass"])
    family = family_of(law)
    if family is None:
        return
    cls = FAMILIES[family]
    grid = np.meshgrid(
        *(np.atleast_1d(np.asarray(values[p.name], dtype=float)) for p in cls.declared),
        indexing="ij",
        sparse=True,
    )
    cases = {p.name: a for p, a in zip(cls.declared, grid, strict=True)}
    check_values(family, cls.declared, cls.conditions, cases)


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
                f"be a family with parameters ({', '.join(FAMILIES)})"
            )
        return {}
    spec = [p.name for p in FAMILIES[family].declared]
    for key in given:
        if key not in spec:
            raise InputError(
                f"law parameter {key} is not allowed with law {show(family)}: must be one of "
                f"{sorted(spec)}"
            )
    own = law.values()
    return {k: given.get(k, own[k]) for k in spec}


def case_law(law: ContactLaw | None, values: Mapping[str, Any], n: int | None = None) -> Any:
    """``law`` with its parameters from ``values`` (option names -> a number or one value per
    case); with ``n`` every parameter is an array of n values (a batch). Returns ``law`` itself
    when it has no named parameters."""
    family = family_of(law)
    if family is None:
        return law
    params = {p.name: values[p.name] for p in FAMILIES[family].declared}
    if n is not None:
        params = {
            k: np.broadcast_to(np.asarray(v, dtype=float), (n,)).copy() for k, v in params.items()
        }
    else:
        params = {k: float(v) for k, v in params.items()}
    return family_law(family, params)
