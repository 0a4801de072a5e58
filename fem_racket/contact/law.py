"""The contact-law interface: force from deflection, its rate and an optional internal state.

A law gives the compound ball/string force ``F(delta, delta', z)`` [N] from the spring deflection
``delta = u_B - w(x_i)`` [m] (positive: compressed), its rate [m/s] and at most one internal
state ``z`` (a deflection [m]). Two kinds of state exist:

- an *ODE state*, ``z' = g(delta, delta', z)`` (the string-bed deflection of a ball in series with
  a string bed, :mod:`fem_racket.contact.series`);
- a *memory state*, the largest deflection reached so far, updated after each accepted step as
  ``z <- max(z, delta)`` (the turning point of a hysteresis loop,
  :mod:`fem_racket.contact.hysteretic`).

The integrators need the partial derivatives (``partials``, ``rate_partials``) for their Newton
iterations and Jacobians, and the law's own end condition: the deflection falling through
``end_deflection(z)`` (0 for elastic laws, the unloading branch's zero-force deflection for a
hysteretic one), the force falling through 0, or the ODE state falling through 0 (a string bed
back in its plane: the force's zero where the force itself may touch zero tangentially).
Every law works elementwise on numpy arrays, so many cases (with per-case parameters) advance
together.

A law declares its parameters once (``declared``: :class:`~.parameters.LawParameter`) with their
physical bounds, the conditions they meet together (``conditions``) and how calibration fits it
(``fit``); construction checks every value against them (arrays elementwise), and the registry
(:mod:`fem_racket.contact.registry`) derives options, run-file keys, sweep axes and JSON keys.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any, ClassVar

import numpy as np

from fem_racket.contact.parameters import LawCondition, LawFit, LawParameter, check_values

__all__ = [
    "DEFLECTION_RANGE",
    "ENDS",
    "REFERENCE_LOAD",
    "ContactLaw",
    "deflection_condition",
    "power_contact_time",
]

#: End conditions a law may name: its deflection, its force or its ODE state falling through
#: the end value.
ENDS = ("displacement", "force", "state")

#: The load [N] at which every law's loading deflection is checked: the order of a tennis
#: impact's peak force (the paper's standard impact: ~1-3 kN; Cross 1999: 0.5-1.5 kN at 15-30 m/s
#: for a ball on strings).
REFERENCE_LOAD = 1e3
#: Allowed deflection [m] under :data:`REFERENCE_LOAD`: from 10 um (stiffer than a golf ball on
#: a steel face, ~1e7 N/m or 0.1 mm) to 0.3 m (several diameters of any ball: a softer law is a
#: cushion, not a ball; the paper's K_CB give 12-36 mm). Outside it the parameters are a unit slip
#: or an unstable integration (stiffness 1e300, 1e-300), not a ball.
DEFLECTION_RANGE = (1e-5, 0.3)


def deflection_condition(
    deflection: Callable[[Mapping[str, np.ndarray], float], Any],
) -> LawCondition:
    """The condition that ``deflection(values, load)`` [m], the loading deflection under
    ``load`` = :data:`REFERENCE_LOAD` [N], lies in :data:`DEFLECTION_RANGE`."""
    low, high = DEFLECTION_RANGE

    def holds(values: Mapping[str, np.ndarray]) -> Any:
        d = deflection(values, REFERENCE_LOAD)
        return (d >= low) & (d <= high)

    return LawCondition(
        f"deflection under {REFERENCE_LOAD:g} N within [{low:g}, {high:g}] m",
        holds,
        "a ball on strings deflects 1-4 cm under 1 kN; a golf or cricket ball ~0.1-1 mm",
    )


class ContactLaw:
    """Base class of the ball/string contact laws (see the module docstring).

    Subclasses are frozen dataclasses holding SI parameters (floats, or arrays for batches) and
    define :meth:`force`, :meth:`partials`, :meth:`contact_time_estimate` and, with a state,
    :meth:`rate` and :meth:`rate_partials`.
    """

    #: Name used on the command line and in run files.
    name: ClassVar[str] = ""
    #: "ode", "memory" or None.
    state: ClassVar[str | None] = None
    #: Default end condition, one of :data:`ENDS`.
    end: ClassVar[str] = "displacement"
    #: The parameters, declared once (bounds, units, keys, options).
    declared: ClassVar[tuple[LawParameter, ...]] = ()
    #: Conditions the parameters meet together (e.g. k2 >= k1).
    conditions: ClassVar[tuple[LawCondition, ...]] = ()
    #: How calibration fits the law (None: not fitted).
    fit: ClassVar[LawFit | None] = None

    def __post_init__(self) -> None:
        """Check every declared parameter (arrays elementwise) and every condition."""
        check_values(self.name, self.declared, self.conditions, self.values())

    @classmethod
    def from_values(cls, values: Mapping[str, Any]) -> ContactLaw:
        """The law from its parameters by their declared names (numbers, or arrays of one value
        per case); a missing one takes its default."""
        return cls(**{p.field: values.get(p.name, p.default) for p in cls.declared})

    def values(self) -> dict[str, Any]:
        """The parameters by their declared names (``k1``, ``hc_alpha`` ...)."""
        return {p.name: getattr(self, p.field) for p in self.declared}

    def force(self, d: Any, v: Any, z: Any) -> Any:
        """Contact force [N] at deflection ``d`` [m], rate ``v`` [m/s] and state ``z`` [m]."""
        raise NotImplementedError

    def partials(self, d: Any, v: Any, z: Any) -> tuple[Any, Any, Any]:
        """(dF/d delta [N/m], dF/d delta' [N s/m], dF/dz [N/m])."""
        raise NotImplementedError

    def rate(self, d: Any, v: Any, z: Any) -> Any:
        """State rate z' [m/s] (ODE state only)."""
        raise NotImplementedError

    def rate_partials(self, d: Any, v: Any, z: Any) -> tuple[Any, Any, Any]:
        """(dz'/d delta [1/s], dz'/d delta' [-], dz'/dz [1/s]) (ODE state only)."""
        raise NotImplementedError

    def end_deflection(self, z: Any) -> Any:
        """Deflection [m] whose downward crossing ends a ``"displacement"`` contact."""
        return 0.0 * np.asarray(z)

    def contact_time_estimate(self, mass: Any, speed: Any) -> Any:
        """Contact time [s] of a mass [kg] striking a rigid support at ``speed`` [m/s]."""
        raise NotImplementedError

    def elastic(self) -> ContactLaw | None:
        """The same law with its losses removed (the paper's "no damping" curves), or None
        when the family has no lossless member."""
        return None

    def for_ball(self, ball_mass: float) -> ContactLaw:
        """The law as it acts on a ball of ``ball_mass`` [kg]: itself, unless its parameters
        are stated for a ball's mass (:meth:`LinearContact.for_ball
        <fem_racket.contact.linear.LinearContact.for_ball>`)."""
        return self

    def static_deflection(self, load: float) -> float:
        """Deflection [m] under a static ``load`` [N] on the loading branch (Brent's method)."""
        from scipy.optimize import brentq

        def excess(d: float) -> float:
            return float(self.force(d, 0.0, d)) - load

        high = 1e-3
        while excess(high) < 0.0 and high < 10.0:
            high *= 2.0
        return float(brentq(excess, 0.0, high, xtol=1e-15))

    def parameters(self) -> dict[str, Any]:
        """Parameters by their run-file and JSON keys, with units in the keys."""
        return {p.key: getattr(self, p.field) for p in self.declared}

    def label(self) -> str:
        """``'name' (key = value, ...)`` for one-line messages (batches: the first case)."""
        values = ", ".join(
            f"{p.name} = {float(np.ravel(getattr(self, p.field))[0]):.6g}" for p in self.declared
        )
        return f"'{self.name}' ({values})" if values else f"'{self.name}'"

    def describe(self) -> dict[str, Any]:
        """``{"law": name, **parameters}`` for JSON and VTK outputs."""
        out: dict[str, Any] = {"law": self.name}
        for key, value in self.parameters().items():
            arr = np.asarray(value)
            out[key] = float(arr) if arr.ndim == 0 else arr.tolist()
        return out


def power_contact_time(k: Any, n: Any, mass: Any, speed: Any) -> Any:
    """Contact time [s] of an elastic power law F = k delta^n against a rigid support.

    With peak deflection ``delta_m = ((n + 1) m v0^2 / (2 k))^(1/(n+1))`` energy conservation
    gives ``t_c = 2 (delta_m / v0) sqrt(pi) Gamma(1 + 1/(n+1)) / Gamma(1/2 + 1/(n+1))``
    (the Hertz time for n = 3/2, pi sqrt(m/k) for n = 1).
    """
    k, n, m, v = (np.asarray(x, dtype=float) for x in (k, n, mass, speed))
    p = 1.0 / (n + 1.0)
    dm = ((n + 1.0) * m * v**2 / (2.0 * k)) ** p
    gam = np.vectorize(lambda q: math.gamma(1.0 + q) / math.gamma(0.5 + q))(p)
    return 2.0 * dm / v * math.sqrt(math.pi) * gam
