"""How the solvers answer impacts on a clamped head (:class:`~fem_racket.impact.clamped.
ClampedHead`): the ball against a rigid support, or against a string bed clamped at its edge.

- ``exact``: the paper's linear law by the batched engine on the head's modes
  (:func:`fem_racket.impact.exact.engine.modal_impacts`: the clamped bed's membrane modes, none
  on a rigid support; no rigid mode), to the solver's COR tolerance;
- ``general``: any law by the general integrator on the same modes
  (:func:`fem_racket.impact.general.integrator.solve_general`), with the contact's histories at
  the integrator's steps.

The problems of one head are solved in one call, by the general integrator those of one law
(laws equal by value, :func:`law_key`, whatever their objects; the paper's law, whose K_CB
follows the speed, one problem a call); each case on its own: its numbers do not depend on the
others asked with it. The ODE solvers refuse a clamped head.
"""

from __future__ import annotations

from collections.abc import Hashable, Sequence
from dataclasses import fields
from functools import lru_cache

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.clamped import ClampedHead, ClampedImpact
from fem_racket.impact.exact.engine import EngineOptions, modal_impacts
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.general.receptance import Receptance
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.settings import Settings
from fem_racket.impact.strung.point import clamped_point

__all__ = ["head_modes", "law_key", "solve_clamped"]


@lru_cache(maxsize=8)
def head_modes(head: ClampedHead) -> tuple[np.ndarray, np.ndarray]:
    """(omega [rad/s], mass-normalised values at the point [1/sqrt(kg)]) of the head's modes:
    the clamped bed's at its centre (:func:`~fem_racket.impact.strung.point.clamped_point`),
    none on a rigid support; no rigid mode. Built once per head (heads compare by identity)."""
    if head.strings is None:
        return np.zeros(0), np.zeros(0)
    return clamped_point(head.strings).flexible


def _exact(problems: list[ImpactProblem], settings: Settings) -> list[ClampedImpact]:
    """The paper's law on one clamped head: the engine, every case in one call."""
    first = problems[0]
    w, a = head_modes(first.structure)
    n = len(problems)
    contacts = [p.contact() for p in problems]
    kcb = None if all(p.kcb is None for p in problems) else [c.stiffness for c in contacts]
    zeta = None if all(p.zeta is None for p in problems) else [c.zeta for c in contacts]
    speed = np.array([p.impact.speed for p in problems])
    out = modal_impacts(
        w,
        np.tile(a, (n, 1)),
        0.0,
        speed=speed,
        kcb=kcb,
        zeta=zeta,
        ball_mass=np.array([p.ball.mass for p in problems]),
        options=EngineOptions(first.separation or "displacement", settings.tolerance),
    )
    return [
        ClampedImpact(float(v), float(e), float(t))
        for v, e, t in zip(speed, out.cor, out.contact_time, strict=True)
    ]


def _general(problems: list[ImpactProblem], settings: Settings) -> list[ClampedImpact]:
    """One law on one clamped head (the paper's: one problem): the general integrator, every
    case in one call."""
    w, a = head_modes(problems[0].structure)
    n = len(problems)
    law = problems[0].contact() if problems[0].law is None else problems[0].law
    speed = np.array([p.impact.speed for p in problems])
    rec = Receptance(
        w, np.tile(a, (n, 1)), np.zeros((n, 2)), np.array([p.ball.mass for p in problems])
    )
    out = solve_general(law, rec, speed, tolerance=settings.tolerance, t_max=settings.t_max)
    cor = -out.ball_velocity / speed
    results = []
    for i in range(n):
        k = int(out.last[i]) + 1
        time = np.arange(k) * out.step[i]
        results.append(
            ClampedImpact(
                float(speed[i]),
                float(cor[i]),
                float(out.contact_time[i]),
                time,
                out.deflection[i, :k],
                out.force[i, :k],
            )
        )
    return results


def law_key(law: ContactLaw) -> tuple[Hashable, ...]:
    """``law`` by value: its class and each field, a number or array by its type, shape and
    bytes (two laws with equal keys give the same force every bit, whatever their objects)."""
    key: list[Hashable] = [type(law)]
    for f in fields(law):  # type: ignore[arg-type]
        value = getattr(law, f.name)
        array = np.asarray(value)
        numeric = array.dtype.kind in "biuf"
        key.append((array.dtype.str, array.shape, array.tobytes()) if numeric else value)
    return tuple(key)


def solve_clamped(
    method: str, problems: Sequence[ImpactProblem], settings: Settings
) -> list[ClampedImpact]:
    """The outcomes of ``problems`` (each on a clamped head, checked) by ``method`` ("exact" or
    "general"), in order (module docstring)."""
    solve = {"exact": _exact, "general": _general}[method]
    groups: dict[tuple, list[int]] = {}
    for i, p in enumerate(problems):
        law = p.separation if method == "exact" else (i if p.law is None else law_key(p.law))
        groups.setdefault((id(p.structure), law), []).append(i)
    out: list = [None] * len(problems)
    for rows in groups.values():
        for i, r in zip(rows, solve([problems[i] for i in rows], settings), strict=True):
            out[i] = r
    return out
