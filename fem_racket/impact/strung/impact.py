"""One impact of the ball on the strung racket: the ball's law against the string bed.

The strung racket at the impact point (:mod:`.point`: frame and bed in series,
one modal structure) goes unchanged through the impact paths: the general integrator or CVODE
for any ball law (:func:`strung_impact`, with histories), the exact batched engine for the linear
ball (:func:`strung_engine`, COR and contact time only); a stretching bed CVODE alone
(:mod:`fem_racket.impact.strung.stretch`). From the histories come the bed's and the ball's
peak deflections and the energy bookkeeping (:class:`~fem_racket.impact.strung.result.
StrungImpact`); they sample the solution (:mod:`fem_racket.impact.strung.solution`) at
:data:`SAMPLES` times, and an oblique impact's normal history samples it at
:data:`OBLIQUE_SAMPLES`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import partial
from typing import Any

import numpy as np

from fem_racket.contact.bed_ball import kawazoe_ball
from fem_racket.contact.law import ContactLaw
from fem_racket.frame.model import FrameModel
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.strung.point import StrungPoint, strung_point
from fem_racket.impact.strung.result import StrungImpact
from fem_racket.impact.strung.solution import States, strung_solution
from fem_racket.impact.strung.stretch import stretch_energy
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError, check_choice, check_positive, check_range

__all__ = ["STRUNG_SOLVERS", "StrungImpact", "simulate_strung", "strung_engine", "strung_impact"]

#: Integrators of an impact on the strung racket: the exact solution (the linear ball), the
#: general integrator and CVODE (any ball law).
STRUNG_SOLVERS = ("exact", "general", "cvode")
#: Output times per contact for the peaks and the energy histories.
SAMPLES = 801
#: Output times per contact of the normal force history an oblique impact's tangential contact
#: marches over (:meth:`StrungImpact.normal_samples`). The march converges fourth order in them:
#: relative to 25 601 samples, the outgoing spin of the 100 N reproducer (45 deg, 5 000 rpm,
#: mu 1) is off by 1.4e-5 at 801 samples and 1.6e-7 at 3 201, the 246 N shot of the README
#: (40 deg, -3 820 rpm, 25 m/s, mu 0.4) by 6.3e-5 and 1.3e-7, for ~0.04 s more CPU per impact
#: (tests/impact/strung/test_strung_release.py).
OBLIQUE_SAMPLES = 3201


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
    (:mod:`fem_racket.impact.strung.stretch`, a ball law without a state). The histories have
    :data:`SAMPLES` output times; :meth:`StrungImpact.normal_samples` gives the same solution at
    :data:`OBLIQUE_SAMPLES`.
    """
    check_choice("solver", solver, STRUNG_SOLVERS)
    if point.strings.stretch and solver != "cvode":
        raise InputError(
            f"solver = {solver!r} is not allowed with the strings' stretch: the stretching bed "
            "is integrated by 'cvode'"
        )
    how = {"tolerance": tolerance, "rtol": rtol, "atol": atol}
    solution = strung_solution(point, law, ball_mass, speed, solver, how)
    return _sampled(_Run(point, law, ball_mass, float(speed), solver, *solution), SAMPLES)


@dataclass(frozen=True, eq=False)
class _Run:
    """A solved strung impact before its output times are chosen
    (:mod:`fem_racket.impact.strung.solution`)."""

    point: StrungPoint
    law: ContactLaw
    ball_mass: float
    speed: float
    solver: str
    contact_time: float
    states: States


def _oblique(run: _Run) -> StrungImpact:
    """``run`` at :data:`OBLIQUE_SAMPLES` output times."""
    return _sampled(run, OBLIQUE_SAMPLES)


def _sampled(run: _Run, samples: int) -> StrungImpact:
    """The :class:`StrungImpact` of ``run`` at ``samples`` output times over the contact."""
    point, law, ball_mass, speed = run.point, run.law, run.ball_mass, run.speed
    tc = run.contact_time
    t = np.linspace(0.0, tc, samples)
    x, v, z = run.states(t)
    a = point.a
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
        speed=speed,
        ball_mass=float(ball_mass),
        solver=run.solver,
        coordinates=x,
        rates=v,
        law_state=z,
        resampled=partial(_oblique, run),
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
