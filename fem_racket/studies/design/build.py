"""A design problem from plain settings (the CLI's options, a run file's ``[design]`` table).

``design_problem(start=None, objectives=("cor",), mass=("start",), ...)`` builds a
:class:`~.problem.DesignProblem` on the starting racket: each constraint is ``None`` (absent), a
``(low, high)`` pair, or ``("start",)`` (equal to the starting racket's value: "keep its mass");
the zone is ``"uniform"`` over ``zone_range`` or ``"node"``, a Gaussian about the starting
racket's mode-1 node on the string face (Hatze 1994). ``ei_points`` / ``rhoa_points`` (control
stations x/L) make EI(x) / rhoA(x) smooth profiles (:mod:`.profiles`); ``vary`` "position"
frees the added masses' centres within ``position_bounds``; "string" frees the string bed's
stiffness (the factor on K_CB for the paper's linear law, k_s of the series law, within
``string_bounds``) and "string_cubic" the series law's k_3 (``cubic_bounds``).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.frame.hand import GRIPS
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.mesh import FrameMesh, frame_from_mesh, frame_mesh
from fem_racket.frame.modal import mode_nodes
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame, standard_frame
from fem_racket.impact.held.shock import DEFAULT_WINDOW
from fem_racket.studies.design.paper_problem import paper_problem
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.swing import (
    SWING_EXPONENT,
    SWING_WEIGHT_AXIS,
    SwingModel,
    mass_quantities,
)
from fem_racket.studies.design.variables import QUANTITIES, Constraint
from fem_racket.studies.design.zone import gaussian_zone, uniform_zone
from fem_racket.validation import InputError, check_choice

__all__ = ["ZONES", "design_problem", "mode1_node"]

ZONES = ("uniform", "node")


def mode1_node(frame: Frame, elements: int = 20) -> float:
    """The first free-free mode's node on the string face (x/L > 0.5) of ``frame``."""
    model = FrameModel(assemble_closed_form(frame_mesh(frame, elements)))
    nodes = mode_nodes(model.fe, model.modes(1).shapes[:, 0])
    face = nodes[nodes > 0.5]
    if face.size == 0:
        raise InputError("zone = 'node' is not allowed: mode 1 has no node beyond 0.5 L")
    return float(face[0])


def _start_values(frame: Frame, elements: int) -> dict[str, float]:
    mesh = frame_mesh(frame, elements)
    mq = mass_quantities(mesh)
    model = FrameModel(assemble_closed_form(mesh))
    return {
        "mass_kg": mq["mass"],
        "balance_m": mq["cg"],
        "swing_weight_kg_cm2": mq["swing_weight_kg_cm2"],
        "f1_hz": float(model.modes(1).frequencies[0]),
    }


def _pair(name: str, value: Sequence[float]) -> tuple[float, float]:
    if len(value) != 2 or not value[0] < value[1]:
        raise InputError(f"{name} = {list(value)} is not allowed: give LOW,HIGH with LOW < HIGH")
    return float(value[0]), float(value[1])


def design_problem(
    start: Frame | FrameMesh | None = None,
    *,
    objectives: Sequence[str] = ("cor",),
    boundaries: Sequence[float] = (0.3, 0.5333333333333333, 0.7666666666666667),
    vary: Sequence[str] = ("ei", "rhoa"),
    link_ei: bool = False,
    ei_bounds: Sequence[float] = (50.0, 3000.0),
    rhoa_bounds: Sequence[float] = (0.2, 1.2),
    mass_positions: Sequence[float] = (),
    mass_bounds: Sequence[float] = (0.0, 0.03),
    mass_width: float = 0.02,
    ei_points: Sequence[float] = (),
    rhoa_points: Sequence[float] = (),
    interpolation: str = "pchip",
    position_bounds: Sequence[float] = (0.0, 1.0),
    mass_start: float = 0.0,
    law: ContactLaw | None = None,
    string_bounds: Sequence[float] | None = None,
    cubic_bounds: Sequence[float] | None = None,
    zone: str = "uniform",
    zone_range: Sequence[float] = (0.6, 0.9),
    zone_points: int = 20,
    zone_sigma: float = 0.05,
    speeds: Sequence[float] = (20.0, 30.0, 40.0),
    racket_speed: float | None = None,
    reference: float = 0.75,
    pivot: float = SWING_WEIGHT_AXIS,
    swing_exponent: float = SWING_EXPONENT,
    constraints: dict[str, Sequence[Any] | None] | None = None,
    stiffness_cost: float = 0.0,
    power_fraction: float = 0.9,
    ball_mass: float | None = None,
    zeta: float | None = None,
    elements: int = 20,
    grip: str = "loose",
    shock_window: float = DEFAULT_WINDOW,
) -> DesignProblem:
    """Build a design problem; see the module docstring and :func:`.paper_problem.paper_problem`.

    Parameters
    ----------
    start : Frame or FrameMesh, optional
        The starting racket (the paper's when None); a mesh is read as its piecewise-uniform
        frame.
    ei_points, rhoa_points : sequence of float
        Control stations x/L of smooth EI(x), rhoA(x) profiles (first 0, last 1); empty: one
        value per segment.
    position_bounds : (float, float)
        Bounds x/L of every added mass's centre when ``vary`` has "position".
    mass_start : float
        Starting value of every added mass [kg] (0: the starting racket as it is).
    law : ContactLaw, optional
        The ball/string law; the paper's linear law when None.
    string_bounds, cubic_bounds : (float, float), optional
        Bounds of the string-bed variables (see :func:`.paper_problem.paper_problem`).
    racket_speed : float, optional
        Swing: the reference point's speed towards the ball with the starting racket [m/s]
        (:class:`.swing.SwingModel`); a stationary racket when None.
    grip : {"loose", "firm"}
        The hand of the handle-shock objectives (:data:`fem_racket.frame.hand.GRIPS`).
    constraints : dict, optional
        Quantity name (:data:`.variables.QUANTITIES`) -> None, ``(low, high)`` or ``("start",)``.
    Other parameters
        As the fields of :class:`.problem.DesignProblem` and :func:`.paper_problem.paper_problem`.
    """
    check_choice("zone", zone, ZONES)
    check_choice("grip", grip, tuple(GRIPS))
    frame = standard_frame() if start is None else start
    if isinstance(frame, FrameMesh):
        frame = frame_from_mesh(frame)
    base = _start_values(frame, elements)
    cons = []
    for name, value in (constraints or {}).items():
        check_choice("constraint", name, tuple(QUANTITIES))
        if value is None:
            continue
        if len(value) == 1 and value[0] == "start":
            cons.append(Constraint(name, base[name], base[name]))
        else:
            cons.append(Constraint(name, *_pair(name, value)))
    if zone == "uniform":
        lo, hi = _pair("zone range", zone_range)
        z = uniform_zone(lo, hi, zone_points)
    else:
        z = gaussian_zone(mode1_node(frame, elements), zone_sigma, zone_points)
    swing = None
    if racket_speed is not None:
        swing = SwingModel(racket_speed, reference, pivot, swing_exponent)
    extra: dict[str, Any] = {}
    if ball_mass is not None:
        extra["ball_mass"] = ball_mass
    if zeta is not None:
        extra["zeta"] = zeta
    return paper_problem(
        start=frame,
        boundaries=tuple(boundaries),
        vary=tuple(vary),
        ei_bounds=_pair("ei bounds", ei_bounds),
        rhoa_bounds=_pair("rhoa bounds", rhoa_bounds),
        mass_positions=tuple(mass_positions),
        mass_bounds=_pair("mass bounds", mass_bounds),
        link_ei=link_ei,
        mass_width=mass_width,
        ei_points=tuple(ei_points),
        rhoa_points=tuple(rhoa_points),
        interpolation=interpolation,
        position_bounds=_pair("position bounds", position_bounds),
        mass_start=mass_start,
        law=law,
        string_bounds=None if string_bounds is None else _pair("string bounds", string_bounds),
        cubic_bounds=None if cubic_bounds is None else _pair("cubic bounds", cubic_bounds),
        zone=z,
        speeds=tuple(float(v) for v in speeds),
        swing=swing,
        constraints=tuple(cons),
        objectives=tuple(objectives),
        stiffness_cost=stiffness_cost,
        power_fraction=power_fraction,
        elements=elements,
        hand=GRIPS[grip],
        shock_window=shock_window,
        **extra,
        region=np.linspace(0.5, 0.98, 25),
    )
