"""What the batched engine takes besides the structure: its options, checked case arrays and the
ball/string law of every case (:mod:`fem_racket.impact.exact.engine`).

The law per case: K_CB from the speed through the paper's three points when not given
(:func:`fem_racket.contact.linear.kcb_from_speed`), the damping ratio from the clamped-frame COR
0.83 when not given (eqs 1-4), C_CB = 2 zeta sqrt(m_B K_CB), m_B 0.057 kg when not given.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from fem_racket.contact.linear import (
    DEFAULT_BALL_MASS,
    KCB_SPEED_RANGE,
    PAPER_CLAMPED_COR,
    check_ball_mass,
    kcb_from_speed,
    zeta_from_cor,
)
from fem_racket.impact.reduction import DEFAULT_TOLERANCE, check_tolerance
from fem_racket.impact.system import SEPARATION_EVENTS
from fem_racket.validation import InputError, check_choice, check_integer

__all__ = ["EngineOptions", "Laws", "case_laws", "check_array", "check_cases"]


@dataclass(frozen=True)
class EngineOptions:
    """How the engine solves a batch (the same for every case).

    Attributes
    ----------
    separation : {"displacement", "force"}
        End of contact: delta back to 0 (the paper's) or the contact force back to 0.
    tolerance : float or None
        COR tolerance (default 1e-6) choosing the modes kept per case; None or 0: every mode.
    peak_force : bool
        Also compute the largest contact force [N].
    modes : int, optional
        Use only the lowest ``modes`` flexible modes of a frame (a plain truncation, as
        ``simulate(modes=...)``), then drop those the tolerance does not need. None: the modes
        below the cut-off are computed and the others enter through static solves. Only for
        :func:`~fem_racket.impact.exact.engine.impacts` (a frame).
    """

    separation: str = "displacement"
    tolerance: float | None = DEFAULT_TOLERANCE
    peak_force: bool = False
    modes: int | None = None

    def __post_init__(self) -> None:
        check_choice("separation", self.separation, SEPARATION_EVENTS)
        check_tolerance(self.tolerance)
        if self.modes is not None:
            check_integer("modes", self.modes)


@dataclass(frozen=True, eq=False)
class Laws:
    """The ball/string law of every case (flat arrays): V_B0 [m/s], K_CB [N/m], zeta, C_CB
    [N s/m], m_B [kg]."""

    speed: np.ndarray
    k: np.ndarray
    zeta: np.ndarray
    c: np.ndarray
    mb: np.ndarray

    def take(self, rows: np.ndarray) -> Laws:
        """The laws of the cases ``rows``."""
        return Laws(self.speed[rows], self.k[rows], self.zeta[rows], self.c[rows], self.mb[rows])


def check_array(name: str, value: Any, unit: str, low: float, high: float, *, closed_high=True):
    """``value`` as a float array with every entry in [low, high] (or [low, high)), or refuse
    naming the first bad one; None stays None."""
    arr = np.asarray(value, dtype=float) if value is not None else None
    if arr is None:
        return None
    bad = ~np.isfinite(arr) | (arr < low) | ((arr > high) if closed_high else (arr >= high))
    if low == 0.0 and name not in ("position", "zeta"):
        bad |= arr <= 0.0
    if np.any(bad):
        v = float(arr.ravel()[int(np.argmax(bad.ravel()))])
        unit_txt = f" {unit}" if unit else ""
        rng = "> 0" if high == math.inf else f"in [{low:g}, {high:g}{']' if closed_high else ')'}"
        raise InputError(
            f"{name} = {v!r}{unit_txt} is not allowed: must be {rng}", parameter=name, value=v
        )
    return arr


def check_cases(speed: Any, kcb: Any, zeta: Any, ball_mass: Any) -> None:
    """Refuse speeds, K_CB, damping ratios and ball masses out of range."""
    low, high = KCB_SPEED_RANGE
    if kcb is None:
        check_array("speed", speed, "m/s", low, high)
    else:
        check_array("speed", speed, "m/s", 0.0, math.inf)
        check_array("kcb", kcb, "N/m", 0.0, math.inf)
    check_array("zeta", zeta, "", 0.0, 1.0, closed_high=False)
    check_array("ball_mass", ball_mass, "kg", 0.0, math.inf)
    if ball_mass is not None:  # a plausible ball (grams typed as kg named)
        for m in np.unique(np.asarray(ball_mass, dtype=float)):
            check_ball_mass(m, "ball_mass")


@lru_cache(maxsize=1 << 16)
def _kcb(speed: float) -> float:
    """:func:`kcb_from_speed`, remembered: a sweep's chunks ask the same speeds again (a
    10^6-impact sweep ~30 000 times)."""
    return kcb_from_speed(speed)


def case_laws(speed: Any, kcb: Any, zeta: Any, ball_mass: Any, shape: tuple) -> Laws:
    """The law of every case of the broadcast ``shape`` (flattened)."""
    v = np.broadcast_to(speed, shape).ravel()
    if kcb is None:
        uniq, inv = np.unique(v, return_inverse=True)
        k = np.array([_kcb(float(x)) for x in uniq])[inv]
    else:
        k = np.broadcast_to(kcb, shape).ravel().astype(float)
    z = zeta_from_cor(PAPER_CLAMPED_COR) if zeta is None else zeta
    z = np.broadcast_to(z, shape).ravel().astype(float)
    mb = np.broadcast_to(DEFAULT_BALL_MASS if ball_mass is None else ball_mass, shape).ravel()
    mb = mb.astype(float)
    return Laws(v, k, z, 2.0 * z * np.sqrt(mb * k), mb)
