"""Many designs at once: each design's modes, then every design's impacts in one engine call.

Evaluating a design one at a time pays the engine's fixed cost per call (grouping the cases by
reduced size, the root and separation iterations over small blocks) for only its ~60 impacts.
Here a batch of designs is evaluated in two passes:

1. per design: its mesh, closed-form matrices (:func:`fem_racket.frame.hermite.
   assemble_closed_form`), every free-free mode (a 20-cell frame has 40: one small dense
   eigenproblem, no static solves for the modes left out), mass properties and the mode values
   at the zone's (and the power region's) points (their Hermite point vectors are shared by
   the designs on one mesh);
2. all the designs' cases together through :func:`fem_racket.impact.exact.engine.modal_impacts`,
each
   case with its own structure's frequencies (designs with equal mode counts share a call).

The physics is that of :func:`.objectives.evaluate_design` (the same reduction of the modes
above the COR tolerance's cut-off to one pseudo-mode per case); the two agree to round-off and
the engine's tolerance. With the paper's linear law K_CB is the closing speed's K_CB(v) times the
design's ``kcb_factor``. Any other contact law (:attr:`.problem.DesignProblem.law`, with the
design's string-bed k_s and k_3 for the series law) runs every design's cases in one call of the
general integrator (:func:`fem_racket.impact.general.integrator.solve_general`, compiled, each
case on its design's receptance at its impact point, vouched for at the problem's COR tolerance);
e_A is -v_B(t_c) / v_closing as for the linear law.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import kcb_from_speed
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.model import FrameModel
from fem_racket.impact.exact.engine import EngineOptions, modal_impacts
from fem_racket.impact.general.batches import stack_laws, stack_receptances
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.law_impact import receptance
from fem_racket.impact.swing import ball_speed_out
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.swing import SWING_WEIGHT_AXIS, mass_quantities
from fem_racket.studies.design.variables import QUANTITIES
from fem_racket.studies.sweetspots import power_region

__all__ = ["BATCHED", "evaluate_batch"]

#: Objectives evaluated here (the others go design by design).
BATCHED = frozenset({"cor", "ball_speed", "power_region"})


@dataclass(frozen=True, eq=False)
class _Design:
    """One design's structure at its impact points and its quantities."""

    model: FrameModel
    omega: np.ndarray  # (m,)
    values: np.ndarray  # (p, m)
    rigid: np.ndarray  # (p,)
    quantities: dict[str, float]
    inertia_pivot: float


#: Hermite point vectors at the impact points, per node set (designs on one mesh share them).
_FIELDS: OrderedDict[bytes, Any] = OrderedDict()
_FIELDS_KEPT = 8


def _field(model: FrameModel, positions: np.ndarray) -> Any:
    """Sparse (points, ndof) matrix of the deflection at ``positions`` (x/L), cached."""
    key = model.mesh.points.tobytes() + b"|" + positions.tobytes()
    g = _FIELDS.get(key)
    if g is None:
        g = model.fe.field_matrix(positions * model.mesh.length, 0)
        _FIELDS[key] = g
        if len(_FIELDS) > _FIELDS_KEPT:
            _FIELDS.popitem(last=False)
    return g


def _design(problem: DesignProblem, x: np.ndarray, positions: np.ndarray) -> _Design:
    mesh = problem.mesh(x)
    model = FrameModel(assemble_closed_form(mesh))
    modes = model.modes(problem.modes)  # every mode when None
    g = _field(model, positions)
    pivot = SWING_WEIGHT_AXIS if problem.swing is None else problem.swing.pivot
    mq = mass_quantities(mesh, pivot)
    quantities = {
        "mass_kg": mq["mass"],
        "balance_m": mq["cg"],
        "swing_weight_kg_cm2": mq["swing_weight_kg_cm2"],
        "f1_hz": float(modes.frequencies[0]),
    }
    values = np.asarray(g @ modes.shapes)
    rigid = (np.asarray(g @ modes.rigid) ** 2).sum(axis=1)
    return _Design(model, modes.omega, values, rigid, quantities, mq["inertia_pivot"])


def _racket_speeds(problem: DesignProblem, x: np.ndarray, inertia: float) -> np.ndarray:
    """v_r [m/s] of the points ``x`` (x/L) for a racket of that inertia (0 without a swing)."""
    if problem.swing is None:
        return np.zeros_like(x)
    return problem.swing.impact_speed(x, inertia, problem.length)


def _linear_cor(
    problem: DesignProblem,
    built: list[_Design],
    rows: np.ndarray,
    speed: np.ndarray,
    factor: np.ndarray,
) -> np.ndarray:
    """e_A (designs, cases) under the linear law, designs with equal mode counts in one call."""
    kcb = None
    if np.any(factor != 1.0):
        uniq, inv = np.unique(speed, return_inverse=True)
        kcb = np.array([kcb_from_speed(v) for v in uniq])[inv].reshape(speed.shape)
        kcb = kcb * factor[:, None]
    cor = np.empty(speed.shape)
    modes = np.array([d.omega.size for d in built])
    for m in np.unique(modes):
        group = np.flatnonzero(modes == m)
        batch = modal_impacts(
            np.stack([built[i].omega for i in group])[:, None, :],
            np.stack([built[i].values[rows] for i in group]),
            np.stack([built[i].rigid[rows] for i in group]),
            speed=speed[group],
            kcb=None if kcb is None else kcb[group],
            zeta=problem.zeta,
            ball_mass=problem.ball_mass,
            options=EngineOptions(tolerance=problem.tolerance),
        )
        cor[group] = batch.cor
    return cor


def _law_cor(
    problem: DesignProblem,
    models: list[FrameModel],
    positions: np.ndarray,
    speed: np.ndarray,
    laws: list[ContactLaw],
) -> np.ndarray:
    """e_A (designs, cases) of every design's cases under its (nonlinear) law: one call of the
    general integrator for all of them, each case on its design's frame."""
    rec = stack_receptances(
        [receptance(m, positions, problem.ball_mass, problem.modes) for m in models]
    )
    law = stack_laws(laws, [positions.size] * len(laws))
    out = solve_general(law, rec, speed.ravel(), tolerance=problem.tolerance)
    return (-out.ball_velocity / speed.ravel()).reshape(speed.shape)


def _row(values: dict[str, np.ndarray], i: int) -> dict[str, float]:
    return {k: float(v[i]) for k, v in values.items()}


def evaluate_batch(problem: DesignProblem, designs: np.ndarray) -> np.ndarray:
    """Outputs (every quantity, then the objectives) of each row of ``designs`` [SI].

    Every objective of the problem must be in :data:`BATCHED`.
    """
    designs = np.atleast_2d(np.asarray(designs, dtype=float))
    wanted = set(problem.objectives)
    zone = problem.zone.positions if wanted & {"cor", "ball_speed"} else np.empty(0)
    region = problem.region if "power_region" in wanted else np.empty(0)
    points = np.concatenate([zone, region])
    v_in = np.asarray(problem.speeds, dtype=float)
    nd, nz, nr, nv = len(designs), zone.size, region.size, v_in.size
    built = [_design(problem, x, points) for x in designs]
    # cases per design: every speed at every zone point, then the first speed on the region
    v_r = np.array([_racket_speeds(problem, points, d.inertia_pivot) for d in built])
    speed = np.concatenate(
        [(v_in[None, :, None] + v_r[:, None, :nz]).reshape(nd, -1), v_in[0] + v_r[:, nz:]], 1
    )
    rows = np.concatenate([np.tile(np.arange(nz), nv), nz + np.arange(nr)])
    if problem.law is None:
        factor = problem.law_values(designs)["kcb_factor"]
        cor = _linear_cor(problem, built, rows, speed, factor)
    else:
        laws = [problem.design_law(x) for x in designs]
        cor = _law_cor(problem, [d.model for d in built], points[rows], speed, laws)
    out = np.empty((nd, len(QUANTITIES) + len(problem.objectives)))
    cost = problem.stiffness_cost * problem.stiffness(designs)
    zone_cor = cor[:, : nv * nz].reshape(nd, nv, nz)
    zone_vr = v_r[:, None, :nz]
    zone_speed = ball_speed_out(zone_cor, v_in[None, :, None], zone_vr)
    for i, d in enumerate(built):
        out[i, : len(QUANTITIES)] = [d.quantities[q] for q in QUANTITIES]
        for j, name in enumerate(problem.objectives):
            if name == "cor":
                value = float(np.mean(problem.zone.mean(zone_cor[i])))
            elif name == "ball_speed":
                value = float(np.mean(problem.zone.mean(zone_speed[i])))
            else:
                v_out = ball_speed_out(cor[i, nv * nz :], v_in[0], v_r[i, nz:])
                lo, hi = power_region(region, v_out, problem.power_fraction)
                value = (hi - lo) * problem.length
            out[i, len(QUANTITIES) + j] = value - cost[i]
    return out
