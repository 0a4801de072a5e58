"""What a design study reports about a racket: mass properties, modes, sweet spots, maps.

Sweet spots (DESIGN section 8): the node of mode 1 on the string face (no vibration); the centre
of percussion for the pivot p, x_COP = x_CG + I_CG / (M (x_CG - p)) (no reaction at the hand);
the points of maximum e_A and, with a swing, of maximum v_out, found on the map's grid and refined
by a parabola through the best grid point and its neighbours.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.modal import mode_nodes
from fem_racket.frame.model import FrameModel
from fem_racket.studies.design.objectives import curves
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.swing import SWING_WEIGHT_AXIS, mass_quantities

__all__ = ["MAP_POSITIONS", "argmax_refined", "racket_map", "racket_report"]

#: Positions x/L of the e_A / v_out maps (the string face and the throat).
MAP_POSITIONS = np.linspace(0.45, 0.99, 55)


def argmax_refined(x: np.ndarray, y: np.ndarray) -> float:
    """Position of the maximum of samples y(x): the vertex of the parabola through the best
    sample and its neighbours (the best sample itself at an end of the grid)."""
    i = int(np.argmax(y))
    if i == 0 or i == len(y) - 1:
        return float(x[i])
    xs, ys = x[i - 1 : i + 2], y[i - 1 : i + 2]
    a, b, _ = np.polyfit(xs, ys, 2)
    return float(np.clip(-b / (2 * a), xs[0], xs[-1])) if a < 0 else float(x[i])


def racket_map(
    problem: DesignProblem, x: np.ndarray, positions: np.ndarray = MAP_POSITIONS
) -> dict[str, np.ndarray]:
    """e_A and v_out [m/s] at ``positions`` x/L for each of the problem's speeds (rows)."""
    mesh = problem.mesh(x)
    model = FrameModel(assemble_closed_form(mesh))
    pivot = SWING_WEIGHT_AXIS if problem.swing is None else problem.swing.pivot
    mq = mass_quantities(mesh, pivot)
    out = curves(problem, model, positions, mq["inertia_pivot"])
    out["positions"] = np.asarray(positions)
    return out


def racket_report(
    problem: DesignProblem, x: np.ndarray, modes: int = 4, curves_map: dict | None = None
) -> dict[str, Any]:
    """Mass properties, the first ``modes`` frequencies and nodes, and the sweet spots.

    ``curves_map``: the design's :func:`racket_map` if already computed.
    """
    mesh = problem.mesh(x)
    model = FrameModel(assemble_closed_form(mesh))
    fm = model.modes(modes)
    pivot = SWING_WEIGHT_AXIS if problem.swing is None else problem.swing.pivot
    mq = mass_quantities(mesh, pivot)
    length = mesh.length
    nodes = [mode_nodes(model.fe, fm.shapes[:, k]).tolist() for k in range(fm.omega.size)]
    face = [n for n in nodes[0] if n > 0.5]
    cop = mq["cg"] + mq["inertia_cg"] / (mq["mass"] * (mq["cg"] - pivot))
    m = racket_map(problem, x) if curves_map is None else curves_map
    spots: dict[str, Any] = {
        "node_x_over_l": face[0] if face else None,
        "cop_x_over_l": cop / length,
        "pivot_m": pivot,
        "max_apparent_cor_x_over_l": [argmax_refined(m["positions"], c) for c in m["cor"]],
    }
    if problem.swing is not None:
        spots["max_ball_speed_x_over_l"] = [
            argmax_refined(m["positions"], v) for v in m["ball_speed"]
        ]
    return {
        "length_m": length,
        "mass_kg": mq["mass"],
        "balance_m": mq["cg"],
        "balance_x_over_l": mq["cg"] / length,
        "inertia_cg_kg_m2": mq["inertia_cg"],
        "swing_weight_kg_cm2": mq["swing_weight_kg_cm2"],
        "frequencies_hz": fm.frequencies.tolist(),
        "nodes_x_over_l": nodes,
        "sweet_spots": spots,
        "speeds_m_s": list(problem.speeds),
    }
