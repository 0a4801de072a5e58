"""Design variables and constraints, and the names of the quantities and objectives.

A :class:`Variable` is one entry of a racket's parameter vector (or, linked, all its EI or rhoA
entries) with bounds; EI variables are searched on a log scale. A :class:`Constraint` bounds a
derived quantity (:data:`QUANTITIES`) to a tolerance. Objectives (:data:`OBJECTIVES`) are
maximised, those in :data:`MINIMISED` (handle shock) minimised (:mod:`.objectives`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.studies.design.objective_names import MINIMISED, OBJECTIVES
from fem_racket.validation import InputError, check_choice

__all__ = ["MINIMISED", "OBJECTIVES", "QUANTITIES", "Constraint", "Variable", "sense"]

#: Derived quantities a constraint can bound: name -> (label with units, tolerance).
QUANTITIES: dict[str, tuple[str, float]] = {
    "mass_kg": ("total mass [kg]", 1e-6),
    "balance_m": ("balance point from the butt [m]", 1e-6),
    "swing_weight_kg_cm2": ("swing weight about 0.10 m [kg cm^2]", 1e-3),
    "f1_hz": ("first free-free frequency [Hz]", 1e-3),
}


def sense(name: str) -> float:
    """+1 for an objective maximised, -1 for one minimised (:data:`MINIMISED`)."""
    return -1.0 if name in MINIMISED else 1.0


@dataclass(frozen=True)
class Variable:
    """A design variable: one entry (or, linked, all EI entries) of the parameter vector.

    Attributes
    ----------
    name : str
        ``ei_k``, ``rhoa_k``, ``mass_k`` (k from 1) or ``ei`` (linked EI).
    index : int
        Its entry of the full parameter vector.
    low, high : float
        Bounds in SI units.
    unit : str
    log : bool
        Searched on a log scale.
    """

    name: str
    index: int
    low: float
    high: float
    unit: str
    log: bool = False

    def to_unit(self, value: np.ndarray) -> np.ndarray:
        """Map physical values to [0, 1]."""
        if self.log:
            return (np.log(value) - np.log(self.low)) / (np.log(self.high) - np.log(self.low))
        return (np.asarray(value) - self.low) / (self.high - self.low)

    def from_unit(self, u: np.ndarray) -> np.ndarray:
        """Map [0, 1] to physical values."""
        u = np.asarray(u, dtype=float)
        if self.log:
            return np.exp(np.log(self.low) + u * (np.log(self.high) - np.log(self.low)))
        return self.low + u * (self.high - self.low)


@dataclass(frozen=True)
class Constraint:
    """``low <= quantity <= high`` (either side may be infinite; equal ends: an equality).

    ``tolerance`` is how far outside the bounds a result may be and still count as feasible,
    in the quantity's unit (default from :data:`QUANTITIES`).
    """

    name: str
    low: float = -np.inf
    high: float = np.inf
    tolerance: float | None = None

    def __post_init__(self) -> None:
        check_choice("constraint", self.name, tuple(QUANTITIES))
        if not self.low <= self.high:
            raise InputError(
                f"constraint {self.name} = [{self.low}, {self.high}] is not allowed: "
                "low must not exceed high"
            )
        if self.tolerance is None:
            object.__setattr__(self, "tolerance", QUANTITIES[self.name][1])

    @property
    def scale(self) -> float:
        """Typical size of the quantity (normalises violations)."""
        ends = [abs(v) for v in (self.low, self.high) if np.isfinite(v)]
        return max(ends) if ends else 1.0

    def violation(self, value: np.ndarray) -> np.ndarray:
        """Distance outside [low, high] (0 inside), in the quantity's unit."""
        value = np.asarray(value)
        return np.maximum(self.low - value, 0.0) + np.maximum(value - self.high, 0.0)

    def holds(self, value: float) -> bool:
        """True when ``value`` is within the bounds to the tolerance."""
        return bool(self.violation(value) <= self.tolerance)
