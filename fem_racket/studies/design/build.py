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
from fem_racket.contact.series import SeriesBallString
from fem_racket.frame.hand import GRIPS
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.masses import DEFAULT_WIDTH
from fem_racket.frame.mesh import FrameMesh, frame_from_mesh, frame_mesh
from fem_racket.frame.modal import mode_nodes
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame, standard_frame
from fem_racket.impact.held_shock import DEFAULT_WINDOW
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.profiles import check_stations, tributary_edges
from fem_racket.studies.design.swing import (
    SWING_EXPONENT,
    SWING_WEIGHT_AXIS,
    SwingModel,
    mass_quantities,
)
from fem_racket.studies.design.variables import QUANTITIES, Constraint, Variable
from fem_racket.studies.design.zone import gaussian_zone, uniform_zone
from fem_racket.validation import InputError, check_choice

__all__ = ["ZONES", "design_problem", "mode1_node", "paper_problem"]

ZONES = ("uniform", "node")
#: Parameter groups a design may vary.
VARY = ("ei", "rhoa", "mass", "position", "string", "string_cubic")


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
    """Build a design problem; see the module docstring and :func:`.problem.paper_problem`.

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
        Bounds of the string-bed variables (see :func:`paper_problem`).
    racket_speed : float, optional
        Swing: the reference point's speed towards the ball with the starting racket [m/s]
        (:class:`.swing.SwingModel`); a stationary racket when None.
    grip : {"loose", "firm"}
        The hand of the handle-shock objectives (:data:`fem_racket.frame.hand.GRIPS`).
    constraints : dict, optional
        Quantity name (:data:`.problem.QUANTITIES`) -> None, ``(low, high)`` or ``("start",)``.
    Other parameters
        As the fields of :class:`.problem.DesignProblem` and :func:`.problem.paper_problem`.
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


def _resample(frame: Frame, bounds: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Length-weighted mean EI and rhoA of ``frame`` over each interval of ``bounds`` [m]."""
    steps = frame.steps
    ei = np.empty(bounds.size - 1)
    ra = np.empty(bounds.size - 1)
    for k, (a, b) in enumerate(zip(bounds[:-1], bounds[1:], strict=True)):
        overlap = np.clip(np.minimum(steps[1:], b) - np.maximum(steps[:-1], a), 0.0, None)
        w = overlap / (b - a)
        ei[k] = sum(wi * s.EI for wi, s in zip(w, frame.segments, strict=True))
        ra[k] = sum(wi * s.rhoA for wi, s in zip(w, frame.segments, strict=True))
    return ei, ra


def paper_problem(
    *,
    boundaries: tuple[float, ...] = (0.3, 0.5333333333333333, 0.7666666666666667),
    vary: tuple[str, ...] = ("ei", "rhoa"),
    ei_bounds: tuple[float, float] = (50.0, 3000.0),
    rhoa_bounds: tuple[float, float] = (0.2, 1.2),
    mass_positions: tuple[float, ...] = (),
    mass_bounds: tuple[float, float] = (0.0, 0.03),
    link_ei: bool = False,
    link_rhoa: bool = False,
    start: Frame | None = None,
    ei_points: tuple[float, ...] = (),
    rhoa_points: tuple[float, ...] = (),
    position_bounds: tuple[float, float] = (0.0, 1.0),
    mass_start: float = 0.0,
    law: ContactLaw | None = None,
    string_bounds: tuple[float, float] | None = None,
    cubic_bounds: tuple[float, float] | None = None,
    **kwargs: Any,
) -> DesignProblem:
    """A design problem on the paper's racket (or ``start``), split at ``boundaries`` x/L.

    Parameters
    ----------
    boundaries : tuple of float
        Interior segment boundaries x/L; the default splits the paper's step at 0.3 L and the top
        side into three equal parts (4 segments: 8 variables with ``vary=("ei", "rhoa")``).
    vary : tuple of str
        Which parameters are free: "ei", "rhoa", "mass", "position" (each a group over all
        segments, control points or added masses).
    ei_bounds, rhoa_bounds, mass_bounds : (float, float)
        Bounds of every EI [N m^2] (Fig 13's 50-3000), rhoA [kg/m] and added mass [kg].
    mass_positions : tuple of float
        Centres of added masses x/L (their starting mass is 0).
    link_ei, link_rhoa : bool
        One EI (rhoA) variable, EI_1 (rhoA_1), the others keeping their starting ratios.
    start : Frame, optional
        The starting racket; the paper's standard racket when None.
    ei_points, rhoa_points : tuple of float
        Control stations x/L of smooth profiles (:mod:`.profiles`) instead of segment values;
        their starting values are the starting racket's means over each station's share of the
        frame (between the midpoints to its neighbours).
    position_bounds : (float, float)
        Bounds x/L of the added masses' centres ("position" in ``vary``), narrowed to keep each
        strip on the frame (a centre within half a width of an end acts as if at that limit).
    mass_start : float
        Starting value of every added mass [kg].
    law : ContactLaw, optional
        The ball/string law (the paper's linear one when None).
    string_bounds : (float, float), optional
        Bounds of the string-bed stiffness ("string" in ``vary``): the factor on the paper's
        K_CB(v) [-] for the linear law, k_s [N/m] for the series law; 0.5-2 times the start
        by default.
    cubic_bounds : (float, float), optional
        Bounds of the series law's k_3 [N/m^3] ("string_cubic" in ``vary``); 0-2 times the
        start by default.
    **kwargs
        Other :class:`DesignProblem` fields (zone, speeds, swing, constraints, objectives, ...).
    """
    for name in vary:
        check_choice("vary", name, VARY)
    frame = standard_frame() if start is None else start
    length = frame.length
    b = np.asarray(boundaries, dtype=float)
    if b.size and (np.any(np.diff(b) <= 0.0) or b[0] <= 0.0 or b[-1] >= 1.0):
        raise InputError(
            f"boundaries = {list(boundaries)} x/L is not allowed: must increase within (0, 1)"
        )
    edges = np.concatenate([[0.0], b, [1.0]]) * length
    ei, ra = _resample(frame, edges)
    if ei_points:
        ei = _resample(frame, tributary_edges(check_stations("ei_points", ei_points)) * length)[0]
    if rhoa_points:
        share = tributary_edges(check_stations("rhoa_points", rhoa_points)) * length
        ra = _resample(frame, share)[1]
    n, r, a = ei.size, ra.size, len(mass_positions)
    m0 = float(mass_start)
    if law is None:
        law_start = [1.0]
    elif isinstance(law, SeriesBallString):
        law_start = [float(law.string_stiffness), float(law.string_cubic)]
    else:
        law_start = []
    p0 = np.concatenate(
        [ei, ra, np.full(a, m0), np.asarray(mass_positions, dtype=float), law_start]
    )
    variables: list[Variable] = []
    if "ei" in vary:
        if link_ei:
            variables.append(Variable("ei", 0, *ei_bounds, "N m^2", log=True))
        else:
            variables += [Variable(f"ei_{k + 1}", k, *ei_bounds, "N m^2", True) for k in range(n)]
    if "rhoa" in vary and link_rhoa:
        variables.append(Variable("rhoa", n, *rhoa_bounds, "kg/m"))
    elif "rhoa" in vary:
        variables += [Variable(f"rhoa_{k + 1}", n + k, *rhoa_bounds, "kg/m") for k in range(r)]
    if "mass" in vary:
        variables += [Variable(f"mass_{k + 1}", n + r + k, *mass_bounds, "kg") for k in range(a)]
    if "position" in vary:
        bounds = _strip_bounds(position_bounds, kwargs.get("mass_width", DEFAULT_WIDTH) / length)
        variables += [Variable(f"pos_{k + 1}", n + r + a + k, *bounds, "x/L") for k in range(a)]
    variables += _law_variables(vary, law, law_start, n + r + 2 * a, string_bounds, cubic_bounds)
    return DesignProblem(
        segment_lengths=tuple(np.diff(edges)),
        start=p0,
        variables=tuple(variables),
        mass_positions=tuple(mass_positions),
        link_ei=link_ei,
        link_rhoa=link_rhoa,
        ei_stations=tuple(ei_points),
        rhoa_stations=tuple(rhoa_points),
        law=law,
        **kwargs,
    )


def _strip_bounds(bounds: tuple[float, float], width: float) -> tuple[float, float]:
    """Position bounds x/L narrowed so that the whole strip (``width`` x/L) lies on the frame:
    beyond them the strip is pushed back inside and its position no longer matters."""
    lo, hi = bounds
    if not 0.0 <= lo < hi <= 1.0:
        return lo, hi  # refused by the problem with the bounds as given
    return max(lo, 0.5 * width), min(hi, 1.0 - 0.5 * width)


def _law_variables(
    vary: tuple[str, ...],
    law: ContactLaw | None,
    start: list[float],
    index: int,
    string_bounds: tuple[float, float] | None,
    cubic_bounds: tuple[float, float] | None,
) -> list[Variable]:
    """The string-bed variables: K_CB factor (linear law) or k_s, k_3 (series law)."""
    out: list[Variable] = []
    series = isinstance(law, SeriesBallString)
    if "string" in vary:
        if law is not None and not series:
            raise InputError(
                f"vary = 'string' is not allowed with law {law.name!r}: only the linear and "
                "series laws have a string-bed stiffness"
            )
        lo, hi = (0.5 * start[0], 2.0 * start[0]) if string_bounds is None else string_bounds
        if series:
            out.append(Variable("k_s", index, lo, hi, "N/m", log=True))
        else:
            out.append(Variable("kcb_factor", index, lo, hi, "-", log=True))
    if "string_cubic" in vary:
        if not series:
            raise InputError(
                "vary = 'string_cubic' is not allowed without law 'series': only its string "
                "bed hardens (k_3)"
            )
        default = (0.0, 2.0 * start[1] if start[1] > 0.0 else 1e9)
        lo, hi = default if cubic_bounds is None else cubic_bounds
        out.append(Variable("k_3", index + 1, lo, hi, "N/m^3"))
    return out
