"""Objectives and constrained quantities of racket designs.

For each design: its mesh, free-free modes and mass properties, then e_A over the impact zone
(:func:`.impacts.apparent_cor`) at every incoming ball speed v_in. With a swing (:mod:`.swing`)
the impact point moves at v_r(x) towards the ball, the strings meet the ball at v_in + v_r (which
sets K_CB) and the ball leaves at v_out = e_A v_in + (1 + e_A) v_r. Without a swing v_r = 0.

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
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.model import FrameModel
from fem_racket.impact.swing import ball_speed_out
from fem_racket.studies.design.batched import BATCHED, evaluate_batch
from fem_racket.studies.design.impacts import apparent_cor, handle_shock
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.swing import SWING_WEIGHT_AXIS, mass_quantities
from fem_racket.studies.design.variables import QUANTITIES, sense
from fem_racket.studies.sweetspots import power_region

__all__ = ["evaluate_design", "evaluate_rows", "output_names"]


def output_names(problem: DesignProblem) -> list[str]:
    """Columns of an evaluation: every quantity, then the problem's objectives."""
    return list(QUANTITIES) + list(problem.objectives)


def speeds_along(problem: DesignProblem, x: np.ndarray, inertia_pivot: float) -> np.ndarray:
    """v_r [m/s] of the points ``x`` (x/L) for a racket of that inertia (0 without a swing)."""
    if problem.swing is None:
        return np.zeros_like(np.asarray(x, dtype=float))
    return problem.swing.impact_speed(x, inertia_pivot, problem.length)


def curves(
    problem: DesignProblem, model: FrameModel, x: np.ndarray, inertia_pivot: float
) -> dict[str, np.ndarray]:
    """e_A and v_out at positions ``x`` (x/L) for every speed: arrays (n_speeds, n_x)."""
    v_in = np.asarray(problem.speeds, dtype=float)[:, None]
    v_r = speeds_along(problem, x, inertia_pivot)[None, :]
    cor = apparent_cor(
        model,
        np.asarray(x)[None, :],
        v_in + v_r,
        ball_mass=problem.ball_mass,
        zeta=problem.zeta,
        modes=problem.modes,
        tolerance=problem.tolerance,
    )
    return {"cor": cor, "ball_speed": ball_speed_out(cor, v_in, v_r)}


def shock_curves(
    problem: DesignProblem, model: FrameModel, inertia_pivot: float
) -> dict[str, np.ndarray]:
    """Handle shock over the zone at every speed: arrays (n_speeds, n_zone) [N]."""
    x = problem.zone.positions
    v = np.asarray(problem.speeds, dtype=float)[:, None] + speeds_along(problem, x, inertia_pivot)
    rms, peak = handle_shock(
        model,
        x[None, :],
        v,
        hand=problem.hand,
        window=problem.shock_window,
        ball_mass=problem.ball_mass,
        zeta=problem.zeta,
        tolerance=problem.tolerance,
        peak="peak_grip_force" in problem.objectives,
    )
    return {"handle_shock": rms, "peak_grip_force": peak}


def evaluate_design(problem: DesignProblem, x: np.ndarray) -> dict[str, Any]:
    """Every output of one design (variables ``x`` [SI]): quantities and objectives."""
    mesh = problem.mesh(x)
    model = FrameModel(assemble_closed_form(mesh))
    fm = model.modes(problem.modes)
    pivot = SWING_WEIGHT_AXIS if problem.swing is None else problem.swing.pivot
    mq = mass_quantities(mesh, pivot)
    out: dict[str, Any] = {
        "mass_kg": mq["mass"],
        "balance_m": mq["cg"],
        "swing_weight_kg_cm2": mq["swing_weight_kg_cm2"],
        "f1_hz": float(fm.frequencies[0]),
    }
    cost = problem.stiffness_cost * float(problem.stiffness(x))
    wanted = set(problem.objectives)
    if wanted & {"cor", "ball_speed"}:
        c = curves(problem, model, problem.zone.positions, mq["inertia_pivot"])
        for name in ("cor", "ball_speed"):
            if name in wanted:
                out[name] = float(np.mean(problem.zone.mean(c[name]))) - cost
    if "power_region" in wanted:
        c = curves(problem, model, problem.region, mq["inertia_pivot"])
        lo, hi = power_region(problem.region, c["ball_speed"][0], problem.power_fraction)
        out["power_region"] = (hi - lo) * problem.length - cost
    if problem.shock:
        c = shock_curves(problem, model, mq["inertia_pivot"])
        for name in ("handle_shock", "peak_grip_force"):
            if name in wanted:
                out[name] = float(np.mean(problem.zone.mean(c[name]))) - sense(name) * cost
    return out


def evaluate_rows(problem: DesignProblem, designs: np.ndarray) -> np.ndarray:
    """Outputs (columns :func:`output_names`) of each row of ``designs`` [SI].

    Objectives in :data:`.batched.BATCHED` run all the designs' impacts together
    (:func:`.batched.evaluate_batch`); others go design by design.
    """
    if set(problem.objectives) <= BATCHED:
        return evaluate_batch(problem, designs)
    names = output_names(problem)
    rows = np.empty((len(designs), len(names)))
    for i, x in enumerate(np.atleast_2d(designs)):
        d = evaluate_design(problem, x)
        rows[i] = [d[n] for n in names]
    return rows
