"""Options of the design commands (``optimize``, ``sensitivity``): the design problem. A run
file's ``[design]`` (optimize) or ``[sensitivity]`` table takes the same keys (``--ei-bounds`` ->
``ei_bounds``); the starting racket comes from the frame options or the ``[frame]`` table. The
option groups: :mod:`.variables`, :mod:`.zones`, :mod:`.objectives`; where the designs run:
:mod:`.execution`."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from fem_racket.cli.common import add_config_option, add_frame_options, frame_from_args
from fem_racket.cli.options.drawing import add_quiet_option
from fem_racket.cli.options.execution import add_run_options
from fem_racket.cli.options.fields import options_from_args
from fem_racket.cli.options.laws import add_law_options, law_from_args
from fem_racket.cli.options.objectives import add_objective_options, objectives_from_args
from fem_racket.cli.options.runfile import given_options
from fem_racket.cli.options.variables import add_variable_options
from fem_racket.cli.options.zones import add_zone_options

if TYPE_CHECKING:
    from fem_racket.studies.design.problem import DesignProblem

__all__ = ["add_design_options", "add_study_tail", "problem_from_args"]


def add_design_options(parser: argparse.ArgumentParser, *, constraints: bool = True) -> None:
    """The design problem's options (starting racket: the frame options); ``constraints``:
    the bounds on mass, balance, swing weight and f1 (optimize's, not sensitivity's)."""
    add_frame_options(parser)
    add_variable_options(parser)
    add_zone_options(parser)
    add_objective_options(parser, constraints=constraints)
    add_law_options(parser)


def add_study_tail(
    parser: argparse.ArgumentParser, out: dict[str, Any], help_of: dict[str, str]
) -> None:
    """What every design study command ends with: where the designs run (:mod:`.execution`),
    the "output" group (``--out`` with the ``add_argument`` keywords ``out``, ``--overwrite``,
    ``--restart`` when ``help_of`` has it, ``--quiet``), ``--json`` and ``--config`` (``--out``
    the run file's own); ``help_of``: the help of --overwrite, --restart and --json."""
    add_run_options(parser)
    g = parser.add_argument_group("output")
    g.add_argument("--out", **out)
    for flag in ("overwrite", "restart"):
        if flag in help_of:
            g.add_argument(f"--{flag}", action="store_true", help=help_of[flag])
    add_quiet_option(g)
    parser.add_argument("--json", action="store_true", help=help_of["json"])
    add_config_option(parser, private=("out",))


def problem_from_args(args: argparse.Namespace) -> DesignProblem:
    """The design problem the options describe."""
    from fem_racket.studies.design.build import build_problem
    from fem_racket.studies.design.options import DesignOptions, VariableOptions, ZoneOptions

    options = DesignOptions(
        variables=options_from_args(args, VariableOptions),
        zone_options=options_from_args(args, ZoneOptions),
        goals=objectives_from_args(args),
        law=law_from_args(args),
        elements=args.elements,
        given=frozenset(given_options(args)),  # refused where unused, even at the default
    )
    return build_problem(frame_from_args(args), options)
