"""Exact natural frequencies of a free-free piecewise-uniform shaft in torsion.

Each uniform segment (length l, GJ, rhoIp) obeys ``GJ theta'' + rhoIp omega^2 theta = 0``, so
with ``k = omega sqrt(rhoIp / GJ)`` the state [theta, T = GJ theta'] (twist angle and torque) is
carried across it by the transfer matrix::

    [[cos kl, sin kl / (GJ k)], [-GJ k sin kl, cos kl]]

and theta and T are continuous at a step. Free ends (T = 0 at both): start from (1, 0) and find
the omega at which the torque reaches x = L as zero. The torque is a bounded, smooth function of
omega, so its roots are bracketed on a grid of 16 points per pi of the total phase
sum(k_i l_i) (successive free-free roots are about pi apart in it) and refined by Brent's method
(xtol 1e-15 relative). For a uniform shaft the roots are omega_n = n pi sqrt(GJ / rhoIp) / L.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from fem_racket.frame.segments import TorsionSegment
from fem_racket.validation import check_integer

__all__ = ["end_torque", "torsion_frequencies"]

#: Grid points per pi of total phase when bracketing roots.
_GRID_PER_PI = 16


def end_torque(segments: Sequence[TorsionSegment], omega: float) -> float:
    """Torque at x = L [N m] of the free-free shaft twisted by 1 rad at x = 0, at ``omega``
    [rad/s], scaled by the largest rigidity so that it is O(1)."""
    theta, T = 1.0, 0.0
    scale = max(s.GJ for s in segments)
    for s in segments:
        k = omega * np.sqrt(s.rhoIp / s.GJ)
        c, sn = np.cos(k * s.length), np.sin(k * s.length)
        z = s.GJ * k / scale
        theta, T = c * theta + sn * T / z, -z * sn * theta + c * T
    return float(T)


def torsion_frequencies(segments: Sequence[TorsionSegment], n: int) -> np.ndarray:
    """The lowest ``n`` flexible free-free torsion frequencies [Hz] (the rigid roll excluded).

    Parameters
    ----------
    segments : sequence of TorsionSegment
        Grip end first.
    n : int
        How many.
    """
    from scipy.optimize import brentq

    n = check_integer("n", n)
    slowness = sum(s.length * np.sqrt(s.rhoIp / s.GJ) for s in segments)  # phase per rad/s
    roots: list[float] = []
    top = (n + 1) * np.pi / slowness
    while len(roots) < n:
        w = np.linspace(0.0, top, int(_GRID_PER_PI * (n + 1) * top * slowness / np.pi) + 2)[1:]
        f = np.array([end_torque(segments, x) for x in w])
        roots = [
            brentq(lambda x: end_torque(segments, x), w[i], w[i + 1], xtol=1e-15, rtol=1e-15)
            for i in np.flatnonzero(np.sign(f[:-1]) * np.sign(f[1:]) < 0)
        ]
        top *= 2.0
    return np.array(roots[:n]) / (2.0 * np.pi)
