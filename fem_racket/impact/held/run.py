"""One impact on a hand-held racket, at rest or swinging: outcome, handle shock and histories.

The entry of ``fem-racket simulate`` with a hand. Two ways to the same answer:

- ``exact`` (default): the eigen-solution of :mod:`fem_racket.impact.held.modal` and the exact
  shock measures of :mod:`fem_racket.impact.held.shock` (peak of the grip force, RMS of its
  vibration part over the window [0, T]);
- ``cvode`` / ``bdf``: the integrators of :func:`fem_racket.impact.held.grip.simulate_held` during
  contact; after separation the frame and hand vibrate freely (ball gone), a linear system
  y' = A_s y of the held structure, y = [x, x'], A_s = [[0, I], [-M^-1 K, -M^-1 C]], stepped
  from the integrator's state at t_c by its propagator exp(A_s dt) (exact for a linear system).
  The shock measures come from the samples: the peak is their largest |F_h| and the energy
  int F_v^2 dt Simpson's rule over them, both to the output step.

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

from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.frame.hand import GRIPS, Hand, held_frame
from fem_racket.frame.model import FrameModel
from fem_racket.impact.held.grip import HELD_SOLVERS, HeldImpact, simulate_held
from fem_racket.impact.held.modal import held_basis, held_contact
from fem_racket.impact.held.shock import (
    DEFAULT_WINDOW,
    contact_peak,
    grip_peak,
    vibration_rms,
)
from fem_racket.impact.ode.integrators import ATOL_RANGE, PHYSICAL_MAX_ELEMENTS, RTOL_RANGE
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.swing import Swing, ball_speed_out, closing_speed
from fem_racket.impact.system import check_output_count
from fem_racket.validation import InputError, check_choice, check_range

__all__ = ["HELD_RUN_SOLVERS", "HeldRun", "hand_summary", "held_impact"]

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
                "(dense matrices of frame + hand)"
            )
        return
    check_range("rtol", rtol, *RTOL_RANGE)
    check_range("atol", atol, *ATOL_RANGE)
    if elements > PHYSICAL_MAX_ELEMENTS:
        raise InputError(
            f"elements = {elements} is not allowed with a hand and solver {solver!r}: at most "
            f"{PHYSICAL_MAX_ELEMENTS} (BDF on every DOF of frame + hand takes minutes beyond: "
            "10 s at 40, 50 s at 60; use solver 'exact')"
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
            "cor": self.apparent_cor,
            "apparent_cor": self.apparent_cor,
            "ball_speed_out_m_s": self.ball_speed_out,
            "racket_speed_at_impact_m_s": self.racket_speed,
            "contact_time_s": self.contact_time,
            "rebound_speed_m_s": self.ball_speed_out,
            "peak_force_n": self.peak_force,
            "peak_grip_force_n": self.peak_grip_force,
            "grip_vibration_rms_n": self.grip_vibration_rms,
            **self.settings(),
        }


def _grid(step: float, tc: float, window: float) -> tuple[np.ndarray, np.ndarray]:
    """Output times during contact (k step, then t_c) and after it (t_c + k step, then T)."""
    on = np.arange(0.0, tc, step)
    on = np.append(on[on < tc * (1 - 1e-12)], tc)
    off = tc + np.arange(step, window - tc, step)
    return on, np.append(off[off < window * (1 - 1e-12)], window)


def _columns(t, force, grip, rigid) -> dict[str, np.ndarray]:
    return {
        "time [s]": t,
        "contact force [N]": force,
        "grip force [N]": grip,
        "grip force rigid part [N]": rigid,
        "grip force vibration part [N]": grip - rigid,
    }


def _exact(model, hand, x, speed, ball, kcb, zeta, tolerance, window, step):
    """The exact path: (e_A, t_c, peak F, peak F_h, RMS), histories or None, what it used."""
    c = held_contact(
        held_basis(model.fe, hand),
        position=x,
        speed=speed,
        ball_mass=ball.mass,
        kcb=kcb,
        zeta=zeta,
        tolerance=tolerance,
    )
    out = (c.cor, c.contact_time, contact_peak(c), grip_peak(c, window), vibration_rms(c, window))
    hist = None
    if step is not None:
        t = np.concatenate(_grid(step, c.contact_time, window))
        grip, rigid = c.grip_force(t)
        hist = _columns(t, c.contact_force(t), grip, rigid)
    return out, hist, {"modes": c.modes, "tolerance": tolerance}


def _free_grip(model: FrameModel, hand: Hand, state: np.ndarray, s: np.ndarray) -> np.ndarray:
    """Grip force [N] of the freely vibrating held racket at times ``s`` after t_c (uniform
    steps but the last), from the state at t_c (module docstring)."""
    from scipy.linalg import expm

    held = held_frame(model.fe, hand)
    n = held.K.shape[0]
    minv = np.linalg.inv(held.M)
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n], A[n:, n:] = -minv @ held.K, -minv @ held.C
    row = held.grip[held.n_frame]
    out_row = -np.concatenate([hand.stiffness * row, hand.damping * row])
    y = np.empty((s.size, 2 * n))
    y[0] = state
    if s.size > 2:
        step = expm(A * (s[1] - s[0]))
        for k in range(1, s.size - 1):
            y[k] = step @ y[k - 1]
    if s.size > 1:
        y[-1] = expm(A * (s[-1] - s[-2])) @ y[-2]
    return y @ out_row


def _integrated(model, hand, x, speed, ball, kcb, zeta, solver, swing, window, step, rtol, atol):
    """The integrators' path: as :func:`_exact`, the shock measures from the samples."""
    from scipy.integrate import simpson

    r: HeldImpact = simulate_held(
        model, hand, position=x, speed=speed, ball_mass=ball.mass, kcb=kcb, zeta=zeta,
        solver=solver, output_step=step, rtol=rtol, atol=atol, swing=swing,
    )  # fmt: skip
    tc = r.contact_time
    if not window > tc:
        raise InputError(
            f"window = {window!r} s is not allowed: must exceed the contact time ({tc:.4g} s)"
        )
    _, off = _grid(step, tc, window)
    free = _free_grip(model, hand, r.state, np.append(0.0, off - tc))  # from t_c
    energy = simpson(r.grip_vibration**2, x=r.t) + simpson(free**2, x=np.append(tc, off))
    free = free[1:]
    peak = max(float(np.max(np.abs(r.grip_force))), float(np.max(np.abs(free))))
    out = (r.cor, tc, float(np.max(r.contact_force)), peak, float(np.sqrt(energy / window)))
    zeros = np.zeros_like(off)
    hist = _columns(
        np.concatenate([r.t, off]),
        np.concatenate([r.contact_force, zeros]),
        np.concatenate([r.grip_force, free]),
        np.concatenate([r.grip_force_rigid, zeros]),
    )
    return out, hist, {"modes": model.fe.ndof + 2, "rtol": rtol, "atol": atol}


def held_impact(
    model: FrameModel,
    hand: Hand,
    *,
    position: float = 0.75,
    speed: float = 20.0,
    ball_mass: float | None = None,
    kcb: float | None = None,
    zeta: float | None = None,
    solver: str = "exact",
    swing: Swing | None = None,
    window: float = DEFAULT_WINDOW,
    output_step: float = 1e-5,
    histories: bool = False,
    tolerance: float | None = DEFAULT_TOLERANCE,
    rtol: float = 1e-10,
    atol: float = 1e-12,
) -> HeldRun:
    """A ball striking the racket held by ``hand`` (module docstring).

    Parameters
    ----------
    model : FrameModel
    hand : Hand
    position, speed, ball_mass, kcb, zeta
        As for :func:`fem_racket.simulate` (``speed`` the incident ball speed v_in [m/s]).
    solver : {"exact", "cvode", "bdf"}
    swing : Swing, optional
        Racket and hand's rigid motion before impact; at rest when None.
    window : float
        Window T of the shock measures from the start of contact [s], > t_c and at most
        :data:`MAX_WINDOW`.
    output_step : float
        Spacing of the histories' times and of the integrators' samples [s] (the integrators'
        shock measures are to it, module docstring).
    histories : bool
        Keep the histories (:attr:`HeldRun.histories`).
    tolerance : float or None
        COR tolerance choosing the exact path's modes (None: every mode).
    rtol, atol
        Tolerances of cvode / bdf.

    Returns
    -------
    HeldRun
    """
    check_choice("solver", solver, HELD_RUN_SOLVERS)
    _check_size(solver, model.mesh.n_elements, rtol, atol)
    window = check_range("shock_window", window, 0.0, MAX_WINDOW, unit="s", include_low=False)
    if not output_step > 0.0:
        raise InputError(f"output_step = {output_step!r} s is not allowed: must be > 0")
    if histories or solver != "exact":  # the integrators sample at output_step
        check_output_count(output_step, window, f"the shock window's {window:g} s")
    x = check_range("position", position, 0.0, 1.0, unit="x/L")
    ball = Ball() if ball_mass is None else Ball(ball_mass)
    v_r = 0.0 if swing is None else float(swing.speed_at(x * model.mesh.length))
    closing = closing_speed(speed, v_r)
    if solver == "exact":
        step = output_step if histories else None
        out, hist, used = _exact(model, hand, x, closing, ball, kcb, zeta, tolerance, window, step)
    else:
        out, hist, used = _integrated(
            model, hand, x, speed, ball, kcb, zeta, solver, swing, window, output_step, rtol, atol
        )
        hist = hist if histories else None
    cor, tc, peak_force, peak_grip, rms = out
    law = LinearContact.for_speed(closing, kcb=kcb, zeta=zeta)
    used = {
        "solver": solver,
        "elements": model.mesh.n_elements,
        **used,
        "position_x_over_l": x,
        "speed_m_s": float(speed),
        "ball_mass_kg": ball.mass,
        "kcb_n_m": law.stiffness,
        "zeta": law.zeta,
        "ccb_n_s_m": law.damping(ball.mass),
        "shock_window_s": float(window),
        "hand": hand_summary(hand),
        **(swing or Swing()).summary(),
    }
    return HeldRun(cor, float(speed), v_r, tc, peak_force, peak_grip, rms, hist, used)
