"""The ball and the paper's linear ball/string law (spring-dashpot), its K_CB(V) and zeta(e) rules.

All quantities in SI.

The compound ball/string system (Kawazoe & Kanda 1997, section 2.1) is a linear spring-dashpot
``F = K_CB * delta + C_CB * d(delta)/dt`` with damping ratio
``zeta = C_CB / (2 sqrt(m_B K_CB))``. The clamped-frame coefficient of restitution ``e`` fixes
``zeta`` through eqs (1)-(4): ``e = exp(-pi zeta / sqrt(1 - zeta**2))``, i.e.
``zeta = -ln e / sqrt(pi**2 + ln(e)**2)`` (0.0592 for e = 0.83).

``K_CB`` depends on impact speed. The paper states three points (section 2.1.1): 2.74e4 N/m at
20 m/s, 5.0e4 N/m at 30 m/s and 8.33e4 N/m at 40 m/s. Between them we interpolate linearly in
log K - log V (a piecewise power law through all three points); outside 20-40 m/s the power law
of the nearest end segment is extended, within 1-100 m/s only (the paper's law excludes "the
extremely low impact speed range"; give K_CB explicitly outside it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, ClassVar

import numpy as np

from fem_racket.contact.constants import DEFAULT_BALL_MASS, KCB_SPEED_RANGE, SEPARATION_EVENTS
from fem_racket.contact.law import ContactLaw
from fem_racket.contact.parameters import LawFit, LawParameter
from fem_racket.validation import (
    InputError,
    check_choice,
    check_finite,
    check_positive,
    check_range,
    show,
)

__all__ = [
    "BALL_MASS_RANGE",
    "DEFAULT_BALL_MASS",
    "KCB_SPEED_RANGE",
    "PAPER_CLAMPED_COR",
    "PAPER_KCB_POINTS",
    "Ball",
    "LinearContact",
    "check_ball_mass",
    "cor_from_zeta",
    "kcb_from_speed",
    "zeta_from_cor",
]

#: Clamped-frame coefficient of restitution of ball on strings, eq (4).
PAPER_CLAMPED_COR = 0.83
#: (impact speed [m/s], K_CB [N/m]) stated in section 2.1.1 of the paper.
PAPER_KCB_POINTS = ((20.0, 2.74e4), (30.0, 5.0e4), (40.0, 8.33e4))
#: Plausible ball masses [kg]: a table-tennis ball is 2.7 g, a tennis ball 56-59.4 g, a baseball
#: 145 g, a cricket ball 156-163 g, a softball ~190 g (the sports' rules); 1 kg leaves room for
#: training balls.
BALL_MASS_RANGE = (1e-3, 1.0)


@dataclass(frozen=True)
class Ball:
    """The ball as a point mass.

    Parameters
    ----------
    mass : float
        m_B [kg]; default 0.057 (an assumption: the paper does not print it).
    """

    mass: float = DEFAULT_BALL_MASS

    def __post_init__(self) -> None:
        object.__setattr__(self, "mass", check_ball_mass(self.mass))


def check_ball_mass(value: object, name: str = "ball mass") -> float:
    """``value`` [kg] as a float, or a one-line :class:`InputError` unless it lies in
    :data:`BALL_MASS_RANGE`, naming the likely unit slip (grams typed as kilograms)."""
    m = check_positive(name, value, "kg")
    low, high = BALL_MASS_RANGE
    if low <= m <= high:
        return m
    slip = ""
    if high < m <= high * 1e3:
        slip = f" (grams typed as kg? {show(m)} g = {show(m / 1e3)} kg)"
    raise InputError(
        f"{name} = {show(m)} kg is not allowed: must lie in [{low:g}, {high:g}] kg, from a "
        f"table-tennis ball to a softball{slip}",
        parameter=name,
        value=m,
    )


def zeta_from_cor(cor: float) -> float:
    """Damping ratio giving clamped-frame COR ``cor`` (from eqs 1-4).

    ``zeta = -ln e / sqrt(pi^2 + ln^2 e)``; 0.83 gives 0.0592.
    """
    e = check_range("clamped COR", cor, 0.0, 1.0, include_low=False)
    le = math.log(e)
    return -le / math.sqrt(math.pi**2 + le**2)


def cor_from_zeta(zeta: float) -> float:
    """Clamped-frame COR for damping ratio ``zeta`` (eqs 1-2): exp(-pi zeta / sqrt(1 - zeta^2))."""
    z = check_range("zeta", zeta, 0.0, 1.0, include_high=False)
    return math.exp(-math.pi * z / math.sqrt(1.0 - z**2))


def kcb_from_speed(speed: float) -> float:
    """K_CB at an impact speed, by piecewise log-log interpolation of the paper's three points.

    Parameters
    ----------
    speed : float
        Impact speed [m/s], within :data:`KCB_SPEED_RANGE` (1-100 m/s).

    Returns
    -------
    float
        K_CB [N/m]: 2.74e4 at 20 m/s, 5.0e4 at 30 m/s, 8.33e4 at 40 m/s (section 2.1.1); below 20
        or above 40 m/s the power law of the end segment is extended.
    """
    low, high = KCB_SPEED_RANGE
    v = check_range("speed", speed, low, high, unit="m/s")
    logv = np.log([p[0] for p in PAPER_KCB_POINTS])
    logk = np.log([p[1] for p in PAPER_KCB_POINTS])
    x = math.log(v)
    i = int(np.clip(np.searchsorted(logv, x) - 1, 0, len(logv) - 2))
    slope = (logk[i + 1] - logk[i]) / (logv[i + 1] - logv[i])
    return float(math.exp(logk[i] + slope * (x - logv[i])))


def _zeta_from_fit(stiffness: float, damping: float, ball_mass: float) -> float:
    return damping / (2.0 * math.sqrt(ball_mass * stiffness))


@dataclass(frozen=True, eq=False)
class LinearContact(ContactLaw):
    """The paper's linear compound ball/string spring-dashpot, F = K_CB delta + C_CB delta'.

    One class for the exact eigen-solution (which reads ``stiffness`` and ``zeta``) and the
    general integrators (which call :meth:`force`). ``C_CB = 2 zeta sqrt(m_B K_CB)``: the damping
    ratio refers to the ball's mass ``ball_mass``, so the law carries it. The law is the spring
    and the dashpot: struck by another ball, K_CB and C_CB stay and zeta is that ball's
    (:meth:`for_ball`, which an impact problem applies to its law).

    Parameters
    ----------
    stiffness : float or ndarray
        K_CB [N/m] (the paper: 2.74e4, 5.0e4, 8.33e4 at 20, 30, 40 m/s).
    zeta : float or ndarray
        Damping ratio C_CB / (2 sqrt(m_B K_CB)), in [0, 1) (the paper: 0.0592).
    ball_mass : float
        m_B [kg] the damping ratio refers to (with ``zeta`` it states C_CB).
    separation : {"displacement", "force"}
        End of contact: delta back to 0 (the paper's) or F back to 0.
    """

    name: ClassVar[str] = "linear"
    declared: ClassVar[tuple[LawParameter, ...]] = (
        LawParameter(
            name="kcb",
            field="stiffness",
            unit="N/m",
            default=PAPER_KCB_POINTS[0][1],
            low=1e2,
            high=1e7,
            help="ball/string stiffness K_CB",
            # 1e2: below K_CB(V) at 1 m/s (322 N/m), a 75 ms contact (1 N/m: 654 ms, minutes of
            # CVODE). 1e7: 120 x the paper's stiffest, a 0.24 ms contact 10 elements resolve (COR
            # -0.2126/-0.2134 at 10/80 elements; 1e12: -0.563/-0.914, an answer set by the mesh).
            why="the paper's 2.74e4-8.33e4 N/m at 20-40 m/s (section 2.1.1), 322-4.2e5 N/m by "
            "its K_CB(V) over 1-100 m/s; beyond 1e7 the contact is too short for the frame's "
            "mesh to resolve",
        ),
        LawParameter(
            name="zeta",
            unit="-",
            default=zeta_from_cor(PAPER_CLAMPED_COR),
            low=0.0,
            high=1.0,
            help="ball/string damping ratio",
            why="0: elastic; 1: critically damped, no rebound (eqs 1-4)",
            open_high=True,
        ),
    )
    fit = LawFit(
        names=("kcb [N/m]", "ccb [N s/m]"),
        build=lambda p: LinearContact.from_damping(p[0], p[1]),
        low=(1e3, 1e-3),
        high=(1e7, 1e3),
        starts={"kawazoe-1997": (5e4, 6.3), "itf": (2e4, 3.0)},
    )
    stiffness: Any
    zeta: Any = field(default_factory=lambda: zeta_from_cor(PAPER_CLAMPED_COR))
    ball_mass: float = DEFAULT_BALL_MASS
    separation: str = "displacement"

    def __post_init__(self) -> None:
        if np.ndim(self.stiffness) == 0 and np.ndim(self.zeta) == 0:
            object.__setattr__(self, "stiffness", check_positive("kcb", self.stiffness, "N/m"))
            object.__setattr__(self, "zeta", check_finite("zeta", self.zeta))
        super().__post_init__()
        check_positive("ball mass", self.ball_mass, "kg")
        check_choice("separation", self.separation, SEPARATION_EVENTS)

    @property
    def end(self) -> str:  # type: ignore[override]
        """The end condition chosen by ``separation``."""
        return self.separation

    @classmethod
    def for_speed(
        cls,
        speed: float,
        *,
        kcb: float | None = None,
        zeta: float | None = None,
        clamped_cor: float = PAPER_CLAMPED_COR,
        ball_mass: float = DEFAULT_BALL_MASS,
        separation: str = "displacement",
    ) -> LinearContact:
        """The ball/string law of an impact at ``speed`` [m/s].

        Parameters
        ----------
        speed : float
            Impact speed [m/s]; sets K_CB through :func:`kcb_from_speed` unless ``kcb`` is given.
        kcb : float, optional
            K_CB [N/m], overriding the speed law.
        zeta : float, optional
            Damping ratio; from ``clamped_cor`` (eqs 1-4) when None.
        clamped_cor : float
            Clamped-frame coefficient of restitution (0.83 in the paper).
        ball_mass : float
            m_B [kg] the damping ratio refers to.
        separation : {"displacement", "force"}
            End of contact.
        """
        z = zeta_from_cor(clamped_cor) if zeta is None else zeta
        k = kcb_from_speed(speed) if kcb is None else kcb
        return cls(k, z, ball_mass, separation)

    @classmethod
    def from_damping(
        cls, stiffness: float, damping: float, ball_mass: float = DEFAULT_BALL_MASS
    ) -> LinearContact:
        """The law with K_CB = ``stiffness`` [N/m] and C_CB = ``damping`` [N s/m]."""
        return cls(stiffness, _zeta_from_fit(stiffness, damping, ball_mass), ball_mass)

    def damping(self, ball_mass: float | None = None) -> Any:
        """C_CB = 2 zeta sqrt(m_B K_CB) [N s/m], m_B the law's own unless ``ball_mass`` [kg]."""
        m = self.ball_mass if ball_mass is None else ball_mass
        if np.ndim(self.stiffness) == 0 and np.ndim(self.zeta) == 0:
            return 2.0 * self.zeta * math.sqrt(m * self.stiffness)
        return 2.0 * np.asarray(self.zeta) * np.sqrt(m * np.asarray(self.stiffness))

    def for_ball(self, ball_mass: float) -> LinearContact:
        """The same K_CB and C_CB, zeta referred to a ball of ``ball_mass`` [kg] (itself at its
        own mass). A problem refers its law to its ball, so its settings state the zeta of the
        ball that struck; refused (one line naming both masses) where C_CB damps that ball
        critically or more."""
        m = float(ball_mass)
        if m == self.ball_mass:
            return self
        scalar = np.ndim(self.stiffness) == 0 and np.ndim(self.zeta) == 0
        root = math.sqrt(m * self.stiffness) if scalar else np.sqrt(m * self.stiffness)
        zeta = self.damping() / (2.0 * root)
        if np.any(np.asarray(zeta) >= 1.0):
            raise InputError(
                f"ball mass = {show(m)} kg is not allowed with contact law {self.label()}: "
                f"its C_CB damps that ball at zeta = {float(np.max(zeta)):.4g}, must be < 1 "
                f"(its zeta is referred to its ball_mass {show(self.ball_mass)} kg)",
                parameter="ball mass",
                value=m,
            )
        return replace(self, zeta=zeta, ball_mass=m)

    def elastic(self) -> LinearContact:
        """zeta = 0: the spring without its dashpot."""
        return replace(self, zeta=0.0)

    def force(self, d: Any, v: Any, z: Any) -> Any:
        return self.stiffness * d + self.damping() * v

    def partials(self, d: Any, v: Any, z: Any) -> tuple[Any, Any, Any]:
        zero = 0.0 * np.asarray(d)
        return self.stiffness + zero, self.damping() + zero, zero

    def contact_time_estimate(self, mass: Any, speed: Any) -> Any:
        """pi sqrt(m / K_CB) [s] (eq 11)."""
        return math.pi * np.sqrt(np.asarray(mass) / self.stiffness) + 0.0 * np.asarray(speed)

    def parameters(self) -> dict[str, Any]:
        """K_CB and zeta (the run file's keys), and C_CB [N s/m]."""
        return {**super().parameters(), "ccb_n_s_m": self.damping()}
