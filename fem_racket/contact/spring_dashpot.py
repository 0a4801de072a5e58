"""The paper's linear compound ball/string law as a :class:`~fem_racket.contact.law.ContactLaw`.

``F = K_CB delta + C_CB delta'`` (Kawazoe & Kanda 1997, section 2.1), with
``C_CB = 2 zeta sqrt(m_B K_CB)`` fixed by the clamped COR (eqs 1-4). The exact eigen-solution
(:mod:`fem_racket.impact.exact.closed_form`) stays this law's default path; this form lets the
general integrators run it too, so every path can be checked against the exact one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from fem_racket.contact.law import ContactLaw

__all__ = ["SpringDashpot"]


@dataclass(frozen=True, eq=False)
class SpringDashpot(ContactLaw):
    """Linear spring K_CB [N/m] and dashpot C_CB [N s/m] in parallel.

    Parameters
    ----------
    stiffness : float or ndarray
        K_CB [N/m] (the paper: 2.74e4, 5.0e4, 8.33e4 at 20, 30, 40 m/s).
    damping : float or ndarray
        C_CB [N s/m] (the paper: 2 zeta sqrt(m_B K_CB), zeta = 0.0592).
    separation : {"displacement", "force"}
        End of contact: delta back to 0 (the paper's) or F back to 0.
    """

    name: ClassVar[str] = "linear"
    stiffness: Any
    damping: Any = 0.0
    separation: str = "displacement"

    @property
    def end(self) -> str:  # type: ignore[override]
        """The end condition chosen by ``separation``."""
        return self.separation

    def force(self, d: Any, v: Any, z: Any) -> Any:
        return self.stiffness * d + self.damping * v

    def partials(self, d: Any, v: Any, z: Any) -> tuple[Any, Any, Any]:
        zero = 0.0 * np.asarray(d)
        return self.stiffness + zero, self.damping + zero, zero

    def contact_time_estimate(self, mass: Any, speed: Any) -> Any:
        """pi sqrt(m / K_CB) [s] (eq 11)."""
        return math.pi * np.sqrt(np.asarray(mass) / self.stiffness) + 0.0 * np.asarray(speed)

    def parameters(self) -> dict[str, Any]:
        return {"kcb_n_m": self.stiffness, "ccb_n_s_m": self.damping}
