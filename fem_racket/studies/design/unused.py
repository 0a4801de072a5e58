"""Settings a design study would ignore, refused in one line naming them and why.

Each row of :data:`RULES` (and of :data:`SEARCH_RULES` for the search) names an option (a
field of :class:`.options.DesignOptions`' groups: the ``design_problem`` keyword, the run
file's key, the command's long option with dashes), when it is used, and why. An option set
to other than its default where it is not used is refused (:class:`.options.DesignOptions`
and :class:`.options.SearchOptions` check their rows when made, so the library, the run files
and the commands refuse alike); so is one given at its default (named in the options'
``given``: every keyword of ``design_problem``, every option on the command line), as simulate
refuses an option given at any value. A run file's key at its default is not counted as given
(as every run-file key, :func:`fem_racket.cli.options.runfile.given_options`).

Not refused because they are used in every mode: ``power_fraction`` (the report's power
region of each racket, ``result.json``'s ``sweet_spots``, even when no objective is the power
region), ``speeds`` (the report's maps at each speed), ``stiffness_cost``, ``ball_mass``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import fields
from typing import Any

from fem_racket.studies.design.methods import METHODS
from fem_racket.studies.design.variables import MINIMISED, OBJECTIVES
from fem_racket.studies.design.zone import ZONES
from fem_racket.validation import InputError, check_choice, show

__all__ = [
    "METHODS",
    "RULES",
    "SEARCH_RULES",
    "refuse_unused",
    "refuse_unused_search",
    "refuse_power_fraction",
    "refuse_unused_sensitivity",
]

Options = Any  # a DesignOptions (its module imports this one)

#: The objectives averaged over the impact zone (the power region has its own grid).
_ZONED = frozenset({"cor", "ball_speed", *MINIMISED})
_OFF_ZONE = "the power region is measured on its own grid, not over the impact zone"


def _vary(group: str) -> Callable[[Options], bool]:
    return lambda o: group in o.variables.vary


def _zoned(o: Options) -> bool:
    return bool(_ZONED & set(o.goals.objectives))


#: (group, option, used when, why it is not used otherwise; the condition is named in the
#: message as "not allowed <why>").
RULES: tuple[tuple[str, str, Callable[[Options], bool], str], ...] = (
    ("variables", "ei_bounds", _vary("ei"), "without 'ei' in vary: no EI is varied"),
    ("variables", "link_ei", _vary("ei"), "without 'ei' in vary: no EI is varied"),
    ("variables", "rhoa_bounds", _vary("rhoa"), "without 'rhoa' in vary: no rhoA is varied"),
    ("variables", "link_rhoa", _vary("rhoa"), "without 'rhoa' in vary: no rhoA is varied"),
    ("variables", "mass_start", lambda o: bool(o.variables.mass_positions),
     "without mass_positions: there is no added mass"),
    ("variables", "mass_width", lambda o: bool(o.variables.mass_positions),
     "without mass_positions: there is no added mass"),
    ("variables", "mass_bounds", _vary("mass"), "without 'mass' in vary (and mass_positions): "
     "no added mass is varied"),
    ("variables", "position_bounds", _vary("position"), "without 'position' in vary (and "
     "mass_positions): no added mass's centre is varied"),
    ("variables", "interpolation", lambda o: bool(o.variables.ei_points or o.variables.rhoa_points),
     "without ei_points or rhoa_points: there is no profile to interpolate"),
    ("variables", "string_bounds", _vary("string"), "without 'string' in vary: the string bed's "
     "stiffness is not varied"),
    ("variables", "cubic_bounds", _vary("string_cubic"), "without 'string_cubic' in vary: k_3 "
     "is not varied"),
    ("zone_options", "zone", _zoned, f"with objectives {{objectives}}: {_OFF_ZONE}"),
    ("zone_options", "zone_points", _zoned, f"with objectives {{objectives}}: {_OFF_ZONE}"),
    ("zone_options", "zone_range", _zoned, f"with objectives {{objectives}}: {_OFF_ZONE}"),
    ("zone_options", "zone_sigma", _zoned, f"with objectives {{objectives}}: {_OFF_ZONE}"),
    ("zone_options", "zone_range", lambda o: o.zone_options.zone == "uniform",
     "with zone 'node': the node zone spans +-2.5 zone_sigma about mode 1's node"),
    ("zone_options", "zone_sigma", lambda o: o.zone_options.zone == "node",
     "with zone 'uniform': only the node zone is a Gaussian"),
    ("zone_options", "reference", lambda o: o.zone_options.racket_speed is not None,
     "without racket_speed: the racket is at rest (no swing to refer to)"),
    ("zone_options", "pivot", lambda o: o.zone_options.racket_speed is not None,
     "without racket_speed: the racket is at rest (no swing to turn about a pivot)"),
    ("zone_options", "swing_exponent", lambda o: o.zone_options.racket_speed is not None,
     "without racket_speed: the racket is at rest (no swing to slow down)"),
    ("zone_options", "zeta", lambda o: o.law is None,
     "with contact law {law}: it is the damping of the paper's linear law only"),
    ("goals", "grip", lambda o: bool(MINIMISED & set(o.goals.objectives)),
     "with objectives {objectives}: only handle_shock and peak_grip_force hold the racket "
     "in a hand"),
    ("goals", "shock_window", lambda o: bool(MINIMISED & set(o.goals.objectives)),
     "with objectives {objectives}: only handle_shock and peak_grip_force measure the grip "
     "over a window"),
)  # fmt: skip

#: The search's rows (:class:`.options.SearchOptions`, a method's budget): as :data:`RULES`.
_LOCAL = "SLSQP and trust-constr"
SEARCH_RULES: tuple[tuple[str, Callable[[Any], bool], str], ...] = (
    ("maxiter", lambda s: s.method != "nsga2", "with method 'nsga2': it runs generations"),
    ("popsize", lambda s: s.method == "differential-evolution",
     "with method {method!r}: only differential-evolution has a population per variable"),
    ("pop_size", lambda s: s.method == "nsga2", "with method {method!r}: only nsga2 has a "
     "population (differential-evolution: popsize)"),
    ("generations", lambda s: s.method == "nsga2", "with method {method!r}: only nsga2 runs "
     "generations (differential-evolution: maxiter)"),
    ("seed", lambda s: s.method in ("differential-evolution", "nsga2"),
     f"with method {{method!r}}: {_LOCAL} are deterministic, nothing random runs"),
)  # fmt: skip


def _same(value: Any, default: Any) -> bool:
    """Whether an option's value is its default (a list as the tuple it defaults to)."""
    if isinstance(value, Sequence) and not isinstance(value, str):
        value = tuple(value)
    if isinstance(default, Sequence) and not isinstance(default, str):
        default = tuple(default)
    return bool(value == default)


def _default(kind: Any, name: str) -> Any:
    f = next(f for f in fields(kind) if f.name == name)
    return f.default


def refuse_unused(options: Options) -> None:
    """Refuse the first option of :data:`RULES` set where ``options`` would not use it, and
    the added masses' groups in ``vary`` without added masses (the names the rules read
    checked first)."""
    v = options.variables
    check_choice("zone", options.zone_options.zone, ZONES)
    for name in options.goals.objectives:
        check_choice("objective", name, tuple(OBJECTIVES))
    for group in ("mass", "position"):
        if group in v.vary and not v.mass_positions:
            raise InputError(
                f"vary = {show(list(v.vary))} is not allowed without mass_positions: there is "
                f"no added mass to vary ({group!r})"
            )
    law = "'linear'" if options.law is None else show(options.law.name)
    for group, name, used, why in RULES:
        part = getattr(options, group)
        value = getattr(part, name)
        told = name in options.given or not _same(value, _default(type(part), name))
        if told and not used(options):
            context = {"objectives": show(list(options.goals.objectives)), "law": law}
            raise InputError(f"{name} = {show(value)} is not allowed {why.format(**context)}")


def refuse_unused_search(search: Any) -> None:
    """Refuse the first option of :data:`SEARCH_RULES` the search's method would not use
    (the method checked first)."""
    check_choice("method", search.method, METHODS)
    for name, used, why in SEARCH_RULES:
        value = getattr(search, name)
        told = name in search.given or not _same(value, _default(type(search), name))
        if told and not used(search):
            raise InputError(
                f"{name} = {show(value)} is not allowed {why.format(method=search.method)}"
            )


def refuse_unused_sensitivity(problem: Any, output: str) -> None:
    """Refuse what Sobol indices of ``output`` on ``problem`` (a DesignProblem) would not use:
    constraints (the sample spans the variables' whole box), objectives other than ``output``
    (only it is analysed) and, unless the power region is, ``power_fraction``."""
    if problem.constraints:
        names = show([c.name for c in problem.constraints])
        raise InputError(
            f"constraints {names} are not allowed in a sensitivity analysis: it samples the "
            "variables' whole box, constraining nothing"
        )
    others = [o for o in problem.objectives if o != output]
    if others and tuple(problem.objectives) != ("cor",):
        raise InputError(
            f"objective = {show(list(problem.objectives))} is not allowed with output "
            f"{output!r}: a sensitivity analysis computes the indices of its output only"
        )
    default = next(f.default for f in fields(problem) if f.name == "power_fraction")
    if problem.power_fraction != default:
        refuse_power_fraction(problem.power_fraction, output)


def refuse_power_fraction(value: float, output: str) -> None:
    """Refuse ``power_fraction`` = ``value`` (given: the command asks this at any value, the
    problem only at other than its default) for Sobol indices of an ``output`` other than the
    power region."""
    if output != "power_region":
        raise InputError(
            f"power_fraction = {show(value)} is not allowed with output {output!r}: only the "
            "power region is measured at a fraction of v_out's maximum"
        )
