"""A run file's design studies in Python: :meth:`RunConfig.optimize` = ``fem-racket optimize
--config`` and :meth:`RunConfig.sensitivity` = ``fem-racket sensitivity --config``.

The starting racket comes from ``[frame]`` (with its lead), the ball, the law and the swing from
the core tables; the command's table (``[design]`` for optimize, ``[sensitivity]``) takes the
command's long options as keys (``--ei-bounds`` -> ``ei_bounds``, lists as arrays), the fields
of :class:`~fem_racket.studies.design.options.DesignOptions`' groups, the search budget and
where the designs run. Unknown keys are refused with a "did you mean"; keys of the impact's
tables the commands take no option for as the commands refuse them
(:mod:`fem_racket.io.config_unused`).
"""

from __future__ import annotations

import os
from dataclasses import fields
from typing import Any

from fem_racket.io.config_keys import reject_unknown
from fem_racket.io.config_tables import flag, integer, number, overwrite_set, text
from fem_racket.io.constants import CONSTRAINTS
from fem_racket.validation import InputError, show

__all__ = ["CONSTRAINTS", "optimize_file", "sensitivity_file"]

#: The options of the core tables a design takes (argparse dests): the swing and the ball.
_CORE = ("ball_mass", "zeta", "racket_speed", "reference", "pivot")
#: Keys of both tables that set where the designs run, how they print or where files go.
_RUN = ("backend", "workers", "scheduler", "seed", "quiet", "json", "out", "overwrite")
#: The search's keys (optimize) and the analysis's (sensitivity), with their defaults.
_SEARCH = {"method": "SLSQP", "maxiter": 100, "popsize": 10, "pop_size": 50, "generations": 100}
_SOBOL = {"output": None, "designs": 10_000}
#: The tables' keys of one number, flag or text, converted as the commands' parsers convert
#: them (choices, lists and ranges are checked where they are read).
_TYPED: dict[str, Any] = {
    **dict.fromkeys(("designs", "generations", "maxiter", "pop_size", "popsize", "seed",
                     "workers", "zone_points"), integer),
    **dict.fromkeys(("mass_start", "power_fraction", "shock_window", "stiffness_cost",
                     "swing_exponent", "zone_sigma"), number),
    **dict.fromkeys(("json", "link_ei", "overwrite", "quiet", "restart"), flag),
    "out": text,
    "scheduler": text,
}  # fmt: skip
#: Default output of optimize (the command's; sensitivity writes nothing by default).
DEFAULT_DESIGN_OUT = os.path.join("output", "design")
RunConfig = Any


def _listed(key: str, value: Any, item: type) -> list:
    """A list option's value: an array (of values, or of text like the command line's "0.3,0.5"),
    as the command takes it."""
    if not isinstance(value, list):
        raise InputError(f"{key} = {show(value)} is not allowed: must be an array")
    words = [w for v in value for w in (v.replace(",", " ").split() if isinstance(v, str) else [v])]
    if item is float and any(isinstance(w, bool) for w in words):
        raise InputError(f"{key} = {show(value)} is not allowed: must be an array of numbers")
    try:
        return [item(w) for w in words]
    except (TypeError, ValueError):
        kind = "numbers" if item is float else "names"
        message = f"{key} = {show(value)} is not allowed: must be an array of {kind}"
        raise InputError(message) from None


def _range(key: str, value: Any) -> tuple:
    """A constraint's range: ``"start"`` or LOW,HIGH."""
    if value == "start":
        return ("start",)
    out = _listed(key, value.split(",") if isinstance(value, str) else value, float)
    if len(out) != 2:
        raise InputError(f"{key} = {show(value)} is not allowed: give LOW,HIGH or 'start'")
    return tuple(out)


def _group(kind: type, values: dict[str, Any], table: str) -> Any:
    """The option group ``kind`` from ``values`` (list fields converted)."""
    out = {}
    for f in fields(kind):
        if f.name in values and values[f.name] is not None and "Sequence" in str(f.type):
            item = str if f.name == "vary" else float
            out[f.name] = _listed(f"{table}.{f.name}", values[f.name], item)
        elif f.name in values:
            out[f.name] = values[f.name]
    return kind(**out)


def _problem(cfg: RunConfig, command: str, table: str, rest: dict[str, Any]) -> tuple:
    """The design problem of ``cfg`` and the table's values of ``rest`` (search, run keys)."""
    from fem_racket.io.config_run import file_frame, file_law
    from fem_racket.io.config_unused import refuse_unused
    from fem_racket.studies.design.build import build_problem
    from fem_racket.studies.design.options import (
        DesignOptions,
        ObjectiveOptions,
        VariableOptions,
        ZoneOptions,
    )
    from fem_racket.studies.grid_values import LAW_PARAMETERS

    names = [f.name for kind in (VariableOptions, ZoneOptions) for f in fields(kind)]
    frame = ("ei1", "ei2", "mesh", "segments", "elements", "add_mass", "law")
    refuse_unused(cfg, command, {*names, *frame, *LAW_PARAMETERS})
    goals = ("objective", "power_fraction", "stiffness_cost", "grip", "shock_window")
    own = {k.replace("-", "_"): v for k, v in cfg.table(table).items()}
    bounds = CONSTRAINTS if command == "optimize" else {}  # sensitivity constrains nothing
    allowed = [k for k in names if k not in _CORE] + [*goals, *bounds, *rest, *_RUN]
    reject_unknown(own, allowed, table)
    own = {k: _TYPED[k](f"{table}.{k}", v) if k in _TYPED else v for k, v in own.items()}
    d = cfg.defaults()
    values = {**{k: d[k] for k in _CORE if k in d}, **own}
    goal = {k: own[k] for k in goals[1:] if k in own}
    objectives = ObjectiveOptions(
        objectives=_listed(f"{table}.objective", own.get("objective", ["cor"]), str),
        constraints={
            q: _range(f"{table}.{k}", own[k]) if k in own else None
            for k, (q, _) in CONSTRAINTS.items()
        },
        **goal,
    )
    options = DesignOptions(
        variables=_group(VariableOptions, values, table),
        zone_options=_group(ZoneOptions, values, table),
        goals=objectives,
        law=file_law(cfg),
        elements=d.get("elements", 20),
    )
    problem = build_problem(file_frame(cfg), options)
    return problem, {k: own.get(k, v) for k, v in rest.items()}, own


def _execution(own: dict[str, Any]) -> Any:
    from fem_racket.studies.design.options import ExecutionOptions

    keys = ("backend", "workers", "scheduler")
    return ExecutionOptions(**{k: own.get(k) for k in keys}, progress=False)


def _overwrite(cfg: RunConfig, own: dict[str, Any]) -> bool:
    """``overwrite`` of the command's table, else ``[output] overwrite``, as the commands."""
    return bool(own.get("overwrite", cfg.defaults().get("overwrite", False)))


def optimize_file(cfg: RunConfig, out: Any = None, *, restart: bool = False) -> Any:
    """The optimisation ``fem-racket optimize --config`` runs on ``cfg`` (its files written
    into ``out``, else ``[design] out``, else ``output/design``, as the command: an existing
    folder replaced with ``overwrite``, or at the default when it holds an earlier study); the
    :func:`~fem_racket.io.design_study.run_optimization` result."""
    from fem_racket.io.config_rerun import rerun_overwrite
    from fem_racket.io.design_study import OptimizationRun, OutputOptions, run_optimization
    from fem_racket.studies.design.options import SearchOptions

    problem, search, own = _problem(cfg, "optimize", "design", {**_SEARCH, "restart": False})
    restart = restart or bool(search.pop("restart"))
    if search["method"] == "nsga2":
        from fem_racket.extras import require

        require("pymoo", "RunConfig.optimize with method nsga2")
    folder = out or own.get("out") or DEFAULT_DESIGN_OUT
    default = os.fspath(folder) == DEFAULT_DESIGN_OUT  # the command's own study is replaced
    files = OutputOptions(folder, rerun_overwrite(_overwrite(cfg, own), default, [folder]))
    search = SearchOptions(**search, seed=own.get("seed", 1))
    return run_optimization(OptimizationRun(problem, search, _execution(own), files, restart))


def sensitivity_file(cfg: RunConfig, out: Any = None) -> Any:
    """The Sobol indices ``fem-racket sensitivity --config`` computes on ``cfg`` (the chart
    written to ``out``, else ``[sensitivity] out``, else nothing)."""
    from fem_racket.extras import require
    from fem_racket.io.design_study import OutputOptions, SensitivityRun, run_sensitivity

    require("SALib", "RunConfig.sensitivity")
    problem, sobol, own = _problem(cfg, "sensitivity", "sensitivity", dict(_SOBOL))
    out = out or own.get("out")
    # overwrite without out is refused, as the command refuses it: [output]'s here, naming
    # its key; the table's own by OutputOptions
    if not out and "overwrite" not in own and (given := overwrite_set(cfg, "sensitivity")):
        raise InputError(f"{given} is not allowed without out: nothing is written")
    files = OutputOptions(out, _overwrite(cfg, own))
    run = SensitivityRun(problem, sobol["output"], sobol["designs"], own.get("seed", 1),
                         _execution(own), files)  # fmt: skip
    return run_sensitivity(run)
