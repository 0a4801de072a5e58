"""What a design study reports about a racket: mass properties, modes, maps and sweet spots.

The e_A / v_out maps and sweet spots are those of ``fem-racket map``
(:func:`fem_racket.studies.racket_map.racket_map`, one per ball speed), with the problem's swing
for this racket (slower for a heavier one, :mod:`.swing`): centre of percussion for the pivot,
nodes of modes 1 and 2, maximum e_A, maximum v_out and the power region.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.model import FrameModel
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.swing import SWING_WEIGHT_AXIS, mass_quantities
from fem_racket.studies.racket_map import RacketMap, racket_map

__all__ = ["MAP_POSITIONS", "design_maps", "racket_report"]

#: Positions x/L of the e_A / v_out maps (the string face and the throat).
MAP_POSITIONS = np.linspace(0.45, 0.99, 55)


def design_maps(
    problem: DesignProblem, x: np.ndarray, positions: np.ndarray = MAP_POSITIONS
) -> list[RacketMap]:
    """The map of design ``x`` at each of the problem's ball speeds."""
    mesh = problem.mesh(x)
    model = FrameModel(assemble_closed_form(mesh))
    swing: dict[str, Any] = {"pivot": SWING_WEIGHT_AXIS}  # for the centre of percussion
    if problem.swing is not None:
        s = problem.swing
        inertia = mass_quantities(mesh, s.pivot)["inertia_pivot"]
        swing = {
            "racket_speed": s.racket_speed(inertia),
            "reference": s.reference,
            "pivot": s.pivot,
        }
    law = problem.design_law(x)
    contact: dict[str, Any] = {"law": law}  # the string bed as the objectives see it
    if law is None:
        factor = float(problem.law_values(np.asarray(x, dtype=float))["kcb_factor"])
        contact = {"zeta": problem.zeta, "kcb_factor": factor}
    return [
        racket_map(
            model,
            speed=v,
            positions=positions,
            ball_mass=problem.ball_mass,
            modes=problem.modes,
            power_fraction=problem.power_fraction,
            **contact,
            **swing,
        )
        for v in problem.speeds
    ]


def racket_report(
    problem: DesignProblem, x: np.ndarray, maps: list[RacketMap] | None = None
) -> dict[str, Any]:
    """Mass properties, the first four frequencies, and per ball speed the sweet spots.

    ``maps``: the design's :func:`design_maps` if already computed.
    """
    mesh = problem.mesh(x)
    model = FrameModel(assemble_closed_form(mesh))
    fm = model.modes(4)
    pivot = SWING_WEIGHT_AXIS if problem.swing is None else problem.swing.pivot
    mq = mass_quantities(mesh, pivot)
    maps = design_maps(problem, x) if maps is None else maps
    out = {
        "length_m": mesh.length,
        "mass_kg": mq["mass"],
        "balance_m": mq["cg"],
        "balance_x_over_l": mq["cg"] / mesh.length,
        "inertia_cg_kg_m2": mq["inertia_cg"],
        "swing_weight_kg_cm2": mq["swing_weight_kg_cm2"],
        "frequencies_hz": fm.frequencies.tolist(),
        "sweet_spots": [
            {"speed_m_s": v, **m.spots.summary(), **m.swing.summary()}
            for v, m in zip(problem.speeds, maps, strict=True)
        ],
    }
    return out
