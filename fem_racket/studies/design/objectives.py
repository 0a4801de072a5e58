"""Objectives and constrained quantities of racket designs.

For each design: its mesh, free-free modes and mass properties, then e_A over the impact zone
at every incoming ball speed v_in. With a swing (:mod:`.swing`) the impact point moves at v_r(x)
towards the ball, the strings meet the ball at v_in + v_r (which sets K_CB) and the ball leaves
at v_out = e_A v_in + (1 + e_A) v_r. Without a swing v_r = 0.

Objectives (maximised), weights w_k of the zone, n_v speeds:

- ``cor``: (1/n_v) sum_v sum_k w_k e_A(x_k, v);
- ``ball_speed``: (1/n_v) sum_v sum_k w_k v_out(x_k, v) [m/s];
- ``power_region``: the length [m] of the interval about the maximum of v_out (first speed) on
  the region grid where v_out stays at least ``power_fraction`` of it
  (:func:`fem_racket.studies.sweetspots.power_region`, as ``fem-racket map``); Hatze (1994)
  measures the same idea as an area on the string face (> 100 cm^2 on quality rackets).

Objectives minimised, of the racket held by the problem's hand (:mod:`fem_racket.frame.hand`,
exact path :mod:`fem_racket.impact.held.modal`) struck at rest at the closing speed v_in + v_r
(the swing being a rigid motion of racket and hand):

- ``handle_shock``: (1/n_v) sum_v sum_k w_k RMS of the grip force's vibration part over the
  shock window [N] (:mod:`fem_racket.impact.held.shock`);
- ``peak_grip_force``: the same mean of the largest grip force over the window [N].

A stiffness price ``stiffness_cost`` [1/(N m^2)] times EI_1 is subtracted from each maximised
objective and added to each minimised one.
Quantities: mass [kg], balance point [m], swing weight about 0.10 m [kg cm^2] (I_CG + M (x_CG -
0.10)^2), first free-free frequency [Hz].

A batch of designs is evaluated at once, in two passes (one design at a time would pay the
engine's fixed cost per call for only its ~60 impacts):

1. per design: its mesh, closed-form matrices (:func:`fem_racket.frame.hermite.
   assemble_closed_form`), every free-free mode (a 20-cell frame has 40: one small dense
   eigenproblem, no static solves for the modes left out) and mass properties;
2. every design's impacts stated as problems (:mod:`.cases`) and solved together
   (:mod:`.impacts`): e_A over the zone at every speed and over the power region at the first,
   each case on its own design's frame; the handle shock of each design held in the hand.

The impacts reduce the modes above the COR tolerance's cut-off to one pseudo-mode per case
(:mod:`fem_racket.impact.exact.engine`); under the paper's linear law K_CB is the closing
speed's K_CB(v) times the design's ``kcb_factor``. Any other contact law
(:attr:`.problem.DesignProblem.law`, with the design's string-bed k_s and k_3 for the series
law) runs through the general integrator, vouched for at the problem's COR tolerance; e_A is
-v_B(t_c) / v_closing as for the linear law.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.model import FrameModel
from fem_racket.impact.swing import ball_speed_out
from fem_racket.studies.design.cases import closing_kcb, design_solver, free_cases, held_cases
from fem_racket.studies.design.impacts import apparent_cor, grip_shock
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.swing import SWING_WEIGHT_AXIS, mass_quantities
from fem_racket.studies.design.variables import QUANTITIES, sense
from fem_racket.studies.sweetspots import power_region

__all__ = ["evaluate_rows", "output_names"]


@dataclass(frozen=True, eq=False)
class _Design:
    """One design's frame and quantities."""

    model: FrameModel
    quantities: dict[str, float]
    inertia_pivot: float


def _design(problem: DesignProblem, x: np.ndarray) -> _Design:
    mesh = problem.mesh(x)
    model = FrameModel(assemble_closed_form(mesh))
    modes = model.modes(problem.modes)  # every mode when None (kept by the model for its cases)
    pivot = SWING_WEIGHT_AXIS if problem.swing is None else problem.swing.pivot
    mq = mass_quantities(mesh, pivot)
    quantities = {
        "mass_kg": mq["mass"],
        "balance_m": mq["cg"],
        "swing_weight_kg_cm2": mq["swing_weight_kg_cm2"],
        "f1_hz": float(modes.frequencies[0]),
    }
    return _Design(model, quantities, mq["inertia_pivot"])


def _racket_speeds(problem: DesignProblem, x: np.ndarray, inertia: float) -> np.ndarray:
    """v_r [m/s] of the points ``x`` (x/L) for a racket of that inertia (0 without a swing)."""
    if problem.swing is None:
        return np.zeros_like(x)
    return problem.swing.impact_speed(x, inertia, problem.length)


def _free_cor(
    problem: DesignProblem,
    designs: np.ndarray,
    built: list[_Design],
    positions: np.ndarray,
    speed: np.ndarray,
) -> np.ndarray:
    """e_A (designs, cases) of each design struck at ``positions`` at its closing ``speed``."""
    if positions.size == 0:
        return np.empty(speed.shape)
    if problem.law is None:
        contact = closing_kcb(speed, problem.law_values(designs)["kcb_factor"])
    else:
        contact = [problem.design_law(x) for x in designs]
    cases = [
        free_cases(problem, d.model, positions, speed[i], contact[i]) for i, d in enumerate(built)
    ]
    every = max(d.model.fe.ndof - 2 for d in built)  # flexible modes of the largest frame
    return apparent_cor(design_solver(problem, flexible=every), cases).reshape(speed.shape)


def _shock(
    problem: DesignProblem, built: list[_Design], speed: np.ndarray
) -> dict[str, np.ndarray]:
    """Handle-shock objectives (designs, speeds, zone) of each design held in the hand."""
    x = problem.zone.positions
    nd, nv = speed.shape[0], len(problem.speeds)
    cases = [
        held_cases(problem, d.model, np.tile(x, nv), v) for d, v in zip(built, speed, strict=True)
    ]
    peak = "peak_grip_force" in problem.objectives
    rms, peaks = grip_shock(design_solver(problem, held=True), cases, peak=peak)
    out = {"handle_shock": rms.reshape(nd, nv, x.size)}
    if peak:
        out["peak_grip_force"] = peaks.reshape(nd, nv, x.size)
    return out


def output_names(problem: DesignProblem) -> list[str]:
    """Columns of an evaluation: every quantity, then the problem's objectives."""
    return list(QUANTITIES) + list(problem.objectives)


def evaluate_rows(problem: DesignProblem, designs: np.ndarray) -> np.ndarray:
    """Outputs (columns :func:`output_names`) of each row of ``designs`` [SI]."""
    designs = np.atleast_2d(np.asarray(designs, dtype=float))
    wanted = set(problem.objectives)
    zone = problem.zone.positions if wanted & {"cor", "ball_speed"} else np.empty(0)
    region = problem.region if "power_region" in wanted else np.empty(0)
    points = np.concatenate([zone, region])
    v_in = np.asarray(problem.speeds, dtype=float)
    nd, nz, nr, nv = len(designs), zone.size, region.size, v_in.size
    built = [_design(problem, x) for x in designs]
    # cases per design: every speed at every zone point, then the first speed on the region
    v_r = np.array([_racket_speeds(problem, points, d.inertia_pivot) for d in built])
    speed = np.concatenate(
        [(v_in[None, :, None] + v_r[:, None, :nz]).reshape(nd, -1), v_in[0] + v_r[:, nz:]], 1
    )
    rows = np.concatenate([np.tile(np.arange(nz), nv), nz + np.arange(nr)])
    cor = _free_cor(problem, designs, built, points[rows], speed)
    shock: dict[str, np.ndarray] = {}
    if problem.shock:
        x = problem.zone.positions
        v_zone = np.array([_racket_speeds(problem, x, d.inertia_pivot) for d in built])
        shock = _shock(problem, built, (v_in[None, :, None] + v_zone[:, None, :]).reshape(nd, -1))
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
            elif name == "power_region":
                v_out = ball_speed_out(cor[i, nv * nz :], v_in[0], v_r[i, nz:])
                lo, hi = power_region(region, v_out, problem.power_fraction)
                value = (hi - lo) * problem.length
            else:
                value = float(np.mean(problem.zone.mean(shock[name][i])))
            out[i, len(QUANTITIES) + j] = value - sense(name) * cost[i]
    return out
