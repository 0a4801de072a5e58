"""One impact on a hand-held racket, at rest or swinging: outcome, handle shock and histories.

The entry of ``fem-racket simulate`` with a hand. Two ways to the same answer:

- ``exact`` (default): the eigen-solution of :mod:`fem_racket.impact.held.modal` and the exact
  shock measures of :mod:`fem_racket.impact.held.shock` (peak of the grip force, RMS of its
  vibration part over the window [0, T]);
- ``cvode`` / ``bdf``: the integrators during contact and the free vibration after it
  (:mod:`fem_racket.impact.held.sampled`), the peaks root-found and the RMS integrated exactly
  between the samples, so none depends on the output step.

A swing (:mod:`fem_racket.impact.swing`) moves racket and hand rigidly; the grip layer is not
stretched by it, so the impact superposes on the stationary one at the closing speed
v_in + v_r with the grip force unchanged, and v_out = e_A v_in + (1 + e_A) v_r (Brody, Cross &
Lindsey 2002, ch. 11). The exact path uses this superposition; the integrators start from the
swing's velocity field, which checks it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.frame.hand import GRIPS, Hand
from fem_racket.impact.held.basis import held_basis
from fem_racket.impact.held.grip import HELD_SOLVERS
from fem_racket.impact.held.modal import held_contact
from fem_racket.impact.held.sampled import history_columns, sampled_impact, shock_grid
from fem_racket.impact.held.shock import (
    DEFAULT_WINDOW,
    contact_peak,
    grip_peak,
    vibration_rms,
)
from fem_racket.impact.ode.integrators import ATOL_RANGE, PHYSICAL_MAX_ELEMENTS, RTOL_RANGE
from fem_racket.impact.problem import HeldRacket, ImpactProblem
from fem_racket.impact.swing import Swing, ball_speed_out, rebound_summary
from fem_racket.impact.system import check_output_count
from fem_racket.validation import InputError, check_choice, check_range, show

__all__ = ["HELD_RUN_SOLVERS", "HeldRun", "HeldSettings", "hand_summary", "held_impact"]

#: Solvers of :func:`held_impact`.
HELD_RUN_SOLVERS = ("exact", *HELD_SOLVERS)
#: Longest window of the shock measures [s] (the samples and the peak's grid grow with it).
MAX_WINDOW = 1.0
#: Most elements of a held racket: the exact path's dense eigenproblem of frame + hand (1.8 s
#: at 200 elements; at 400 round-off mixes its rigid modes with the flexible ones).
HELD_MAX_ELEMENTS = 200


def _check_size(solver: str, elements: int, rtol: float, atol: float) -> None:
    """Refuse element counts and tolerances the held racket's solvers cannot meet in time."""
    if solver == "exact":
        if elements > HELD_MAX_ELEMENTS:
            raise InputError(
                f"elements = {elements} is not allowed with a hand: at most {HELD_MAX_ELEMENTS} "
                "(dense matrices of frame + hand)",
                parameter="elements",
                value=elements,
            )
        return
    check_range("rtol", rtol, *RTOL_RANGE)
    check_range("atol", atol, *ATOL_RANGE)
    if elements > PHYSICAL_MAX_ELEMENTS:
        raise InputError(
            f"elements = {elements} is not allowed with a hand and solver {solver!r}: at most "
            f"{PHYSICAL_MAX_ELEMENTS} (BDF on every DOF of frame + hand takes minutes beyond: "
            "10 s at 40, 50 s at 60; use solver 'exact')",
            parameter="elements",
            value=elements,
        )


def hand_summary(hand: Hand) -> dict[str, Any]:
    """The hand's parameters, JSON-ready, units in the keys; ``grip`` names a preset of
    :data:`fem_racket.frame.hand.GRIPS` it equals, else "custom"."""
    name = next((k for k, h in GRIPS.items() if h == hand), "custom")
    return {
        "grip": name,
        "mass_kg": hand.mass,
        "grip_start_m": hand.grip_start,
        "grip_end_m": hand.grip_end,
        "stiffness_n_m2": hand.stiffness,
        "damping_n_s_m2": hand.damping,
        "inertia_kg_m2": hand.rotary_inertia,
    }


@dataclass(frozen=True, eq=False)
class HeldRun:
    """Outcome of :func:`held_impact`.

    Attributes
    ----------
    apparent_cor : float
        e_A: the COR of the held racket at rest struck at the closing speed.
    contact_time, peak_force : float
        t_c [s] and the largest contact force [N].
    peak_grip_force, grip_vibration_rms : float
        Largest |F_h| and RMS of its vibration part over the window [N].
    histories : dict or None
        Column name (units in it) -> values at the output times over [0, T] (t_c is one of
        them): time, contact force, grip force and its rigid and vibration parts.
    used : dict
        What the run used (:meth:`settings`), the hand under ``"hand"``.
    """

    apparent_cor: float
    speed: float
    racket_speed: float
    contact_time: float
    peak_force: float
    peak_grip_force: float
    grip_vibration_rms: float
    histories: dict[str, np.ndarray] | None
    used: dict[str, Any]

    @property
    def ball_speed_out(self) -> float:
        """v_out = e_A v_in + (1 + e_A) v_r [m/s]."""
        return float(ball_speed_out(self.apparent_cor, self.speed, self.racket_speed))

    def settings(self) -> dict[str, Any]:
        """What the run used (solver, tolerances, modes, K_CB, zeta, C_CB, the hand ...)."""
        return dict(self.used)

    def summary(self) -> dict[str, Any]:
        """Scalar results and :meth:`settings`, JSON-ready, units in the keys."""
        return {
            **rebound_summary(self, self.racket_speed),
            "peak_grip_force_n": self.peak_grip_force,
            "grip_vibration_rms_n": self.grip_vibration_rms,
            **self.settings(),
        }


@dataclass(frozen=True)
class HeldSettings:
    """How a held racket is solved.

    Attributes
    ----------
    solver : {"exact", "cvode", "bdf"}
    output_step : float
        Spacing of the histories' times and of the integrators' samples [s] (the peaks and the
        RMS do not depend on it, module docstring).
    histories : bool
        Keep the histories (:attr:`HeldRun.histories`).
    tolerance : float or None
        COR tolerance choosing the exact path's modes (None: every mode).
    rtol, atol : float
        Tolerances of cvode / bdf.
    """

    solver: str = "exact"
    output_step: float = 1e-5
    histories: bool = False
    tolerance: float | None = None
    rtol: float = 1e-10
    atol: float = 1e-12


def _exact(problem: ImpactProblem, tolerance: float | None, window: float, step: float | None):
    """The exact path: (e_A, t_c, peak F, peak F_h, RMS), histories or None, what it used."""
    held = problem.structure
    c = held_contact(
        held_basis(held.model.fe, held.hand),
        position=problem.impact.position,
        speed=problem.closing_speed,
        ball_mass=problem.ball.mass,
        kcb=problem.kcb,
        zeta=problem.zeta,
        tolerance=tolerance,
    )
    out = (c.cor, c.contact_time, contact_peak(c), grip_peak(c, window), vibration_rms(c, window))
    hist = None
    if step is not None:
        t = np.concatenate(shock_grid(step, c.contact_time, window))
        grip, rigid = c.grip_force(t)
        hist = history_columns(t, c.contact_force(t), grip, rigid)
    return out, hist, {"modes": c.modes, "tolerance": tolerance}


def held_impact(problem: ImpactProblem, settings: HeldSettings | None = None) -> HeldRun:
    """A ball striking the racket held in a hand (``problem.structure`` a
    :class:`~fem_racket.impact.problem.HeldRacket`; module docstring), solved as ``settings``
    say (by default the exact solution with every mode).

    Returns
    -------
    HeldRun
    """
    s = HeldSettings() if settings is None else settings
    held = problem.structure
    if not isinstance(held, HeldRacket):
        raise InputError("held_impact takes a problem whose structure is a HeldRacket")
    model, hand = held.model, held.hand
    check_choice("solver", s.solver, HELD_RUN_SOLVERS)
    _check_size(s.solver, model.mesh.n_elements, s.rtol, s.atol)
    window = DEFAULT_WINDOW if held.shock_window is None else held.shock_window
    window = check_range("shock_window", window, 0.0, MAX_WINDOW, unit="s", include_low=False)
    if not s.output_step > 0.0:
        raise InputError(f"output_step = {show(s.output_step)} s is not allowed: must be > 0")
    if s.histories or s.solver != "exact":  # the integrators sample at output_step
        check_output_count(s.output_step, window, f"the shock window's {window:g} s")
    if s.solver == "exact":
        step = s.output_step if s.histories else None
        out, hist, used = _exact(problem, s.tolerance, window, step)
    else:
        out, hist, used = sampled_impact(problem, s.solver, window, s)
        hist = hist if s.histories else None
    cor, tc, peak_force, peak_grip, rms = out
    law = problem.contact()
    speed = float(problem.impact.speed)
    used = {
        "solver": s.solver,
        "elements": model.mesh.n_elements,
        **used,
        "position_x_over_l": problem.impact.position,
        "speed_m_s": speed,
        "ball_mass_kg": problem.ball.mass,
        "kcb_n_m": law.stiffness,
        "zeta": law.zeta,
        "ccb_n_s_m": law.damping(problem.ball.mass),
        "shock_window_s": float(window),
        "hand": hand_summary(hand),
        **(problem.swing or Swing()).summary(),
    }
    v_r = problem.racket_speed
    return HeldRun(cor, speed, v_r, tc, peak_force, peak_grip, rms, hist, used)
