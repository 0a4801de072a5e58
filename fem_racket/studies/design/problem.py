"""A racket design problem: variables with bounds, fixed quantities, impact zone, constraints.

The racket is a stepped beam of fixed length L whose segments (between fixed boundaries x/L) each
have a bending rigidity EI_k [N m^2] and mass per length rhoA_k [kg/m], plus optional masses added
at chosen positions (strips, :mod:`fem_racket.frame.masses`). Its full parameter vector is::

    p = [EI_1 .. EI_n, rhoA_1 .. rhoA_n, m_1 .. m_a, x_1 .. x_a]

(x_k the added masses' centres x/L), followed by the contact law's string-bed parameters
(:meth:`DesignProblem.law_names`): the factor on the paper's K_CB(v) for its linear law, k_s and
k_3 for the series law. With ``ei_stations`` (``rhoa_stations``) the EI (rhoA)
entries are instead the values of a smooth profile at those control points x/L, interpolated
between them and averaged over each mesh cell (:mod:`.profiles`); their count is the stations'.

Any subset of p is free (the design variables, each with bounds); the rest keeps the starting
racket's values. With ``link_ei`` one variable "ei" is EI_1 and every EI_k keeps its starting ratio
EI_k / EI_1 (the paper's Fig 13 varies EI1 with EI2 = 0.88 EI1 this way). EI variables are searched
on a log scale. An added mass's position is a variable too (``pos_k``, bounded inside [0, 1]).
The starting racket by default is the paper's (Kawazoe & Kanda 1997, section 2.2) sampled on the
segments.

Constraints bound derived quantities (:data:`QUANTITIES`): total mass, balance point, swing weight
about 0.10 m, first free-free frequency. Objectives (:data:`OBJECTIVES`, maximised but for the
handle shock's, minimised) average over the impact zone (:mod:`.zone`) and the ball speeds; see
:mod:`.objectives`.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, dataclass, field, replace
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import (
    DEFAULT_BALL_MASS,
    KCB_SPEED_RANGE,
    PAPER_CLAMPED_COR,
    zeta_from_cor,
)
from fem_racket.contact.series import SeriesBallString
from fem_racket.frame.hand import Hand
from fem_racket.frame.masses import DEFAULT_WIDTH, AddedMass, add_masses
from fem_racket.frame.mesh import FrameMesh, frame_mesh
from fem_racket.frame.segments import Frame, Segment
from fem_racket.impact.held_shock import DEFAULT_WINDOW
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
)

__all__ = ["DesignProblem"]


@dataclass(frozen=True, eq=False)
class DesignProblem:
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
        Flexible modes kept per impact (None: the engine's choice by ``tolerance``).
    tolerance : float or None
        COR tolerance of the impact engine (:mod:`fem_racket.impact.engine`; None: every mode).
    hand : Hand
        The hand on the grip for the handle-shock objectives (:mod:`fem_racket.frame.hand`).
    shock_window : float
        Window of the handle-shock measures from the start of contact [s]
        (:mod:`fem_racket.impact.held_shock`).
    ei_stations, rhoa_stations : tuple of float
        Control points x/L of a smooth EI (rhoA) profile (:mod:`.profiles`); empty: one value
        per segment.
    interpolation : {"pchip", "linear"}
        The profiles' interpolant between control points.
    law : ContactLaw or None
        The ball/string law (None: the paper's linear law, K_CB from the closing speed times the
        ``kcb_factor`` entry of p, and ``zeta``); another law's impacts run through the general
        integrator (:func:`fem_racket.impact.general.solve_general`).
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
        self.mesh(self.x_start)  # checks the added masses' positions and widths
        if self.shock:
            check_positive("shock window", self.shock_window, "s")
            # The held racket's exact path (fem_racket.impact.held_modal) is the paper's linear
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
                    f"grip_end = {self.hand.grip_end!r} m is not allowed: must lie on the frame "
                    f"(< {self.length:g} m)"
                )
        if self.swing is not None and self.swing.reference_inertia is None:
            object.__setattr__(self, "swing", replace(self.swing, reference_inertia=self._i0()))

    @property
    def shock(self) -> bool:
        """Whether an objective needs the hand-held racket (:data:`MINIMISED`)."""
        return bool(MINIMISED & set(self.objectives))

    # -- layout -----------------------------------------------------------------------------
    @property
    def n_segments(self) -> int:
        """Number of design segments."""
        return len(self.segment_lengths)

    @property
    def n_ei(self) -> int:
        """Number of EI entries of p (control points or segments)."""
        return len(self.ei_stations) or self.n_segments

    @property
    def n_rhoa(self) -> int:
        """Number of rhoA entries of p (control points or segments)."""
        return len(self.rhoa_stations) or self.n_segments

    @property
    def law_names(self) -> tuple[str, ...]:
        """The contact law's entries at the end of p (see the module docstring)."""
        if self.law is None:
            return ("kcb_factor",)
        if isinstance(self.law, SeriesBallString):
            return ("string_stiffness", "string_cubic")
        return ()

    def law_values(self, x: np.ndarray) -> dict[str, np.ndarray]:
        """The law entries of p for design variables ``x`` (shape (..., n_var)), by name."""
        p = self.parameters(x)
        k = len(self.law_names)
        tail = p[..., p.shape[-1] - k :]
        return {name: tail[..., j] for j, name in enumerate(self.law_names)}

    def design_law(self, x: np.ndarray) -> ContactLaw | None:
        """The contact law of one design ``x`` (1-D): the problem's law with the design's
        string bed (series law), or None for the paper's linear law (its K_CB factor is
        ``law_values(x)["kcb_factor"]``)."""
        if not isinstance(self.law, SeriesBallString):
            return self.law
        values = self.law_values(np.asarray(x, dtype=float))
        return replace(
            self.law,
            string_stiffness=float(values["string_stiffness"]),
            string_cubic=float(values["string_cubic"]),
        )

    @property
    def length(self) -> float:
        """Frame length L [m]."""
        return float(sum(self.segment_lengths))

    @property
    def names(self) -> list[str]:
        """Variable names."""
        return [v.name for v in self.variables]

    @property
    def n_var(self) -> int:
        """Number of design variables."""
        return len(self.variables)

    @property
    def lower(self) -> np.ndarray:
        """Lower bounds [SI]."""
        return np.array([v.low for v in self.variables])

    @property
    def upper(self) -> np.ndarray:
        """Upper bounds [SI]."""
        return np.array([v.high for v in self.variables])

    @property
    def x_start(self) -> np.ndarray:
        """The starting racket's design variables, clipped into the bounds [SI]."""
        x = self.start[[v.index for v in self.variables]]
        return np.clip(x, self.lower, self.upper)

    def to_unit(self, x: np.ndarray) -> np.ndarray:
        """Design variables [SI], shape (..., n_var) -> unit box."""
        x = np.asarray(x, dtype=float)
        return np.stack([v.to_unit(x[..., k]) for k, v in enumerate(self.variables)], -1)

    def from_unit(self, u: np.ndarray) -> np.ndarray:
        """Unit box -> design variables [SI]."""
        u = np.clip(np.asarray(u, dtype=float), 0.0, 1.0)
        return np.stack([v.from_unit(u[..., k]) for k, v in enumerate(self.variables)], -1)

    def parameters(self, x: np.ndarray) -> np.ndarray:
        """Full parameter vector(s) p for design variables ``x`` (shape (..., n_var))."""
        x = np.asarray(x, dtype=float)
        p = np.broadcast_to(self.start, x.shape[:-1] + self.start.shape).copy()
        n, r = self.n_ei, self.n_rhoa
        for k, v in enumerate(self.variables):
            if v.name == "ei":
                p[..., :n] = x[..., k, None] * self.start[:n] / self.start[0]
            elif v.name == "rhoa":
                p[..., n : n + r] = x[..., k, None] * self.start[n : n + r] / self.start[n]
            else:
                p[..., v.index] = x[..., k]
        return p

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

    def stiffness(self, x: np.ndarray) -> np.ndarray:
        """EI_1 of each design [N m^2] (priced by ``stiffness_cost``)."""
        return self.parameters(x)[..., 0]

    def _i0(self) -> float:
        q = mass_quantities(self.mesh(self.x_start), self.swing.pivot)
        return float(q["inertia_pivot"])

    def describe(self) -> dict[str, Any]:
        """A JSON-able description (provenance, history files)."""
        return {
            "segment_lengths_m": list(self.segment_lengths),
            "start": self.start.tolist(),
            "variables": [
                {"name": v.name, "low": v.low, "high": v.high, "unit": v.unit, "log": v.log}
                for v in self.variables
            ],
            "mass_positions_x_over_l": list(self.mass_positions),
            "mass_width_m": self.mass_width,
            "zone": {
                "description": self.zone.description,
                "positions_x_over_l": self.zone.positions.tolist(),
                "weights": self.zone.weights.tolist(),
            },
            "speeds_m_s": list(self.speeds),
            "swing": None
            if self.swing is None
            else {
                "head_speed_m_s": self.swing.head_speed,
                "reference_x_over_l": self.swing.reference,
                "pivot_m": self.swing.pivot,
                "exponent": self.swing.exponent,
                "reference_inertia_kg_m2": self.swing.reference_inertia,
            },
            "constraints": [
                {"name": c.name, "low": c.low, "high": c.high, "tolerance": c.tolerance}
                for c in self.constraints
            ],
            "objectives": list(self.objectives),
            "link_ei": self.link_ei,
            "link_rhoa": self.link_rhoa,
            "stiffness_cost_per_n_m2": self.stiffness_cost,
            "region_x_over_l": self.region.tolist(),
            "power_fraction": self.power_fraction,
            "ball_mass_kg": self.ball_mass,
            "zeta": self.zeta,
            "elements": self.elements,
            "modes": "by tolerance" if self.modes is None else self.modes,
            "tolerance": self.tolerance,
            **(
                {
                    "ei_stations_x_over_l": list(self.ei_stations),
                    "rhoa_stations_x_over_l": list(self.rhoa_stations),
                    "interpolation": self.interpolation,
                }
                if self.ei_stations or self.rhoa_stations
                else {}
            ),
            **({} if self.law is None else {"law": self.law.describe()}),
        } | ({"hand": asdict(self.hand), "shock_window_s": self.shock_window} if self.shock else {})

    @property
    def digest(self) -> str:
        """SHA-256 of :meth:`describe` (a history file belongs to one problem)."""
        text = json.dumps(self.describe(), sort_keys=True, default=str)
        return hashlib.sha256(text.encode()).hexdigest()
