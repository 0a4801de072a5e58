"""Mesh-refinement study: FE frequencies against the exact beam, COR and contact time.

For each element count the frame is meshed (uniform or graded cells, every section step a node) and
built as :class:`~fem_racket.frame.model.FrameModel` (exact element matrices, free-free modes in
curvature coordinates: round-off ~1e-14 on any accepted mesh, :mod:`fem_racket.frame.curvature`).
The relative errors of the first flexible frequencies against the exact piecewise-uniform beam
(:func:`fem_racket.frame.continuous.free_free_frequencies`) give the observed order of convergence

    p = log(e_i / e_(i+1)) / log(N_(i+1) / N_i)

which is 4 for cubic Hermite beam elements (eigenvalue error O(h^(2(k+1-m))) with k = 3, m = 2).
COR and contact time (the impact of :func:`fem_racket.simulate`, modal basis with the lowest 80
modes) are computed at the chosen impact points on every mesh; their change under refinement and
a Richardson estimate ``c_N + (c_N - c_(N/r)) / (r^4 - 1)`` show how close the default mesh is.
"""

from __future__ import annotations

import logging
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from fem_racket.frame.continuous import free_free_frequencies
from fem_racket.frame.mesh import FrameMesh, frame_mesh, graded_mesh
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame
from fem_racket.impact.simulate import simulate
from fem_racket.progress import progress_bar
from fem_racket.studies.options import take
from fem_racket.studies.refine_meshes import refinable
from fem_racket.studies.refine_options import (
    DEFAULT_ELEMENTS,
    DEFAULT_GRADING,
    DEFAULT_POSITIONS,
    FAMILIES,
    RefineOptions,
    graded,
)
from fem_racket.validation import InputError, check_choice, check_integer, check_range, show

__all__ = [
    "DEFAULT_ELEMENTS",
    "DEFAULT_GRADING",
    "graded",
    "DEFAULT_POSITIONS",
    "FAMILIES",
    "RefineOptions",
    "RefinementStudy",
    "refinement_study",
]

log = logging.getLogger(__name__)

#: Convergence order of cubic Hermite beam elements (frequencies, and COR through them).
THEORETICAL_ORDER = 4.0
#: Observed orders within which a Richardson extrapolation of order 4 is trusted.
ASYMPTOTIC_ORDERS = (3.0, 5.0)


@dataclass(frozen=True, eq=False)
class RefinementStudy:
    """Results of one mesh family over a sequence of element counts.

    Attributes
    ----------
    family : {"uniform", "graded"}
    elements : ndarray, shape (n,)
        Cells of each mesh (requested count, plus one per impact node inserted).
    frequencies_hz : ndarray, shape (n, m)
        Free-free frequencies [Hz] of each mesh.
    exact_frequencies_hz : ndarray, shape (m,)
    positions : ndarray, shape (k,)
        Impact points x/L.
    cor, contact_time_s : ndarray, shape (n, k)
    build_time_s : ndarray, shape (n,)
        Assembly plus modes [s] per mesh; impact_time_s: mean wall time per impact [s].
    impact_settings : dict
        What the impacts used, the same on every mesh (solver, separation, m_B, K_CB, zeta,
        C_CB: :meth:`fem_racket.ImpactResult.settings` less the per-mesh entries).
    impact_modes_used : ndarray of int, shape (n,)
        Flexible modes the impacts kept on each mesh (at most 2 per element).

    In a notebook it shows a one-line summary (``repr``) or a table per mesh
    (``_repr_html_``); :meth:`to_xarray` gives every result as a labelled dataset.
    """

    family: str
    elements: np.ndarray
    frequencies_hz: np.ndarray
    exact_frequencies_hz: np.ndarray
    positions: np.ndarray
    speed: float
    cor: np.ndarray
    contact_time_s: np.ndarray
    build_time_s: np.ndarray
    impact_time_s: np.ndarray
    skipped: tuple[int, ...] = field(default=())
    impact_settings: dict[str, Any] = field(default_factory=dict)
    impact_modes_used: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))

    def __repr__(self) -> str:
        from fem_racket.studies.refine_views import study_repr

        return study_repr(self)

    def _repr_html_(self) -> str:
        from fem_racket.studies.refine_views import study_html

        return study_html(self)

    def to_xarray(self) -> Any:
        """Every result as an ``xarray.Dataset`` over ``elements`` (and ``mode``,
        ``position``), units in each variable's ``units``."""
        from fem_racket.studies.refine_views import study_dataset

        return study_dataset(self)

    @property
    def relative_error(self) -> np.ndarray:
        """(f_FE - f_exact) / f_exact per mesh and mode (positive: FE is an upper bound)."""
        return self.frequencies_hz / self.exact_frequencies_hz - 1.0

    @property
    def observed_order_pairs(self) -> np.ndarray:
        """Order between successive meshes, shape (n - 1, m)."""
        return _orders(self.elements, np.abs(self.relative_error))

    @property
    def observed_order(self) -> np.ndarray:
        """Per mode: the order between the two finest meshes, shape (m,)."""
        pairs = self.observed_order_pairs
        return pairs[-1] if pairs.shape[0] else np.full(self.exact_frequencies_hz.size, np.nan)

    def change(self, values: np.ndarray) -> np.ndarray:
        """|v_i - v_(i-1)| per mesh (NaN for the first), same shape as ``values``."""
        out = np.full(values.shape, np.nan)
        out[1:] = np.abs(np.diff(values, axis=0))
        return out

    def richardson(self, values: np.ndarray) -> np.ndarray:
        """Richardson estimate with order 4 from the two finest meshes, per impact point.

        NaN where the observed order of ``values`` on the three finest meshes is not within
        :data:`ASYMPTOTIC_ORDERS` (3-5): there the values are not in the asymptotic range (or
        are at the truncation floor) and an order-4 extrapolation would mislead.
        """
        if values.shape[0] < 3:
            return np.full(values.shape[1:], np.nan)
        r = self.elements[-1] / self.elements[-2]
        estimate = values[-1] + (values[-1] - values[-2]) / (r**THEORETICAL_ORDER - 1.0)
        p = self.observed_order_of(values)
        low, high = ASYMPTOTIC_ORDERS
        return np.where((p >= low) & (p <= high), estimate, np.nan)

    def observed_order_of(self, values: np.ndarray) -> np.ndarray:
        """Order of convergence of ``values`` from the three finest meshes, per impact point."""
        if values.shape[0] < 3:
            return np.full(values.shape[1:], np.nan)
        d = np.abs(np.diff(values[-3:], axis=0))
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.log(d[0] / d[1]) / np.log(self.elements[-1] / self.elements[-2])

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready results, units in the keys."""
        return {
            "family": self.family,
            "elements": self.elements.tolist(),
            "frequencies_hz": self.frequencies_hz.tolist(),
            "exact_frequencies_hz": self.exact_frequencies_hz.tolist(),
            "relative_error": self.relative_error.tolist(),
            "observed_order": self.observed_order.tolist(),
            "observed_order_pairs": self.observed_order_pairs.tolist(),
            "positions_x_over_l": self.positions.tolist(),
            "speed_m_s": self.speed,
            "cor": self.cor.tolist(),
            "contact_time_s": self.contact_time_s.tolist(),
            "cor_change": self.change(self.cor).tolist(),
            "contact_time_change_s": self.change(self.contact_time_s).tolist(),
            "cor_richardson": self.richardson(self.cor).tolist(),
            "contact_time_richardson_s": self.richardson(self.contact_time_s).tolist(),
            "cor_observed_order": self.observed_order_of(self.cor).tolist(),
            "contact_time_observed_order": self.observed_order_of(self.contact_time_s).tolist(),
            "impact_modes_used": self.impact_modes_used.tolist(),
            "build_time_s": self.build_time_s.tolist(),
            "impact_time_s": self.impact_time_s.tolist(),
            "skipped_elements": list(self.skipped),
        }


def _orders(elements: np.ndarray, errors: np.ndarray) -> np.ndarray:
    ratio = np.log(elements[1:] / elements[:-1])[:, None]
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.log(errors[:-1] / errors[1:]) / ratio


def refinement_study(
    frame: Frame | FrameMesh | None = None,
    elements: Sequence[int] = DEFAULT_ELEMENTS,
    **options: Any,
) -> RefinementStudy:
    """Refine the frame over ``elements`` and compare with the exact solution.

    Parameters
    ----------
    frame : Frame or FrameMesh, optional
        The paper's standard racket when None. A mesh is read as its piecewise-uniform frame
        (one segment per run of equal cells) and re-meshed at each count.
    elements : sequence of int
        Element counts; counts below the number of segments are skipped.
    family : {"uniform", "graded"}
        Uniform cells in each segment, or cells graded towards steps and ends
        (:func:`fem_racket.frame.mesh.graded_mesh`, ratio ``grading``).
    grading : float, optional
        Cell-size ratio of the graded family (default 4; refused with "uniform", at any value).
    n_modes : int
        Flexible frequencies compared with the exact ones.
    positions : sequence of float
        Impact points x/L for COR and contact time.
    speed : float
        Ball speed [m/s].
    impact_nodes : bool
        Put a node at every impact point (otherwise they may fall inside cells).
    impact_modes : int
        Flexible modes in the impact's modal basis (80 by default, as :func:`simulate`).
    progress : bool or None
        A progress bar over the meshes on stderr (None: when stderr is a terminal).
    ball_mass, kcb, zeta, separation
        As for :func:`fem_racket.simulate` (its defaults when None).

    The keywords after ``elements`` are the fields of :class:`RefineOptions`, checked with a
    "did you mean".
    """
    o = take(options, "an option of refinement_study", RefineOptions)[0]
    family, n_modes, positions, speed = o.family, o.n_modes, o.positions, o.speed
    grading, impact_nodes, impact_modes, progress = (
        o.grading, o.impact_nodes, o.impact_modes, o.progress
    )  # fmt: skip
    impact = {k: getattr(o, k) for k in ("ball_mass", "kcb", "zeta", "separation")}
    impact = {k: v for k, v in impact.items() if v is not None}
    check_choice("family", family, FAMILIES)
    if family == "uniform" and grading is not None:  # given, at any value
        why = "only the graded family grades its cells"
        raise InputError(f"grading = {show(grading)} is not allowed with family 'uniform': {why}")
    grading = DEFAULT_GRADING if grading is None else grading
    check_integer("modes", n_modes)
    pos = np.array([check_range("position", p, 0.0, 1.0, unit="x/L") for p in positions])
    if pos.size == 0:
        raise InputError("positions = [] is not allowed: give at least one impact point")
    frame, counts, skipped = refinable(frame, elements)
    exact = free_free_frequencies(frame, n_modes)
    extra = tuple(pos) if impact_nodes else ()
    rows = []
    for n in progress_bar(counts, desc=f"refine ({family})", unit="mesh", enabled=progress):
        if family == "uniform":
            mesh = frame_mesh(frame, int(n), extra)
        else:
            mesh = graded_mesh(frame, int(n), grading, extra)
        t0 = time.perf_counter()
        model = FrameModel.build(mesh)
        modes = model.modes(max(impact_modes, n_modes))
        freq = np.full(n_modes, np.nan)
        k = min(n_modes, modes.omega.size)
        freq[:k] = modes.frequencies[:k]
        build = time.perf_counter() - t0
        t0 = time.perf_counter()
        # The batched engine with every mode kept (tolerance None; ``impact_modes`` of them at
        # most): the study measures the mesh's error, far below the engine's default COR
        # tolerance on fine meshes.
        kw = {"tolerance": None, "modes": impact_modes, **impact}
        res = [simulate(model, position=p, speed=speed, output_step=None, **kw) for p in pos]
        per_impact = (time.perf_counter() - t0) / pos.size
        rows.append((mesh.n_elements, freq, res, build, per_impact))
        log.info("%s %d cells: %.3f s build, %.2f ms/impact", family, n, build, per_impact * 1e3)
    return RefinementStudy(
        family=family,
        elements=np.array([r[0] for r in rows]),
        frequencies_hz=np.array([r[1] for r in rows]),
        exact_frequencies_hz=exact,
        positions=pos,
        speed=float(speed),
        cor=np.array([[x.cor for x in r[2]] for r in rows]),
        contact_time_s=np.array([[x.contact_time for x in r[2]] for r in rows]),
        build_time_s=np.array([r[3] for r in rows]),
        impact_time_s=np.array([r[4] for r in rows]),
        skipped=skipped,
        impact_settings=_common_settings(rows[0][2][0]),
        impact_modes_used=np.array([r[2][0].n_modes for r in rows]),
    )


def _common_settings(result: Any) -> dict[str, Any]:
    """What every impact of the study used, whatever the mesh and the impact point."""
    used = result.settings()
    for key in ("modes", "elements", "position_x_over_l"):
        del used[key]
    return used
