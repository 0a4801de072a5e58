"""The options of a power map (:func:`fem_racket.studies.racket_map.racket_map`): the racket's
setting (:class:`MapSetup`), how the racket is played over the map (:class:`MapPlay`: the ball
speed, the swing and the grid; also the base of
:class:`fem_racket.studies.compare.Play`) and how each point is struck and solved
(:class:`MapImpact`).

The map functions take them as keywords, checked with a "did you mean"
(:func:`fem_racket.studies.options.take`).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import Any

import numpy as np

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import DEFAULT_MODES, FrameModel
from fem_racket.impact.constants import DEFAULT_REFERENCE
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.swing import Swing
from fem_racket.studies.map_defaults import MAP_POSITIONS as DEFAULT_POSITIONS
from fem_racket.studies.map_defaults import MAP_POWER_FRACTION as DEFAULT_POWER_FRACTION
from fem_racket.validation import InputError, check_range, show

__all__ = [
    "DEFAULT_POSITIONS",
    "DEFAULT_POWER_FRACTION",
    "MapImpact",
    "MapPlay",
    "MAX_MAP_POINTS",
    "MapSetup",
    "check_at_rest",
    "check_map_points",
    "map_grid",
    "map_model",
]

#: Cells a Frame is meshed with (the paper's 20).
DEFAULT_ELEMENTS = 20
#: Most impact points of one map (positions x offsets): the batched engine holds a few arrays of
#: (points x modes) doubles, so 10^7 points need several GB (a 2.98 GiB array was refused by
#: numpy at 10^7 positions). Real maps have 200 (the default) to a few 10^3 points (a 41 x 41
#: face): 10^5 is well beyond them and about 100 MB an array.
MAX_MAP_POINTS = 100_000


def check_map_points(positions: int, offsets: int = 1) -> None:
    """Refuse a map of ``positions`` x ``offsets`` points (counts, known before any array is
    made) over :data:`MAX_MAP_POINTS`, naming the option that makes it too large."""
    if positions * offsets <= MAX_MAP_POINTS:
        return
    if offsets == 1:
        what = f"positions = {positions} values"
    elif positions >= offsets:
        what = f"positions = {positions} values with offsets = {offsets}"
    else:
        what = f"offsets = {offsets} values with positions = {positions}"
    name = "positions" if offsets == 1 or positions >= offsets else "offsets"
    raise InputError(
        f"{what} is not allowed: a map takes at most {MAX_MAP_POINTS} points (positions x "
        f"offsets = {positions * offsets})",
        parameter=name,
        value=positions if name == "positions" else offsets,  # the count refused
    )


def check_at_rest(racket_speed: float, reference: Any, pivot: float | None = None) -> None:
    """Refuse a swing's ``reference`` point (x/L; a sweep's values too) or ``pivot`` [m], each
    given (not None) at any value, without a swing (``racket_speed`` 0): the racket at rest
    would drop them. Give None for what was not given (the maps' centre of percussion takes
    the pivot at rest: they leave it out)."""
    if racket_speed != 0.0:
        return
    for name, value, unit in (("reference", reference, "x/L"), ("pivot", pivot, "m")):
        if value is not None:
            value = np.asarray(value).tolist()  # a number, or a sweep's values
            raise InputError(
                f"{name} = {show(value)} {unit} is not allowed without a swing: give "
                "racket_speed (--racket-speed)",
                parameter=name,
                value=value,
            )


@dataclass(frozen=True)
class MapImpact:
    """How each point is struck and solved.

    Attributes
    ----------
    ball_mass, kcb, zeta, separation, modes, tolerance
        As for :func:`fem_racket.simulate` (``tolerance``: the batched engine's COR tolerance,
        or the general integrator's under a law).
    law : ContactLaw, str or None
        A contact law other than the paper's (the general integrator; it takes neither
        ``kcb`` nor ``zeta``).
    kcb_factor : float
        Factor on the linear law's K_CB (a stiffer or softer string bed).
    """

    ball_mass: float = DEFAULT_BALL_MASS
    kcb: float | None = None
    zeta: float | None = None
    separation: str = "displacement"
    modes: int | None = DEFAULT_MODES
    tolerance: float | None = DEFAULT_TOLERANCE
    law: Any = None
    kcb_factor: float = 1.0


@dataclass(frozen=True)
class MapPlay:
    """How the racket is played over a map: the ball speed, the swing and the grid.

    Attributes
    ----------
    speed : float
        Incoming ball speed v_in [m/s].
    racket_speed, reference, pivot
        The swing: speed [m/s] of the point ``reference`` (x/L; not given: None at rest, 0.75
        with a swing) towards the ball, turning about ``pivot`` [m from the butt] or
        translating when None (:meth:`swing`). A reference given, at any value, is refused at
        rest.
    positions : array of float or None
        Impact points x/L; :data:`DEFAULT_POSITIONS` when None.
    """

    speed: float = 20.0
    racket_speed: float = 0.0
    reference: float | None = None
    pivot: float | None = None
    positions: Any = None

    def __post_init__(self) -> None:
        check_at_rest(self.racket_speed, self.reference)  # the pivot sets the centre of percussion
        if self.reference is None and self.racket_speed != 0.0:  # a swing's point: its default
            object.__setattr__(self, "reference", DEFAULT_REFERENCE)

    def swing(self, length: float) -> Swing:
        """The swing of a racket of length ``length`` [m]
        (:meth:`fem_racket.impact.swing.Swing.from_speed`)."""
        return Swing.from_speed(
            self.racket_speed, length, reference=self.reference, pivot=self.pivot
        )

    def keywords(self) -> dict[str, Any]:
        """The fields of :class:`MapPlay`, by name, as the map functions take them."""
        return {f.name: getattr(self, f.name) for f in fields(MapPlay)}


def map_grid(positions: Any) -> np.ndarray:
    """The map's impact points x/L: :data:`DEFAULT_POSITIONS` when None, else at least 3
    increasing points in [0, 1] (at most :data:`MAX_MAP_POINTS`, counted first); text as the
    command line and a sweep's ``position`` take it (a comma list or ``start:stop:num``,
    :func:`~fem_racket.studies.grid_values.as_values`)."""
    from fem_racket.studies.grid_values import as_values, value_count

    if positions is None:
        start, stop, num = DEFAULT_POSITIONS
        return np.linspace(start, stop, num)
    check_map_points(value_count(positions))
    given = positions  # as the refusals name it
    if isinstance(positions, str):
        positions = as_values("position", positions)
    try:
        x = np.atleast_1d(np.asarray(positions, dtype=float))
    except (TypeError, ValueError):
        raise InputError(
            f"positions = {show(positions)} is not allowed: must be at least 3 increasing x/L "
            "(numbers, a comma list or start:stop:num)",
            parameter="positions",
            value=given,
        ) from None
    if x.size < 3 or np.any(np.diff(x) <= 0.0):
        raise InputError(
            f"positions = {x.size} values is not allowed: must be at least 3 increasing x/L",
            parameter="positions",
            value=given,  # (a run file's key is named by it)
        )
    for p in (x[0], x[-1]):
        check_range("position", p, 0.0, 1.0, unit="x/L")
    return x


def map_model(frame: Any, elements: int | None) -> FrameModel:
    """The model of ``frame`` (the standard racket when None), a Frame meshed with
    ``elements`` cells (20 when None); ``elements`` refused with a model or a mesh of another
    count (as :meth:`fem_racket.impact.problem.ImpactProblem.build` and ``sweep`` refuse it)."""
    if isinstance(frame, FrameModel):
        if elements is not None:
            raise InputError(
                f"elements = {show(elements)} is not allowed with a FrameModel: it is meshed "
                "already (give a Frame or a FrameMesh to mesh)",
                parameter="elements",
                value=elements,
            )
        return frame
    if isinstance(frame, FrameMesh) and elements not in (None, frame.n_elements):
        raise InputError(
            f"elements = {show(elements)} is not allowed with a mesh: it has "
            f"{frame.n_elements} elements",
            parameter="elements",
            value=elements,
        )
    return FrameModel.build(frame, DEFAULT_ELEMENTS if elements is None else elements)


@dataclass(frozen=True)
class MapSetup:
    """The racket's setting and how it is played over the map.

    Attributes
    ----------
    name : str
        The racket's label in tables and plots.
    play : MapPlay
        Ball speed, swing and grid (given as their own keywords: ``speed``, ``racket_speed``,
        ``reference``, ``pivot``, ``positions``).
    elements : int
        Cells when meshing a Frame.
    power_fraction : float
        The power region is where v_out >= power_fraction x its maximum.
    """

    name: str = "racket"
    play: MapPlay = field(default_factory=MapPlay)
    elements: int = DEFAULT_ELEMENTS
    power_fraction: float = DEFAULT_POWER_FRACTION

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):  # a label of tables, plots and files
            raise InputError(
                f"name = {show(self.name)} is not allowed: must be a string",
                parameter="name",
                value=self.name,
            )
