"""An oblique, spinning ball on the racket: :func:`solve_oblique` -> :class:`ObliqueResult`.

The normal impact is today's, at the normal speed V cos(angle): any contact law, any solver, on
the free racket (:func:`fem_racket.impact.incidence.head_on`, solved by the problem's solver)
or on a clamped head (:func:`clamped_normal`: eqs 1-3 in closed form, the paper's linear law).
The tangential contact (:mod:`fem_racket.impact.tangential`) is then marched over its normal
force history, with the racket's tangential response: the free racket moves rigidly in the
plane of its face (the string plane lies on the beam's axis, so the tangential force neither
bends nor twists it, and the frame is taken as rigid in that plane), translating with its mass
M and turning about the face normal through its centre of gravity (its yaw, inertia
I_n = I_cg + I_p for a flat racket, the perpendicular-axis theorem; I_p the polar moment of
:mod:`fem_racket.impact.offaxis`): on the long axis and in its plane that is M_t = M; across
the face, or off the axis, the impact point's 2x2 compliance couples the two directions
(:class:`~fem_racket.impact.tangential.oblique.BallMotion`). The racket's roll about its long
axis, from the normal force off the axis, moves the face point only along the normal (the
face contains the roll axis), so it enters the normal impact (:mod:`fem_racket.impact.offaxis`)
and not the tangential one; the tangential force, applied in the face, exerts no roll moment.
A clamped head does not move.

Assumed (stated in the README): the tangential force does not change the normal impact (so with
mu = 0, or head-on without spin, the normal outcome is exactly the head-on impact's at the
normal speed); the contact point stays at the impact point (the ball travels a few cm along
the face during contact); the frame's tangential compliance and the strings' lateral motion are
neglected; K_CB follows the normal speed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.impact.analytic.rigid import ClampedImpact, clamped_impact
from fem_racket.impact.held.run import HeldRun
from fem_racket.impact.incidence import Incidence, head_on
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.result import ImpactResult
from fem_racket.impact.tangential.normal import (
    ClampedNormal,
    NormalHistory,
    SampledNormal,
    peak_force,
)
from fem_racket.impact.tangential.oblique import (
    BallMotion,
    ObliqueOutcome,
    RacketYaw,
    tangential_impact,
)
from fem_racket.impact.tangential.result_history import normal_history
from fem_racket.validation import InputError, check_choice, work_begins

__all__ = [
    "CLAMPED_ARGS",
    "NormalImpact",
    "ObliqueResult",
    "clamped_normal",
    "free_normal",
    "held_normal",
    "normal_history",
    "oblique_on",
    "solve_oblique",
]

#: Output step of the normal impact whose force history drives the tangential contact [s].
OBLIQUE_OUTPUT_STEP = 1e-5


@dataclass(frozen=True, eq=False)
class ObliqueResult:
    """The normal impact and the tangential contact of one oblique impact.

    Attributes
    ----------
    normal : ImpactResult or ClampedImpact
        The normal impact at the normal speed (ClampedImpact: a clamped head, eqs 1-3).
    tangential : ObliqueOutcome
        Outgoing speed, angle and spin, the regime, histories.
    speed : float
        Incident ball speed [m/s].
    contact : LinearContact or None
        The clamped head's K_CB and zeta (None on the free racket: in ``normal``).
    stroke : dict or None
        A stroke's face and path angles, the incidence they give and the launch angle
        (:mod:`fem_racket.impact.simulate_stroke`), units in the keys.
    """

    normal: ImpactResult | ClampedImpact | HeldRun
    tangential: ObliqueOutcome
    speed: float
    contact: LinearContact | None = None
    stroke: dict[str, Any] | None = None

    @property
    def clamped(self) -> bool:
        return isinstance(self.normal, ClampedImpact)

    @property
    def held(self) -> bool:
        return isinstance(self.normal, HeldRun)

    def histories(self) -> dict[str, np.ndarray]:
        """Time histories of the tangential contact at the normal impact's output times (over
        the force's contact for a clamped head or a hand-held racket), units in the names."""
        if self.clamped or self.held:
            t = self.tangential.solution.normal.grid
            return {"time [s]": t, **self.tangential.histories(t)}
        return {"time [s]": self.normal.t, **self.tangential.histories(self.normal.t)}

    def summary(self) -> dict[str, Any]:
        """The normal impact's summary (its ``rebound_speed_m_s`` the normal component) with the
        oblique outcome: ``ball_speed_out_m_s`` the full outgoing speed, ``angle_out_deg``,
        ``spin_out_rpm``, ``contact_regime``...; units in the keys."""
        if self.clamped:
            n, c = self.normal, self.contact
            base = {
                "cor": n.cor,
                "contact_time_s": n.contact_time,
                "rebound_speed_m_s": -n.rebound_velocity,
                "peak_force_n": peak_force(self.tangential.solution.normal),
                "structure": "clamped head",
                "ball_mass_kg": self.tangential.ball.mass,
                "law": "linear",
                "kcb_n_m": c.stiffness,
                "zeta": c.zeta,
            }
        else:
            where = "hand-held racket" if self.held else "free racket"
            base = {**self.normal.summary(), "structure": where}
        normal_speed = self.tangential.incidence.components(self.speed)[0]
        return {
            **base,
            "speed_m_s": self.speed,
            "normal_speed_m_s": normal_speed,
            **self.tangential.summary(),
            **(self.stroke or {}),
        }


@dataclass(frozen=True, eq=False)
class NormalImpact:
    """The normal impact an oblique one builds on (shared by every spin and friction at one
    normal speed).

    Attributes
    ----------
    result : ImpactResult or ClampedImpact
    history : NormalHistory
        Its force history.
    ball_mass : float
        m [kg].
    racket_mass : float
        M_t [kg], the tangential effective mass (``math.inf``: clamped head).
    contact : LinearContact or None
        A clamped head's K_CB and zeta.
    model : FrameModel or None
        The free racket (its yaw inertia); None: clamped, or no yaw (a hand).
    point : (float, float)
        The impact point: along the frame from the butt and across from the long axis [m].
    """

    result: ImpactResult | ClampedImpact
    history: NormalHistory
    ball_mass: float
    racket_mass: float
    contact: LinearContact | None = None
    model: Any = None
    point: tuple[float, float] = (0.0, 0.0)
    held: bool = False

    @property
    def offset(self) -> float:
        return self.point[1]

    def racket_yaw(self) -> RacketYaw | None:
        """The free racket's yaw about the face normal (None for a clamped head); needs the
        frame's polar moment (torsion data)."""
        if self.model is None:
            return None
        props = self.model.props
        inertia = props.inertia + self.model.torsion.polar_moment
        return RacketYaw(inertia, self.point[0] - props.cg, self.point[1])

    @property
    def rebound_speed(self) -> float:
        """Normal speed of the ball away from the strings after impact [m/s]."""
        if isinstance(self.result, ClampedImpact):
            return -self.result.rebound_velocity
        return self.result.ball_speed_out


def oblique_on(normal: NormalImpact, incidence: Incidence, speed: float) -> ObliqueResult:
    """The oblique impact of ``incidence`` at ``speed`` [m/s] over its computed normal impact
    (at the normal speed ``speed cos(side) cos(angle)``); the racket's yaw enters when
    anything crosses the face or the point is off the axis (else M_t alone, as in the plane)."""
    v_t = incidence.components(speed)[1]
    if normal.held and incidence.lateral:
        raise InputError(
            "side_angle and side_spin are not allowed with a hand: the hand holds the racket in "
            "the plane of its long axis only (the held racket's yaw is not modelled)"
        )
    yaw = normal.racket_yaw() if incidence.lateral or normal.offset != 0.0 else None
    motion = BallMotion(
        normal.ball_mass, v_t, normal.rebound_speed, normal.racket_mass,
        lateral_speed=incidence.lateral_speed(speed), yaw=yaw,
    )  # fmt: skip
    out = tangential_impact(incidence, normal.history, motion)
    return ObliqueResult(normal.result, out, speed, normal.contact)


def free_normal(result: ImpactResult) -> NormalImpact:
    """The normal impact of a free racket, computed with histories."""
    m_b, model = result.ball.mass, result.model
    point = (result.x_impact, result.offset)
    return NormalImpact(result, normal_history(result), m_b, model.props.mass, None, model, point)


def held_normal(run: HeldRun, problem: ImpactProblem) -> NormalImpact:
    """The normal impact of a hand-held racket, computed with histories.

    The impulse P(t) is the integral of the contact force's samples over the contact (a cubic
    spline's, fourth order in the output step); k_n is K_CB. Along the face the held racket
    recoils with the frame's mass M: the hand model's grip layer acts across the handle, in
    the swing plane, and nothing joins it along the long axis (a hand rigidly joined there
    would make it M + m_h; README "Oblique impacts and spin" gives the difference).
    """
    from scipy.interpolate import CubicSpline

    if run.histories is None:
        raise InputError(
            "an oblique impact needs the normal impact's histories: give an output_step"
        )
    t, f = run.histories["time [s]"], run.histories["contact force [N]"]
    on = t <= run.contact_time
    t, f = t[on], f[on]
    impulse = CubicSpline(t, f).antiderivative()(t)
    history = SampledNormal(t, impulse, f, run.used["kcb_n_m"])
    model = problem.structure.model
    point = (problem.impact.position * model.mesh.length, 0.0)
    return NormalImpact(
        run, history, problem.ball.mass, model.props.mass, None, None, point, held=True
    )


def solve_oblique(solver: Any, problem: ImpactProblem) -> ObliqueResult:
    """Solve an oblique ``problem`` with ``solver`` (a :class:`~fem_racket.impact.solvers.Solver`,
    which calls this for a problem with an incidence): its normal impact
    (:func:`fem_racket.impact.incidence.head_on`), then the tangential contact over it."""
    result = solver.solve(head_on(problem))
    if isinstance(result, HeldRun):
        normal = held_normal(result, problem)
    else:
        normal = free_normal(result)
    return oblique_on(normal, problem.incidence, problem.impact.speed)


#: What a clamped head takes besides the incidence and the speed.
CLAMPED_ARGS = ("ball_mass", "kcb", "zeta", "separation")


def clamped_normal(frame: Any, v_n: float, kwargs: dict) -> NormalImpact:
    """The normal impact on a clamped head at ``v_n`` [m/s]: the paper's spring-dashpot in
    closed form (eqs 1-3); ``kwargs`` only ``ball_mass``, ``kcb``, ``zeta``, ``separation``
    (``frame`` must be None)."""
    extra = sorted(set(kwargs) - set(CLAMPED_ARGS))
    if frame is not None or extra:
        name = "frame" if frame is not None else extra[0]
        raise InputError(
            f"{name} is not allowed with a clamped head: it takes only {', '.join(CLAMPED_ARGS)}"
        )
    separation = check_choice(
        "separation", kwargs.get("separation", "displacement"), ("displacement", "force")
    )
    ball = Ball() if kwargs.get("ball_mass") is None else Ball(kwargs["ball_mass"])
    contact = LinearContact.for_speed(v_n, kcb=kwargs.get("kcb"), zeta=kwargs.get("zeta"))
    work_begins()  # fem-racket config --check stops here: every check has passed
    history = ClampedNormal(ball.mass, contact.stiffness, contact.zeta, v_n)
    eqs = clamped_impact(ball.mass, contact.stiffness, contact.zeta, v_n)
    if separation == "force":  # contact ends as the force returns to zero (DESIGN.md section 1)
        out = history.rebound_speed()
        eqs = ClampedImpact(eqs.omega_n, eqs.omega_d, history.end, -out, out / v_n)
    return NormalImpact(eqs, history, ball.mass, math.inf, contact)
