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
from dataclasses import dataclass, field

import numpy as np

from fem_racket.validation import check_positive, check_range

__all__ = [
    "DEFAULT_BALL_MASS",
    "KCB_SPEED_RANGE",
    "PAPER_CLAMPED_COR",
    "PAPER_KCB_POINTS",
    "Ball",
    "LinearContact",
    "cor_from_zeta",
    "kcb_from_speed",
    "zeta_from_cor",
]

#: Ball mass [kg]. The paper does not print it; the rules allow 56.0-59.4 g.
DEFAULT_BALL_MASS = 0.057
#: Clamped-frame coefficient of restitution of ball on strings, eq (4).
PAPER_CLAMPED_COR = 0.83
#: (impact speed [m/s], K_CB [N/m]) stated in section 2.1.1 of the paper.
PAPER_KCB_POINTS = ((20.0, 2.74e4), (30.0, 5.0e4), (40.0, 8.33e4))
#: Impact speeds [m/s] over which :func:`kcb_from_speed` extrapolates the paper's K_CB law.
KCB_SPEED_RANGE = (1.0, 100.0)


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
        object.__setattr__(self, "mass", check_positive("ball mass", self.mass, "kg"))


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


@dataclass(frozen=True)
class LinearContact:
    """Linear compound ball/string spring-dashpot.

    Parameters
    ----------
    stiffness : float
        K_CB [N/m].
    zeta : float
        Damping ratio C_CB / (2 sqrt(m_B K_CB)), in [0, 1).
    """

    stiffness: float
    zeta: float = field(default_factory=lambda: zeta_from_cor(PAPER_CLAMPED_COR))

    def __post_init__(self) -> None:
        object.__setattr__(self, "stiffness", check_positive("kcb", self.stiffness, "N/m"))
        object.__setattr__(
            self, "zeta", check_range("zeta", self.zeta, 0.0, 1.0, include_high=False)
        )

    @classmethod
    def for_speed(
        cls,
        speed: float,
        *,
        kcb: float | None = None,
        zeta: float | None = None,
        clamped_cor: float = PAPER_CLAMPED_COR,
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
        """
        z = zeta_from_cor(clamped_cor) if zeta is None else zeta
        return cls(kcb_from_speed(speed) if kcb is None else kcb, z)

    def damping(self, ball_mass: float) -> float:
        """C_CB = 2 zeta sqrt(m_B K_CB) [N s/m]."""
        return 2.0 * self.zeta * math.sqrt(ball_mass * self.stiffness)
