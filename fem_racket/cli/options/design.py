"""Options of the design commands (``optimize``, ``sensitivity``): the design problem. A run
file's ``[design]`` (optimize) or ``[sensitivity]`` table takes the same keys (``--ei-bounds`` ->
``ei_bounds``); the starting racket comes from the frame options or the ``[frame]`` table. The
option groups: :mod:`.variables`, :mod:`.zones`, :mod:`.objectives`; where the designs run:
:mod:`.execution`."""

from __future__ import annotations

import argparse
from typing import Any

from fem_racket.cli.common import add_frame_options, frame_from_args
from fem_racket.cli.options.laws import add_law_options, law_from_args
from fem_racket.cli.options.objectives import add_objective_options, objectives_from_args
from fem_racket.cli.options.variables import add_variable_options, variables_from_args
from fem_racket.cli.options.zones import add_zone_options, zone_from_args
from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.problem import DesignProblem

__all__ = ["add_design_options", "problem_from_args"]


def add_design_options(parser: argparse.ArgumentParser) -> None:
    """The design problem's options (starting racket: the frame options)."""
    add_frame_options(parser)
    add_variable_options(parser)
    add_zone_options(parser)
    add_objective_options(parser)
    add_law_options(parser)


def problem_from_args(args: argparse.Namespace) -> DesignProblem:
    """The design problem the options describe."""
    kwargs: dict[str, Any] = {
        **variables_from_args(args),
        "law": law_from_args(args),
        **zone_from_args(args),
        **objectives_from_args(args),
        "elements": args.elements,
    }
    return design_problem(frame_from_args(args), **kwargs)
