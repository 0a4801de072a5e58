"""A racket design problem: variables with bounds, fixed quantities, impact zone, constraints.

The racket is a stepped beam of fixed length L split into segments, with optional added masses;
its full parameter vector p, the design variables x (any subset of p, each with bounds) and their
unit box are laid out in :mod:`.layout`. An added mass's position is a variable too (``pos_k``,
bounded inside [0, 1]). The starting racket by default is the paper's (Kawazoe & Kanda 1997,
section 2.2) sampled on the segments.

Constraints bound derived quantities (:data:`QUANTITIES`): total mass, balance point, swing weight
about 0.10 m, first free-free frequency. Objectives (:data:`OBJECTIVES`, maximised but for the
handle shock's, minimised) average over the impact zone (:mod:`.zone`) and the ball speeds; see
:mod:`.objectives`. A problem's description and digest (provenance, history): :mod:`.description`.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import (
    DEFAULT_BALL_MASS,
    KCB_SPEED_RANGE,
    PAPER_CLAMPED_COR,
    zeta_from_cor,
)
from fem_racket.frame.hand import Hand
from fem_racket.frame.masses import DEFAULT_WIDTH, AddedMass, add_masses
from fem_racket.frame.mesh import FrameMesh, frame_mesh
from fem_racket.frame.segments import Frame, Segment
from fem_racket.impact.held.shock import DEFAULT_WINDOW
from fem_racket.studies.design.description import ProblemDescription
from fem_racket.studies.design.layout import ParameterLayout
from fem_racket.studies.design.profiles import INTERPOLATIONS, cell_means, check_stations
from fem_racket.studies.design.swing import SwingModel, mass_quantities
from fem_racket.studies.design.variables import MINIMISED, OBJECTIVES, Constraint, Variable
from fem_racket.studies.design.zone import ImpactZone, uniform_zone
from fem_racket.validation import (
    InputError,
    check_choice,
    check_finite,
    check_integer,
    check_positive,
    check_range,
    show,
)

__all__ = ["DesignProblem"]


@dataclass(frozen=True, eq=False)
class DesignProblem(ParameterLayout, ProblemDescription):
    """Everything a design study fixes, and its variables.

    Attributes
    ----------
    segment_lengths : tuple of float
        Lengths of the design segments [m], grip end first (their sum is L).
    start : ndarray
        The starting racket's full parameter vector (see the module docstring).
    variables : tuple of Variable
    mass_positions : tuple of float
        Starting centres of the added masses x/L (their entries of p, fixed unless a ``pos_k``
        variable frees them).
    mass_width : float
        Width of each added mass's strip [m].
    zone : ImpactZone
    speeds : tuple of float
        Incoming ball speeds [m/s]; objectives average over them with equal weights.
    swing : SwingModel or None
        The player's swing for ``ball_speed`` and ``power_region`` (None: a stationary racket).
    constraints : tuple of Constraint
    objectives : tuple of str
        Names from :data:`OBJECTIVES`, maximised, those in :data:`MINIMISED` minimised (the
        first one for single-objective solvers).
    link_ei, link_rhoa : bool
        One variable "ei" (or "rhoa") sets every EI (rhoA) keeping the starting ratios.
    stiffness_cost : float
        Subtracted from the objectives per N m^2 of EI_1 (a price on stiffness) [1/(N m^2)].
    region : ndarray
        Positions x/L over which the power region is measured.
    power_fraction : float
        The power region is where v_out >= this fraction of its maximum (e_A without a swing).
    ball_mass, zeta : float
        m_B [kg] and the ball/string damping ratio.
    elements : int
        Cells of each design's mesh (before the added masses' strip nodes).
    modes : int or None
        Flexible modes kept per impact under the paper's law (None: every mode, the engine
        keeping those ``tolerance`` needs and the others as one pseudo-mode).
    tolerance : float or None
        COR tolerance of the impact engine (:mod:`fem_racket.impact.exact.engine`; None: every
        mode).
    hand : Hand
        The hand on the grip for the handle-shock objectives (:mod:`fem_racket.frame.hand`).
    shock_window : float
        Window of the handle-shock measures from the start of contact [s]
        (:mod:`fem_racket.impact.held.shock`).
    ei_stations, rhoa_stations : tuple of float
        Control points x/L of a smooth EI (rhoA) profile (:mod:`.profiles`); empty: one value
        per segment.
    interpolation : {"pchip", "linear"}
        The profiles' interpolant between control points.
    law : ContactLaw or None
        The ball/string law (None: the paper's linear law, K_CB from the closing speed times the
        ``kcb_factor`` entry of p, and ``zeta``); another law's impacts run through the general
        integrator (:func:`fem_racket.impact.general.integrator.solve_general`).
    """

    segment_lengths: tuple[float, ...]
    start: np.ndarray
    variables: tuple[Variable, ...]
    mass_positions: tuple[float, ...] = ()
    mass_width: float = DEFAULT_WIDTH
    zone: ImpactZone = field(default_factory=uniform_zone)
    speeds: tuple[float, ...] = (20.0, 30.0, 40.0)
    swing: SwingModel | None = None
    constraints: tuple[Constraint, ...] = ()
    objectives: tuple[str, ...] = ("cor",)
    link_ei: bool = False
    link_rhoa: bool = False
    stiffness_cost: float = 0.0
    region: np.ndarray = field(default_factory=lambda: np.linspace(0.5, 0.98, 25))
    power_fraction: float = 0.9
    ball_mass: float = DEFAULT_BALL_MASS
    zeta: float = field(default_factory=lambda: zeta_from_cor(PAPER_CLAMPED_COR))
    elements: int = 20
    modes: int | None = None
    tolerance: float | None = 1e-6
    hand: Hand = field(default_factory=Hand)
    shock_window: float = DEFAULT_WINDOW
    ei_stations: tuple[float, ...] = ()
    rhoa_stations: tuple[float, ...] = ()
    interpolation: str = "pchip"
    law: ContactLaw | None = None

    def __post_init__(self) -> None:
        n = self.n_segments
        for name in ("ei_stations", "rhoa_stations"):
            if getattr(self, name):
                object.__setattr__(self, name, check_stations(name, getattr(self, name)))
        check_choice("interpolation", self.interpolation, INTERPOLATIONS)
        size = self.n_ei + self.n_rhoa + 2 * len(self.mass_positions) + len(self.law_names)
        if self.start.shape != (size,):
            raise InputError("design start vector does not match the segments and masses")
        edges = np.concatenate([[0.0], np.cumsum(self.segment_lengths)])
        frame = Frame(tuple(Segment(h, 1.0, 1.0) for h in self.segment_lengths))
        points = frame_mesh(frame, check_integer("elements", self.elements, minimum=n)).points
        mid = 0.5 * (points[1:] + points[:-1])
        object.__setattr__(self, "_points", points)
        object.__setattr__(self, "_cell_segment", np.searchsorted(edges, mid) - 1)
        if not self.variables:
            raise InputError("design variables: none given; vary at least one")
        for name in self.objectives:
            check_choice("objective", name, tuple(OBJECTIVES))
        if not self.objectives:
            raise InputError("design objectives: none given; name at least one")
        check_range("power fraction", self.power_fraction, 0.0, 1.0, include_low=False)
        if not self.speeds:
            raise InputError("speeds = [] is not allowed: give at least one ball speed [m/s]")
        for v in self.speeds:  # the K_CB law's range (fem_racket.contact.linear)
            if self.law is None:
                check_range("speed", v, KCB_SPEED_RANGE[0], KCB_SPEED_RANGE[1], unit="m/s")
            else:
                check_range("speed", v, 0.0, KCB_SPEED_RANGE[1], unit="m/s", include_low=False)
        check_finite("stiffness cost", self.stiffness_cost, "1/(N m^2)")
        for v in self.variables:
            floor = 0.0 if v.unit in ("kg", "x/L", "N/m^3") else np.nextafter(0.0, 1.0)
            top = 1.0 if v.unit == "x/L" else np.inf
            if not (np.isfinite(v.low) and np.isfinite(v.high) and floor <= v.low < v.high <= top):
                need = (
                    "0 <= low < high <= 1"
                    if v.unit == "x/L"
                    else (f"{'0 <=' if floor == 0.0 else '0 <'} low < high, finite")
                )
                raise InputError(
                    f"{v.name} bounds = [{v.low}, {v.high}] {v.unit} are not allowed: need {need}"
                )
            declared = {p.name: p for p in getattr(self.law, "declared", ())}
            name = {"k_s": "string_stiffness", "k_3": "string_cubic"}.get(v.name, "")
            for bound in (v.low, v.high) if name in declared else ():
                declared[name].check(bound, f"{v.name} bound")  # the law's own bounds
        self.mesh(self.x_start)  # checks the added masses' positions and widths
        if self.shock:
            check_positive("shock window", self.shock_window, "s")
            # The held racket's exact path (fem_racket.impact.held.modal) is the paper's linear
            # law at K_CB(v); the string bed's variables would reach only the other objectives.
            if self.law is not None:
                raise InputError(
                    f"law = {self.law.name!r} is not allowed with the objectives "
                    f"{sorted(MINIMISED & set(self.objectives))}: the hand-held racket's "
                    "exact path takes the linear law only"
                )
            if any(v.name == "kcb_factor" for v in self.variables):
                raise InputError(
                    "variable kcb_factor is not allowed with the objectives "
                    f"{sorted(MINIMISED & set(self.objectives))}: the hand-held racket's "
                    "exact path takes K_CB(v) as it is (drop 'string' from the variables)"
                )
            if not self.hand.grip_end < self.length:
                raise InputError(
                    f"grip_end = {show(self.hand.grip_end)} m is not allowed: must lie on the "
                    "frame "
                    f"(< {self.length:g} m)",
                    parameter="grip_end",
                    value=self.hand.grip_end,
                )
        if self.swing is not None and self.swing.reference_inertia is None:
            object.__setattr__(self, "swing", replace(self.swing, reference_inertia=self._i0()))

    @property
    def shock(self) -> bool:
        """Whether an objective needs the hand-held racket (:data:`MINIMISED`)."""
        return bool(MINIMISED & set(self.objectives))

    def mesh(self, x: np.ndarray) -> FrameMesh:
        """The racket of design variables ``x`` (one design) as a mesh."""
        p = self.parameters(x)
        n, r, a = self.n_ei, self.n_rhoa, len(self.mass_positions)
        points = self._points
        ei, ra = p[:n], p[n : n + r]
        ei = (
            cell_means(self.ei_stations, ei, points, self.interpolation)
            if self.ei_stations
            else (ei[self._cell_segment])
        )
        if self.rhoa_stations:
            ra = cell_means(self.rhoa_stations, ra, points, self.interpolation)
        else:
            ra = ra[self._cell_segment]
        masses = [
            AddedMass(float(pos), float(m), self.mass_width)
            for m, pos in zip(p[n + r : n + r + a], p[n + r + a : n + r + 2 * a], strict=True)
        ]
        return add_masses(FrameMesh(points, ei, ra), masses)

    def _i0(self) -> float:
        q = mass_quantities(self.mesh(self.x_start), self.swing.pivot)
        return float(q["inertia_pivot"])
