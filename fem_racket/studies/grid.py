"""Sweep grids: the full sweep specification and its cases.

Each parameter is fixed or swept (:mod:`fem_racket.studies.grid_values`, whose names this
module also exports). The dimensions are named after the options and
ordered as in :data:`PARAMETERS`, then the contact law's (:data:`LAW_PARAMETERS`, only those
of the sweep's law family: :mod:`fem_racket.studies.law_axes`); the flat case index runs over
them in C order (last fastest).
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.contact.presets import check_linear_options
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.segments import (
    PAPER_EI1,
    Frame,
    standard_frame,
)
from fem_racket.impact.constants import DEFAULT_REFERENCE
from fem_racket.impact.ode.integrators import check_solver_settings
from fem_racket.impact.reduction import check_tolerance
from fem_racket.impact.settings import UNSET, SolverOptions
from fem_racket.impact.solvers import auto_pick, make_solver
from fem_racket.impact.system import SEPARATION_EVENTS
from fem_racket.strings.bed import StringBed
from fem_racket.studies.grid_checks import (
    check_incidences,
    check_offsets,
    check_rigidity,
    check_swings,
)
from fem_racket.studies.grid_values import (
    LAW_PARAMETERS,
    OPTIONAL,
    PARAMETERS,
    Parameter,
    as_values,
    parameter,
    parse_values,
    value_count,
)
from fem_racket.studies.law_axes import case_law, check_law_grid, sweep_law_values
from fem_racket.studies.limits import check_grid_size
from fem_racket.studies.sweep_options import SOLVING_DEFAULTS, SweepSolving
from fem_racket.studies.sweep_physics import STRING_AXES, check_physics, given
from fem_racket.validation import (
    InputError,
    check_choice,
    check_positive,
    show,
)

__all__ = [
    "LAW_PARAMETERS",
    "PARAMETERS",
    "Parameter",
    "SweepSpec",
    "as_values",
    "parameter",
    "parse_values",
]


def _frame_description(frame: Frame | FrameMesh | None) -> dict[str, Any]:
    if frame is None:
        return {"frame": "standard stepped beam (Kawazoe & Kanda 1997)"}
    if isinstance(frame, Frame):
        segs = [[s.length, s.EI, s.rhoA] for s in frame.segments]
        return {"frame": "segments [length m, EI N m^2, rhoA kg/m]: " + json.dumps(segs)}
    if isinstance(frame, FrameMesh):
        h = hashlib.sha256()
        torsion = (frame.GJ, frame.rhoIp) if frame.has_torsion else ()
        for arr in (frame.points, frame.EI, frame.rhoA, *torsion):
            h.update(np.ascontiguousarray(arr, dtype=float).tobytes())
        return {"frame": f"mesh of {frame.n_elements} elements, sha256 {h.hexdigest()[:16]}"}
    raise InputError(f"frame = {show(frame)} is not allowed: must be a Frame, a FrameMesh or None")


@dataclass(frozen=True, eq=False)
class SweepSpec(SweepSolving):
    """Everything that determines a sweep's results: its grid and frame, solved as the
    :class:`~fem_racket.studies.sweep_options.SweepSolving` fields it inherits say (checked, the
    law made, the solver picked: :meth:`build`).

    Attributes
    ----------
    values : dict
        Parameter name -> fixed value (number, or None for the default law) or a 1-D array;
        with a law family, its parameters too (:data:`LAW_PARAMETERS`).
    frame : Frame, FrameMesh or None
        The racket (the standard one when None, whose EI1 is ``ei1``).
    ei2 : float or None
        Fixed top-side rigidity of the standard frame [N m^2] (0.88 EI1 when None).
    solver, separation, basis, modes, rtol, atol
        As for :func:`fem_racket.simulate`.
    law : ContactLaw or None
        A contact law other than the paper's (on a string bed the ball's own), its parameters
        overridden case by case by those in ``values`` (:meth:`case_law`); None: the paper's
        linear law from ``kcb`` and ``zeta``. ``auto`` picks as simulate's (``auto_pick``).
    tolerance : float or None
        COR tolerance of the batched engine (exact solver); None: every mode.
    peak_force : bool
        Whether the peak force is computed (a result variable).
    given : frozenset of str
        The options and parameters given (at any value: refused where simulate refuses them).
    """

    values: dict[str, Any] = field(kw_only=True)
    frame: Frame | FrameMesh | None = field(default=None, kw_only=True)
    given: frozenset[str] = field(default=frozenset(), kw_only=True)

    # a spec holds a dict of arrays: equal only to itself (not by SweepSolving's fields)
    __eq__ = object.__eq__
    __hash__ = object.__hash__

    @classmethod
    def build(cls, frame: Frame | FrameMesh | None = None, **kwargs: Any) -> SweepSpec:
        """Validated spec from user values (numbers, strings, sequences); see
        :func:`fem_racket.sweep` for the keywords (the law's parameters by their names in
        :data:`LAW_PARAMETERS`)."""
        raw = {name: kwargs.pop(name, None) for name in PARAMETERS}
        told = frozenset(n for n, v in raw.items() if v is not None)  # given, at any value
        told |= {n for n in SOLVING_DEFAULTS if kwargs.get(n, UNSET) is not UNSET}
        kwargs.update({n: d for n, d in SOLVING_DEFAULTS.items() if n not in told})
        check_linear_options(kwargs.get("law"), kcb=raw["kcb"], zeta=raw["zeta"])
        law_given = {name: kwargs.pop(name) for name in list(kwargs) if name in LAW_PARAMETERS}
        # the grid's size from the counts alone, before any value is made (20:40:10000000)
        counts = {n: value_count(v) for n, v in {**raw, **law_given}.items()}
        swept = {n: c for n, c in counts.items() if c > 1}
        check_grid_size(list(swept.values()), list(swept))
        values = {name: as_values(name, value) for name, value in raw.items()}
        for name, value in sweep_law_values(kwargs.get("law"), law_given).items():
            values[name] = as_values(name, value)
        check_law_grid(kwargs.get("law"), values)  # every combination, before any work
        defaults = {"position": 0.75, "offset": 0.0, "speed": 20.0, "ei_factor": 1.0}
        defaults["elements"] = 20
        defaults.update(racket_speed=0.0, reference=DEFAULT_REFERENCE)
        defaults["ball_mass"] = DEFAULT_BALL_MASS
        for name, default in defaults.items():
            values[name] = default if values[name] is None else values[name]
        ei2 = kwargs.pop("ei2", None)
        ei2 = None if ei2 is None else check_positive("ei2", ei2, "N m^2")
        _frame_description(frame)
        if frame is None:
            values["ei1"] = PAPER_EI1 if values["ei1"] is None else values["ei1"]
        else:
            if values["ei1"] is not None or ei2 is not None:
                raise InputError(
                    "ei1 and ei2 are not allowed with a custom frame: use ei_factor to scale its EI"
                )
            if isinstance(frame, FrameMesh):
                cells = raw["elements"]
                if cells is not None and (
                    np.ndim(values["elements"]) == 1 or values["elements"] != frame.n_elements
                ):
                    raise InputError(
                        f"elements = {show(cells)} is not allowed with a mesh: it has "
                        f"{frame.n_elements} elements"
                    )
                values["elements"] = frame.n_elements
        if kwargs.get("solver", "auto") == "auto":  # simulate's pick (no bed of a sweep stretches)
            bed = StringBed() if given(values, STRING_AXES) else None
            kwargs["solver"] = auto_pick(kwargs.get("law"), bed)
        spec = cls(values=values, frame=frame, ei2=ei2, given=told, **kwargs)
        # no list of solvers: the solver refuses (make_solver, then cases.check_first_case)
        check_choice("separation", spec.separation, SEPARATION_EVENTS)
        object.__setattr__(spec, "tolerance", check_tolerance(spec.tolerance))
        make_solver(spec.solver, **spec.solver_options())  # the options simulate's solver takes
        check_solver_settings(
            spec.solver, spec.basis, int(np.max(values["elements"])), spec.rtol, spec.atol
        )
        check_rigidity(spec)
        frame_length = float((frame if frame is not None else standard_frame()).length)
        check_physics(values, frame_length)
        check_swings(spec)
        check_incidences(spec)
        check_offsets(spec)
        check_grid_size(spec.shape, spec.dims)
        if not isinstance(spec.peak_force, bool):
            raise InputError(f"peak_force = {spec.peak_force!r} is not allowed: must be a bool")
        return spec

    def solver_options(self) -> dict[str, Any]:
        """The options of the cases' solver that were given (:attr:`given`), by name: the sweep
        makes its solver with them (:func:`fem_racket.impact.solvers.make_solver`), so it
        refuses what simulate refuses, by the same rule."""
        return {n: getattr(self, n) for n in SolverOptions.names() if n in self.given}

    @property
    def problem_separation(self) -> str | None:
        """The separation the cases' problems state: the sweep's under the paper's law; under
        another law only when given (at any value: the problem refuses it, as simulate's)."""
        if self.law is None or "separation" in self.given:
            return self.separation
        return None

    # -- the grid ----------------------------------------------------------------------------
    @cached_property
    def axes(self) -> dict[str, np.ndarray]:
        """Swept parameters -> their values, in dimension order."""
        return {k: v for k, v in self.values.items() if np.ndim(v) == 1}

    @property
    def fixed(self) -> dict[str, Any]:
        """Parameters held fixed -> value (None: the default law)."""
        return {k: v for k, v in self.values.items() if np.ndim(v) == 0}

    @property
    def dims(self) -> tuple[str, ...]:
        """Dimension names."""
        return tuple(self.axes)

    @property
    def shape(self) -> tuple[int, ...]:
        """Grid shape."""
        return tuple(v.size for v in self.axes.values())

    @property
    def size(self) -> int:
        """Number of impacts."""
        return int(np.prod(self.shape, dtype=np.int64))

    def case(self, index: int) -> dict[str, Any]:
        """All parameter values of case ``index`` (flat, C order)."""
        out = dict(self.values)
        if self.axes:
            for (name, vals), i in zip(
                self.axes.items(), np.unravel_index(index, self.shape), strict=True
            ):
                out[name] = vals[i].item()
        return out

    def case_arrays(self, indices: np.ndarray) -> dict[str, Any]:
        """Parameter values of many cases: swept ones as arrays (one entry per index), fixed
        ones as they are (a number, or None for the default law)."""
        out = dict(self.values)
        if self.axes:
            where = np.unravel_index(np.asarray(indices, dtype=np.int64), self.shape)
            for (name, vals), i in zip(self.axes.items(), where, strict=True):
                out[name] = vals[i]
        return out

    def case_law(self, p: dict[str, Any], n: int | None = None) -> Any:
        """The contact law of the case(s) with parameter values ``p`` (:meth:`case` or, with
        ``n`` cases, :meth:`case_arrays`); None for the paper's linear law."""
        return case_law(self.law, p, n)

    # -- identity --------------------------------------------------------------------------
    def describe(self) -> dict[str, Any]:
        """JSON-ready description of everything that determines the results."""
        from fem_racket.version import __version__

        def plain(v: Any) -> Any:
            return v.tolist() if isinstance(v, np.ndarray) else v

        return {  # the string-bed and oblique axes only when given (digests stay as they were)
            "values": {
                k: plain(v) for k, v in self.values.items() if not (k in OPTIONAL and v is None)
            },
            "ei2": self.ei2,
            "frame": self.frame_key,
            "solver": self.solver,
            "separation": self.separation,
            "basis": self.basis,
            "modes": self.modes,
            "rtol": self.rtol,
            "atol": self.atol,
            "tolerance": self.tolerance,
            "peak_force": self.peak_force,
            "version": __version__,
            **({} if self.law is None else {"law": self.law.describe()}),
        }

    @cached_property
    def frame_key(self) -> str:
        """Short description identifying the frame (cache key of its assembly)."""
        return _frame_description(self.frame)["frame"]

    @cached_property
    def digest(self) -> str:
        """SHA-256 of :meth:`describe` (hex): the key of the sweep's checkpoint."""
        text = json.dumps(self.describe(), sort_keys=True, allow_nan=False)
        return hashlib.sha256(text.encode()).hexdigest()


def chunks(indices: Sequence[int] | np.ndarray, size: int) -> list[np.ndarray]:
    """Split ``indices`` into consecutive pieces of at most ``size``."""
    arr = np.asarray(indices, dtype=np.int64)
    return [arr[i : i + size] for i in range(0, arr.size, size)]
