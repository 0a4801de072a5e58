"""The tangential contact marched phase by phase in closed form: :func:`march`.

Stronge's compliant frictional contact (Stronge 2000, *Impact Mechanics*, ch. 5): a massless
tangential spring k_t = k_n / eta^2 in series with a Coulomb slider (friction mu) joins the
ball's contact point to the strings. With s the slip velocity (the ball's contact point relative
to the strings, along the face), F_t the tangential force on the ball and u = -F_t / k_t the
spring's stretch::

    s' = F_t / m*,   1/m* = beta_t / m + 1/M_t,   beta_t = 1 + m R^2 / I
    grip:  u' = s              (s'' = -omega_t^2 s, omega_t^2 = k_t / m*: a harmonic oscillator)
    slide: F_t = -sigma mu F(t),  s(t) = s(t_a) - sigma mu (P(t) - P(t_a)) / m*

(M_t: the racket's tangential effective mass, infinite for a clamped head; F, P: the normal
force and impulse, :mod:`fem_racket.impact.tangential.normal`). The ball grips while
|F_t| < mu F and starts to slide, in the direction sigma of its stretch, when |F_t| reaches
mu F; it grips again when the slider's velocity sigma s - mu F' / k_t falls to zero. Each phase
is solved in closed form, so only the switching times are searched for (bracketed on the normal
history's grid, then Brent's method to machine precision). With eta^2 = 0 (rigid tangential
contact, Routh's model) the ball slides until s = 0 and then rolls (F_t = 0).

Assumed: the tangential force does not change the normal impact (the frame's normal and
tangential motions are independent: the string plane lies on the beam's axis, which is rigid
along itself), the contact point stays at the impact point, friction acts only while the normal
force presses.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fem_racket.impact.tangential.normal import NormalHistory, _piece_root
from fem_racket.validation import InputError, show

__all__ = ["Phase", "TangentialContact", "TangentialSolution", "check_chattering", "march"]

#: Phases a march may take before it is declared stuck (Zeno chattering; refused in one line).
MAX_PHASES = 200


def check_chattering(friction: float, phases: int, t: float) -> None:
    """Refuse, in one line naming the ``friction`` [-], a march (scalar or vector) that has
    taken ``phases`` >= :data:`MAX_PHASES` phases by the time ``t`` [s] of its next switch."""
    if phases >= MAX_PHASES:
        raise InputError(
            f"friction = {show(friction)} is not allowed for this impact: the tangential "
            f"contact switched {MAX_PHASES} times by {t * 1e3:.4g} ms without settling "
            "(grip and slide undecided: chattering)",
            parameter="friction",
            value=friction,
        )


@dataclass(frozen=True, eq=False)
class FrictionSpring:
    """Coulomb friction and the tangential spring: what the scalar contact
    (:class:`TangentialContact`) and the vector one (``plane_ode.PlaneContact``) share.

    Parameters
    ----------
    friction : float
        mu >= 0.
    stiffness : float
        k_t [N/m], > 0; ``math.inf`` for a rigid tangential contact.
    """

    friction: float
    stiffness: float

    @property
    def rigid(self) -> bool:
        return math.isinf(self.stiffness)


@dataclass(frozen=True)
class TangentialContact(FrictionSpring):
    """The tangential contact's mechanics.

    Parameters
    ----------
    friction, stiffness : float
        As :class:`FrictionSpring`.
    effective_mass : float
        m* [kg]: 1/m* = beta_t / m + 1/M_t.
    """

    effective_mass: float

    @property
    def omega(self) -> float:
        """omega_t = sqrt(k_t / m*) [rad/s] of the gripping contact."""
        return math.sqrt(self.stiffness / self.effective_mass)


@dataclass(frozen=True)
class Phase:
    """One phase: ``kind`` "grip" or "slide" over [start, end] [s], starting with slip
    velocity ``slip`` [m/s] and tangential force ``force`` [N] on the ball; ``sign`` the sliding
    direction (0 when gripping)."""

    kind: str
    start: float
    end: float
    slip: float
    force: float
    sign: int


def _grip(c: TangentialContact, p: Phase, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    if c.rigid:
        return np.zeros_like(t), np.zeros_like(t)
    w = c.omega
    th = w * (t - p.start)
    u0 = -p.force / c.stiffness
    u = u0 * np.cos(th) + p.slip / w * np.sin(th)
    return p.slip * np.cos(th) - u0 * w * np.sin(th), -c.stiffness * u


def _slide(c, p: Phase, normal: NormalHistory, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    mu = c.friction * p.sign
    s = p.slip - mu * (normal.impulse(t) - normal.impulse(p.start)) / c.effective_mass
    return s, -mu * np.maximum(normal.force(t), 0.0)


class PhaseSummary:
    """The regime and grip intervals of a marched solution with ``contact`` (``friction``),
    ``normal`` (``end``) and ``phases`` (``kind``, ``start``, ``end``): shared by the scalar and
    the vector march."""

    @property
    def regime(self) -> str:
        """``slide`` when the ball slides throughout, else the phases joined by ``-`` (e.g.
        ``slide-grip-slide``)."""
        if self.contact.friction == 0.0:
            return "slide"
        # a phase of zero length (a start exactly on a regime boundary) is not a regime
        short = 1e-9 * self.normal.end
        kinds = [p.kind for p in self.phases if p.end - p.start > short] or [self.phases[0].kind]
        return "-".join(k for i, k in enumerate(kinds) if i == 0 or kinds[i - 1] != k)

    @property
    def grip_intervals(self) -> list[tuple[float, float]]:
        """(start, end) of each grip [s]."""
        if self.contact.friction == 0.0:
            return []
        return [(p.start, p.end) for p in self.phases if p.kind == "grip"]


@dataclass(frozen=True)
class TangentialSolution(PhaseSummary):
    """The marched tangential contact: its phases, and the slip velocity and force at any time."""

    contact: TangentialContact
    normal: NormalHistory
    phases: tuple[Phase, ...]

    def at(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Slip velocity s [m/s] and tangential force F_t [N] on the ball at times ``t`` [s]
        (after ``end`` the force is zero and s keeps its final value)."""
        t = np.minimum(np.asarray(t, dtype=float), self.normal.end)
        s, f = np.zeros_like(t), np.zeros_like(t)
        for p in self.phases:
            sel = (t >= p.start) & (t <= p.end)
            fun = _grip if p.kind == "grip" else _slide
            args = (
                (self.contact, p, t[sel])
                if p.kind == "grip"
                else (self.contact, p, self.normal, t[sel])
            )
            s[sel], f[sel] = fun(*args)
        return s, f

    @property
    def final_slip(self) -> float:
        """Slip velocity at the end of the contact [m/s]."""
        return float(self.at(np.array([self.normal.end]))[0][0])

    @property
    def impulse(self) -> float:
        """Tangential impulse on the ball int F_t dt [N s] = m* (s_end - s_0)."""
        return self.contact.effective_mass * (self.final_slip - self.phases[0].slip)

    @property
    def reversal_times(self) -> list[float]:
        """Times the tangential force changes sign [s] (zeros of the spring's stretch inside a
        grip)."""
        out: list[float] = []
        if self.contact.rigid or self.contact.friction == 0.0:
            return out
        w = self.contact.omega
        for p in (q for q in self.phases if q.kind == "grip"):
            a, b = -p.force / self.contact.stiffness, p.slip / w  # u = a cos + b sin
            if a == 0.0 and b == 0.0:
                continue
            first = math.atan2(b, a) + 0.5 * math.pi  # zeros of cos(theta - phi)
            k = math.floor(-first / math.pi) + 1
            while (theta := first + k * math.pi) <= w * (p.end - p.start):
                if theta > 0.0:
                    out.append(p.start + theta / w)
                k += 1
        return out


def _first_crossing(fun, t0: float, end: float, grid: np.ndarray) -> float | None:
    """The first time in (t0, end] where ``fun`` reaches >= 0, or None."""
    tiny = 1e-12 * end
    pts = np.concatenate(([t0 + tiny], grid[(grid > t0 + tiny) & (grid < end)], [end]))
    vals = fun(pts)
    hit = np.flatnonzero(vals >= 0.0)
    if hit.size and hit[0] == 0 and pts.size > 1 and vals[1] < 0.0:
        hit = hit[1:]  # a tangency at t0 (a start exactly on a regime boundary): not a switch
    if hit.size == 0:
        return None
    i = int(hit[0])
    if i == 0:  # at once: a phase of zero length, unless it holds just after its start
        held = _held_from(fun, t0, float(pts[1]) if pts.size > 1 else end)
        return float(pts[0]) if held is None else _first_crossing(fun, held, end, grid)
    return _piece_root(fun, float(pts[i - 1]), float(pts[i]))


#: Where a phase whose switching function is >= 0 just after its start is probed again, as
#: fractions of the way to the next search point.
PROBES = (1e-6, 1e-4, 1e-2, 1e-1)


def _held_from(fun, t0: float, nxt: float) -> float | None:
    """The first probe after ``t0`` (toward ``nxt``) where ``fun`` < 0, or None.

    A phase starting at a grazing switch (a slide stopping just as the spring reaches mu F: the
    grip's margin then starts at zero with zero slope, mu (F'' + omega_t^2 F) its curvature) is
    decided at t0 + 1e-12 ``end`` by round-off (1e-18 N of a 1e-3 N force): the march then
    switched back and forth at one instant (phases of 5e-15 s, or 200 of them: chattering). A
    probe far enough from t0 for the curvature to show decides it; a phase that ends at once
    shows it at every probe (its margin falls at first order)."""
    for fraction in PROBES:
        t = t0 + fraction * (nxt - t0)
        if float(fun(np.array([t]))[0]) < 0.0:
            return t
    return None


def _start(c: TangentialContact, normal: NormalHistory, s0: float) -> Phase:
    """The first phase: grip, the spring unstretched, unless the ball slips at once (a rigid
    contact, or a spring that cannot stretch as fast as the friction limit mu F grows from 0)."""
    f0 = max(float(normal.force(0.0)), 0.0)
    slow = f0 == 0.0 and c.stiffness * abs(s0) >= c.friction * float(normal.rate(0.0))
    if c.friction == 0.0 or (s0 != 0.0 and (c.rigid or slow)):
        sign = int(np.sign(s0))
        return Phase("slide", 0.0, normal.end, s0, -c.friction * sign * f0, sign)
    return Phase("grip", 0.0, normal.end, s0, 0.0, 0)


def march(c: TangentialContact, normal: NormalHistory, slip: float) -> TangentialSolution:
    """March the tangential contact over the normal history from slip velocity ``slip`` [m/s]
    and an unstretched spring.

    Returns
    -------
    TangentialSolution
    """
    phases = [_start(c, normal, float(slip))]
    while True:
        p = phases[-1]
        if c.friction == 0.0:
            break
        if p.kind == "grip":

            def g(t, p=p):
                return np.abs(_grip(c, p, t)[1]) - c.friction * normal.force(t)

        else:

            def g(t, p=p):
                s = _slide(c, p, normal, t)[0]
                lag = 0.0 if c.rigid else c.friction * normal.rate(t) / c.stiffness
                return -(p.sign * s - lag)

        t1 = _first_crossing(g, p.start, normal.end, normal.grid)
        if t1 is None or t1 >= normal.end:
            break
        check_chattering(c.friction, len(phases), t1)
        tt = np.array([t1])
        if p.kind == "grip":
            s1, f1 = (v[0] for v in _grip(c, p, tt))
            nxt = Phase("slide", t1, normal.end, float(s1), float(f1), -int(np.sign(f1)))
        else:
            s1, f1 = (v[0] for v in _slide(c, p, normal, tt))
            nxt = Phase("grip", t1, normal.end, 0.0 if c.rigid else float(s1), float(f1), 0)
        phases[-1] = Phase(p.kind, p.start, t1, p.slip, p.force, p.sign)
        phases.append(nxt)
    return TangentialSolution(c, normal, tuple(phases))
