"""One impact of the ball on the strung racket: the ball's law against the string bed.

The strung racket at the impact point (:mod:`fem_racket.impact.strung`: frame and bed in series,
one modal structure) goes unchanged through the impact paths: the general integrator or CVODE
for any ball law (:func:`strung_impact`, with histories), the exact batched engine for the linear
ball (:func:`strung_engine`, COR and contact time only). From the histories come the bed's and
the ball's peak deflections and the energy bookkeeping (every coordinate x of the modal structure
stores ``(x'^2 + omega^2 x^2) / 2``, the bed's coordinates the bed's energy relative to its edge)::

    ball's loss          m_B (V_B0^2 - v_B(t_c)^2) / 2    (= the work of the contact force on it)
    energy to the racket E_frame(t_c) + E_bed(t_c)
    lost in the ball     ball's loss - energy to the racket (the law's dissipation)
    returned by the bed  max_t E_bed(t) - E_bed(t_c)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.frame.model import FrameModel
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.general.receptance import Receptance
from fem_racket.impact.law_impact import law_histories, ode_state_at
from fem_racket.impact.ode.law_cvode import solve_law_cvode
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.strung import StrungPoint, kawazoe_ball, strung_point
from fem_racket.impact.strung_exact import strung_exact_states
from fem_racket.strings.bed import StringBed
from fem_racket.validation import check_choice, check_positive, check_range

__all__ = ["STRUNG_SOLVERS", "StrungImpact", "simulate_strung", "strung_engine", "strung_impact"]

#: Integrators of an impact on the strung racket: the exact solution (the linear ball), the
#: general integrator and CVODE (any ball law).
STRUNG_SOLVERS = ("exact", "general", "cvode")
#: Output times per contact for the peaks and the energy histories.
SAMPLES = 801


@dataclass(frozen=True, eq=False)
class StrungImpact:
    """An impact on the strung racket: results and histories (see the module docstring).

    Attributes
    ----------
    cor : float
        Apparent COR -v_B(t_c)/V_B0.
    contact_time : float
        t_c [s].
    peak_force : float
        Largest contact force [N].
    t, ball_deflection, bed_deflection, force : ndarray
        Times [s], the ball's compression (the law's deflection) [m], the bed's deflection at the
        point relative to its edge [m] and the contact force [N].
    ball_loss, racket_energy, bed_energy_left, bed_peak_energy : float
        Energies [J] of the module docstring.
    frame_momentum : float
        Linear momentum of the frame at t_c [kg m/s] (its rigid translation).
    point : StrungPoint
        The structure used.
    law : ContactLaw
        The ball's law.
    speed, ball_mass : float
        V_B0 [m/s] and m_B [kg].
    solver : str
        The integrator that ran.
    coordinates : ndarray, shape (nt, 1 + n)
        u_B [m] and the structure's coordinates (:attr:`StrungPoint.omega` order) at ``t``.
    """

    cor: float
    contact_time: float
    peak_force: float
    t: np.ndarray
    ball_deflection: np.ndarray
    bed_deflection: np.ndarray
    force: np.ndarray
    ball_loss: float
    racket_energy: float
    bed_energy_left: float
    bed_peak_energy: float
    frame_momentum: float
    point: StrungPoint
    law: ContactLaw
    speed: float
    ball_mass: float
    solver: str
    coordinates: np.ndarray

    def summary(self) -> dict[str, Any]:
        """The results, the bed and what the run used, JSON-ready, units in the keys."""
        return {
            "cor": self.cor,
            "contact_time_s": self.contact_time,
            "rebound_speed_m_s": self.cor * self.speed,
            "peak_force_n": self.peak_force,
            "position_x_over_l": self.point.position,
            "speed_m_s": self.speed,
            "ball_mass_kg": self.ball_mass,
            "solver": self.solver,
            **self.law.describe(),
            **self.point.describe(),
            "peak_bed_deflection_m": float(np.max(self.bed_deflection)),
            "peak_ball_deflection_m": float(np.max(self.ball_deflection)),
            "ball_energy_loss_j": self.ball_loss,
            "energy_lost_in_ball_j": self.ball_loss - self.racket_energy,
            "bed_energy_returned_j": self.bed_peak_energy - self.bed_energy_left,
            "bed_energy_left_j": self.bed_energy_left,
        }


def _energies(point: StrungPoint, x: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Energy of each structure coordinate at each time, shape (T, n) [J]."""
    return 0.5 * (v**2 + (point.omega * x) ** 2)


def strung_impact(
    point: StrungPoint,
    law: ContactLaw,
    ball_mass: float,
    speed: float,
    *,
    solver: str = "general",
    tolerance: float | None = DEFAULT_TOLERANCE,
    rtol: float = 1e-10,
    atol: float = 1e-13,
) -> StrungImpact:
    """The ball (``ball_mass`` [kg], ``speed`` [m/s]) under ``law`` on the strung racket at rest.

    ``solver``: ``"exact"`` (the linear ball, every mode:
    :mod:`fem_racket.impact.strung_exact`), ``"general"`` (COR ``tolerance``) or ``"cvode"``
    (``rtol``, ``atol``, every mode).
    """
    check_choice("solver", solver, STRUNG_SOLVERS)
    w, a = point.omega, point.a
    z = None
    if solver == "exact":
        t, x, v = strung_exact_states(point, law, ball_mass, speed, SAMPLES)
        tc = float(t[-1])
    elif solver == "cvode":
        tr = solve_law_cvode(law, w, a, ball_mass, speed, rtol=rtol, atol=atol)
        n = tr.n
        tc = tr.contact_time
        t = np.linspace(0.0, tc, SAMPLES)
        y = np.column_stack([np.interp(t, tr.t, col) for col in tr.y.T])
        x, v = y[:, :n], y[:, n : 2 * n]
        z = y[:, -1] if law.state == "ode" else None
    else:
        rec = Receptance(w[2:], a[None, 2:], a[None, :2], np.array([ball_mass]))
        out = solve_general(law, rec, speed, tolerance=tolerance)
        tc = float(out.contact_time[0])
        t = np.linspace(0.0, tc, SAMPLES)
        x, v = law_histories(out, w, a, ball_mass, speed, None, t)
        if law.state == "ode":
            z = ode_state_at(law, out, t)
    d = x[:, 0] - x[:, 1:] @ a
    rate = v[:, 0] - v[:, 1:] @ a
    if law.state == "memory":
        z = np.maximum.accumulate(d)
    force = np.asarray(law.force(d, rate, d if z is None else z), dtype=float)
    energy = _energies(point, x[:, 1:], v[:, 1:])
    bed = point.bed
    e_bed = energy[:, bed].sum(axis=1)
    vb = float(v[-1, 0])
    return StrungImpact(
        cor=-vb / speed,
        contact_time=tc,
        peak_force=float(np.max(force)),
        t=t,
        ball_deflection=d,
        bed_deflection=x[:, 1:][:, bed] @ a[bed],
        force=force,
        ball_loss=0.5 * ball_mass * (speed**2 - vb**2),
        racket_energy=float(energy[-1].sum()),
        bed_energy_left=float(e_bed[-1]),
        bed_peak_energy=float(np.max(e_bed)),
        frame_momentum=float(v[-1, 1] / a[0]) if a[0] else math.nan,
        point=point,
        law=law,
        speed=float(speed),
        ball_mass=float(ball_mass),
        solver=solver,
        coordinates=x,
    )


def strung_engine(
    point: StrungPoint,
    kcb: Any,
    zeta: Any,
    ball_mass: Any,
    speed: Any,
    *,
    separation: str = "displacement",
    tolerance: float | None = DEFAULT_TOLERANCE,
):
    """The linear ball (spring ``kcb`` [N/m], damping ratio ``zeta``) on the strung racket
    through the exact batched engine: an :class:`~fem_racket.impact.exact.engine.ImpactBatch`
    (arrays broadcast)."""
    from fem_racket.impact.exact.engine import EngineOptions, modal_impacts

    w, a = point.flexible
    return modal_impacts(
        w,
        a,
        float(np.sum(point.rigid**2)),
        speed=speed,
        kcb=kcb,
        zeta=zeta,
        ball_mass=ball_mass,
        options=EngineOptions(separation, tolerance, peak_force=True),
    )


def simulate_strung(
    model: FrameModel,
    strings: StringBed,
    *,
    position: float = 0.75,
    offset: float = 0.0,
    speed: float = 20.0,
    ball_mass: float = 0.057,
    law: ContactLaw | None = None,
    solver: str = "exact",
    **options: Any,
) -> StrungImpact:
    """The ball striking the strung racket ``model`` + ``strings`` at rest.

    Parameters
    ----------
    model : FrameModel
        The frame (every mode used).
    strings : StringBed
        The bed (:mod:`fem_racket.strings.bed`).
    position, offset : float
        Impact point: x/L along the frame and its offset from the axis [m].
    speed, ball_mass : float
        V_B0 [m/s] and m_B [kg].
    law : ContactLaw, optional
        The ball's own law; the ``kawazoe-1997-ball`` when None.
    solver : {"exact", "general", "cvode"}
        As :func:`strung_impact`.
    **options
        ``tolerance``, ``rtol``, ``atol``: as :func:`strung_impact`.
    """
    check_positive("speed", speed, "m/s")
    point = strung_point(model, strings, check_range("position", position, 0.0, 1.0), offset)
    ball = kawazoe_ball(ball_mass) if law is None else law
    return strung_impact(point, ball, ball_mass, speed, solver=solver, **options)
