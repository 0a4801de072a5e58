"""A design problem on the paper's racket (or any starting frame) split into segments.

``paper_problem(boundaries=..., vary=...)`` resamples the starting racket onto the segments between
``boundaries`` x/L (length-weighted means of EI and rhoA over each), or onto control stations'
shares of the frame (:mod:`.profiles`), appends the added masses and the contact law's string-bed
entries to make the starting parameter vector (:mod:`.layout`), and frees the groups in ``vary``
(:mod:`.variable_groups`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.series import SeriesBallString
from fem_racket.frame.masses import DEFAULT_WIDTH
from fem_racket.frame.segments import Frame, standard_frame
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.profiles import check_stations, tributary_edges
from fem_racket.studies.design.variable_groups import VARY, design_variables
from fem_racket.validation import InputError, check_choice

__all__ = ["paper_problem"]


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
    variables = design_variables(
        vary,
        n_ei=n,
        n_rhoa=r,
        n_masses=a,
        link_ei=link_ei,
        link_rhoa=link_rhoa,
        ei_bounds=ei_bounds,
        rhoa_bounds=rhoa_bounds,
        mass_bounds=mass_bounds,
        position_bounds=position_bounds,
        mass_width=kwargs.get("mass_width", DEFAULT_WIDTH) / length,
        law=law,
        law_start=law_start,
        string_bounds=string_bounds,
        cubic_bounds=cubic_bounds,
    )
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
