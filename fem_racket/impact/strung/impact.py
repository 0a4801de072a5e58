"""One impact of the ball on the strung racket: the ball's law against the string bed.

The strung racket at the impact point (:mod:`.point`: frame and bed in series,
one modal structure) goes unchanged through the impact paths: the general integrator or CVODE
for any ball law (:func:`strung_impact`, with histories), the exact batched engine for the linear
ball (:func:`strung_engine`, COR and contact time only); a stretching bed CVODE alone
(:mod:`fem_racket.impact.strung.stretch`). From the histories come the bed's and the ball's
peak deflections and the energy bookkeeping (:class:`~fem_racket.impact.strung.result.
StrungImpact`).
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

import numpy as np

from fem_racket.contact.bed_ball import kawazoe_ball
from fem_racket.contact.law import ContactLaw
from fem_racket.frame.model import FrameModel
from fem_racket.impact.general.histories import law_histories, ode_state_at
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.general.receptance import Receptance
from fem_racket.impact.ode.law_cvode import solve_law_cvode
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.strung.exact import strung_exact_states
from fem_racket.impact.strung.point import StrungPoint, strung_point
from fem_racket.impact.strung.result import StrungImpact
from fem_racket.impact.strung.stretch import stretch_energy, stretch_states
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError, check_choice, check_positive, check_range

__all__ = ["STRUNG_SOLVERS", "StrungImpact", "simulate_strung", "strung_engine", "strung_impact"]

#: Integrators of an impact on the strung racket: the exact solution (the linear ball), the
#: general integrator and CVODE (any ball law).
STRUNG_SOLVERS = ("exact", "general", "cvode")
#: Output times per contact for the peaks and the energy histories.
SAMPLES = 801


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
    :mod:`fem_racket.impact.strung.exact`), ``"general"`` (COR ``tolerance``) or ``"cvode"``
    (``rtol``, ``atol``, every mode); a stretching bed (``strings.stretch``) only ``"cvode"``
    (:mod:`fem_racket.impact.strung.stretch`, a ball law without a state).
    """
    check_choice("solver", solver, STRUNG_SOLVERS)
    w, a = point.omega, point.a
    z = None
    stretch = point.strings.stretch
    if stretch and solver != "cvode":
        raise InputError(
            f"solver = {solver!r} is not allowed with the strings' stretch: the stretching bed "
            "is integrated by 'cvode'"
        )
    if stretch:
        t, x, v = stretch_states(point, law, ball_mass, speed, SAMPLES, (rtol, atol))
        tc = float(t[-1])
    elif solver == "exact":
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
        rc = point.rigid_count
        rec = Receptance(w[rc:], a[None, rc:], a[None, :rc], np.array([ball_mass]))
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
    e_bed = energy[:, bed].sum(axis=1) + stretch_energy(point, x[:, 1:])
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
        racket_energy=float(energy[-1].sum() + e_bed[-1] - energy[-1, bed].sum()),
        bed_energy_left=float(e_bed[-1]),
        bed_peak_energy=float(np.max(e_bed)),
        frame_momentum=float(v[-1, 1] / a[0]) if point.rigid_count else math.nan,
        point=point,
        law=law,
        speed=float(speed),
        ball_mass=float(ball_mass),
        solver=solver,
        coordinates=x,
        rates=v,
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
    out = strung_impact(point, ball, ball_mass, speed, solver=solver, **options)
    return replace(out, model=model)
