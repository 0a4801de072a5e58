"""The linear ball on the strung racket, exactly: roots, separation and closed-form histories.

The ball's spring-dashpot (k, c) on the strung racket's modal structure
(:mod:`.point`) is the engine's linear problem (:mod:`fem_racket.impact.exact`)
with every mode kept. From its roots lambda_j and contact-force residues f_j = (k + c lambda_j) r_j
(per unit speed; :mod:`fem_racket.impact.exact.single`) every coordinate follows in closed form::

    F(t) = Re sum m f_j e^{lambda_j t},   J = Re sum m f_j (e^{lambda t} - 1) / lambda,
    P = Re sum m f_j (e^{lambda t} - 1 - lambda t) / lambda^2
    ball        u_B = V t - P / m_B,  v_B = V - J / m_B
    rigid r     eta_r = a_r P,        eta_r' = a_r J
    flexible f  eta_f = a_f Re sum m f_j e^{lambda_j t} / (lambda_j^2 + omega_f^2)   (and ')

(everything times the speed V). The separation is the first fall of delta (or F) through zero
(:func:`fem_racket.impact.exact.separation.separation_time`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.exact.roots import RootSet, coupled_roots
from fem_racket.impact.exact.separation import separation_time
from fem_racket.impact.strung.point import StrungPoint
from fem_racket.impact.system import no_separation
from fem_racket.validation import InputError, show

__all__ = ["T_MAX_FACTOR", "ExactStates", "strung_exact"]

#: Give up on separation after this many spring-alone contact times.
T_MAX_FACTOR = 40.0


def _linear(law: ContactLaw) -> tuple[float, float, str]:
    """(k [N/m], c [N s/m], end) of a linear spring-dashpot law, or refuse."""
    if law.name != "linear":
        raise InputError(
            f"law = {show(law.name)} is not allowed with the exact strung solver: it takes the "
            "linear ball (use the general integrator or CVODE)"
        )
    return float(law.stiffness), float(law.damping()), law.end


def strung_exact(
    point: StrungPoint, law: ContactLaw, ball_mass: float, speed: float
) -> tuple[float, ExactStates]:
    """The contact time t_c [s] and the states ``[u_B, eta]`` and their rates at any times
    in [0, t_c] (:class:`ExactStates`), in closed form (module docstring).

    Parameters
    ----------
    point : StrungPoint
    law : ContactLaw
        A linear spring-dashpot (``name == "linear"``).
    ball_mass, speed : float
        m_B [kg], V_B0 [m/s].
    """
    k, c, end = _linear(law)
    w, a = point.flexible
    mu0 = 1.0 / ball_mass + float(np.sum(point.rigid**2))
    d = np.concatenate([[0.0], w**2])[None]
    v = np.concatenate([[mu0], a**2])[None]
    roots = next(r for p, r in coupled_roots(d, v, np.array([k]), np.array([c])) if p.size)
    lam, m = roots.lam[0], roots.mult
    fw = (k + c * lam) * roots.res[0]
    t_est = math.pi / math.sqrt(k * mu0)
    weights = roots.res if end == "displacement" else fw[None]
    one = RootSet(lam[None], roots.res, m)
    t_c, _ = separation_time(one, weights, np.array([t_est]), np.array([T_MAX_FACTOR * t_est]))
    tc = float(t_c[0])
    if not tc > 0.0:
        raise no_separation(T_MAX_FACTOR * t_est)
    inv = 1.0 / (lam[None, :] ** 2 + (w**2)[:, None])  # (modes, roots)
    return tc, ExactStates(lam, m, fw, inv, a, point.rigid, ball_mass, speed)


@dataclass(frozen=True, eq=False)
class ExactStates:
    """The states ``[u_B, eta]`` and their rates at times [s] in [0, t_c] (call it with the
    times), from the roots ``lam``, their multiplicities ``mult`` and contact-force residues
    ``fw``, ``inv`` = 1 / (lam^2 + omega_f^2) per flexible mode and root, the flexible and
    rigid shapes at the point ``a`` and ``rigid``, m_B [kg] and V_B0 [m/s] (module docstring)."""

    lam: np.ndarray
    mult: np.ndarray
    fw: np.ndarray
    inv: np.ndarray
    a: np.ndarray
    rigid: np.ndarray
    ball_mass: float
    speed: float

    def __call__(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        lam, m, fw, inv, mb = self.lam, self.mult, self.fw, self.inv, self.ball_mass
        e = np.exp(np.outer(t, lam))  # (T, R)
        J = m * ((e - 1.0) / lam * fw).real.sum(axis=1)
        P = m * ((e - 1.0 - np.outer(t, lam)) / lam**2 * fw).real.sum(axis=1)
        flex = m * ((e * fw) @ inv.T).real * self.a  # (T, modes)
        flex_v = m * ((e * fw * lam) @ inv.T).real * self.a
        x = np.column_stack([t - P / mb, np.outer(P, self.rigid), flex]) * self.speed
        xv = np.column_stack([1.0 - J / mb, np.outer(J, self.rigid), flex_v]) * self.speed
        return x, xv
