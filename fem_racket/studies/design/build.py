"""A design problem from plain settings (the CLI's options, a run file's ``[design]`` table).

``build_problem(start, DesignOptions(...))`` (or ``design_problem(start, objectives=("cor",),
constraints={"mass_kg": ("start",)}, ...)`` with the options' fields as flat keywords, checked
by :meth:`.options.DesignOptions.from_keywords`) builds a
:class:`~.problem.DesignProblem` on the starting racket (:mod:`.options`): each constraint is
``None`` (absent), a
``(low, high)`` pair, or ``("start",)`` (equal to the starting racket's value: "keep its mass");
the zone is ``"uniform"`` over ``zone_range`` or ``"node"``, a Gaussian about the starting
racket's mode-1 node on the string face (Hatze 1994). ``ei_points`` / ``rhoa_points`` (control
stations x/L) make EI(x) / rhoA(x) smooth profiles (:mod:`.profiles`); ``vary`` "position"
frees the added masses' centres within ``position_bounds``; "string" frees the string bed's
stiffness (the factor on K_CB for the paper's linear law, k_s of the series law, within
``string_bounds``) and "string_cubic" the series law's k_3 (``cubic_bounds``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from typing import Any

import numpy as np

from fem_racket.frame.hand import GRIPS
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.mesh import FrameMesh, frame_from_mesh, frame_mesh
from fem_racket.frame.modal import mode_nodes
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame, standard_frame
from fem_racket.impact.constants import DEFAULT_REFERENCE
from fem_racket.studies.design.options import DesignOptions, VariableOptions
from fem_racket.studies.design.paper_problem import paper_problem
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.swing import SwingModel, mass_quantities
from fem_racket.studies.design.variables import QUANTITIES, Constraint
from fem_racket.studies.design.zone import gaussian_zone, uniform_zone
from fem_racket.validation import InputError, check_choice

__all__ = ["build_problem", "design_problem", "mode1_node"]


def mode1_node(frame: Frame, elements: int = 20) -> float:
    """The first free-free mode's node on the string face (x/L > 0.5) of ``frame``."""
    model = FrameModel(assemble_closed_form(frame_mesh(frame, elements)))
    nodes = mode_nodes(model.fe, model.modes(1).shapes[:, 0])
    face = nodes[nodes > 0.5]
    if face.size == 0:
        raise InputError("zone = 'node' is not allowed: mode 1 has no node beyond 0.5 L")
    return float(face[0])


def _start_values(frame: Frame, elements: int) -> dict[str, float]:
    mesh = frame_mesh(frame, elements)
    mq = mass_quantities(mesh)
    model = FrameModel(assemble_closed_form(mesh))
    return {
        "mass_kg": mq["mass"],
        "balance_m": mq["cg"],
        "swing_weight_kg_cm2": mq["swing_weight_kg_cm2"],
        "f1_hz": float(model.modes(1).frequencies[0]),
    }


def _pair(name: str, value: Sequence[float]) -> tuple[float, float]:
    if len(value) != 2 or not value[0] < value[1]:
        raise InputError(f"{name} = {list(value)} is not allowed: give LOW,HIGH with LOW < HIGH")
    return float(value[0]), float(value[1])


def design_problem(start: Frame | FrameMesh | None = None, **options: Any) -> DesignProblem:
    """:func:`build_problem` with the fields of :class:`.options.DesignOptions`' groups as
    keywords (``objectives=("cor",)``, ``zone_points=20``, ``law=...``; an unknown one is
    refused naming the nearest)."""
    return build_problem(start, DesignOptions.from_keywords(**options))


def build_problem(start: Frame | FrameMesh | None, options: DesignOptions) -> DesignProblem:
    """Build a design problem; see the module docstring and :func:`.paper_problem.paper_problem`.

    Parameters
    ----------
    start : Frame or FrameMesh, optional
        The starting racket (the paper's when None); a mesh is read as its piecewise-uniform
        frame.
    options : DesignOptions
        The variables, zone, ball and swing, objectives and constraints, law and mesh.
    """
    z, goals, elements = options.zone_options, options.goals, options.elements
    check_choice("grip", goals.grip, tuple(GRIPS))
    frame = standard_frame() if start is None else start
    if isinstance(frame, FrameMesh):
        frame = frame_from_mesh(frame)
    base = _start_values(frame, elements)
    cons = []
    for name, value in (goals.constraints or {}).items():
        check_choice("constraint", name, tuple(QUANTITIES))
        if value is None:
            continue
        if len(value) == 1 and value[0] == "start":
            cons.append(Constraint(name, base[name], base[name]))
        else:
            cons.append(Constraint(name, *_pair(name, value)))
    if z.zone == "uniform":
        lo, hi = _pair("zone range", z.zone_range)
        zone = uniform_zone(lo, hi, z.zone_points)
    else:
        zone = gaussian_zone(mode1_node(frame, elements), z.zone_sigma, z.zone_points)
    swing = None
    if z.racket_speed is not None:
        reference = DEFAULT_REFERENCE if z.reference is None else z.reference
        swing = SwingModel(z.racket_speed, reference, z.pivot, z.swing_exponent)
    ball = {k: v for k, v in (("ball_mass", z.ball_mass), ("zeta", z.zeta)) if v is not None}
    return paper_problem(
        frame,
        _checked_variables(options.variables),
        options.law,
        zone=zone,
        speeds=tuple(float(v) for v in z.speeds),
        swing=swing,
        constraints=tuple(cons),
        objectives=tuple(goals.objectives),
        stiffness_cost=goals.stiffness_cost,
        power_fraction=goals.power_fraction,
        elements=elements,
        hand=GRIPS[goals.grip],
        shock_window=goals.shock_window,
        **ball,
        region=np.linspace(0.5, 0.98, 25),
    )


def _checked_variables(v: VariableOptions) -> VariableOptions:
    """``v`` with every bounds pair checked (LOW < HIGH) and the sequences as tuples."""

    def pair(name: str, value: Sequence[float] | None) -> tuple[float, float] | None:
        return None if value is None else _pair(name.replace("_", " "), value)

    return replace(
        v,
        **{
            name: pair(name, getattr(v, name))
            for name in (
                "ei_bounds",
                "rhoa_bounds",
                "mass_bounds",
                "position_bounds",
                "string_bounds",
                "cubic_bounds",
            )
        },
        **{
            name: tuple(getattr(v, name))
            for name in ("boundaries", "vary", "mass_positions", "ei_points", "rhoa_points")
        },
    )
