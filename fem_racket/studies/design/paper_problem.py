"""A design problem on the paper's racket (or any starting frame) split into segments.

``paper_problem(start, VariableOptions(boundaries=..., vary=...))`` resamples the starting racket
onto the segments between the ``boundaries`` x/L (length-weighted means of EI and rhoA over
each), or onto control stations' shares of the frame (:mod:`.profiles`), appends the added
masses and the contact law's string-bed entries to make the starting parameter vector
(:mod:`.layout`), and frees the groups in ``vary`` (:mod:`.variable_groups`).
"""

from __future__ import annotations

from dataclasses import fields as dataclass_fields
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.series import SeriesBallString
from fem_racket.frame.segments import Frame, standard_frame
from fem_racket.studies.design.options import DesignOptions, VariableOptions, check_names
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.profiles import check_stations, tributary_edges
from fem_racket.studies.design.variable_groups import VARY, design_variables
from fem_racket.validation import InputError, check_choice

__all__ = ["paper_problem"]

#: The DesignProblem fields set here (from the variables, the starting racket and the law).
_FROM_VARIABLES = (
    "segment_lengths",
    "start",
    "variables",
    "mass_positions",
    "mass_width",
    "link_ei",
    "link_rhoa",
    "ei_stations",
    "rhoa_stations",
    "interpolation",
    "law",
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
    start: Frame | None = None,
    variables: VariableOptions | None = None,
    law: ContactLaw | None = None,
    **fields: Any,
) -> DesignProblem:
    """A design problem on the paper's racket (or ``start``), split at the boundaries x/L.

    Parameters
    ----------
    start : Frame, optional
        The starting racket; the paper's standard racket when None.
    variables : VariableOptions, optional
        The segments, the groups varied and their bounds (:class:`.options.VariableOptions`;
        its defaults when None): the default boundaries split the paper's step at 0.3 L and
        the top side into three equal parts (4 segments: 8 variables varying EI and rhoA).
        Control stations (``ei_points``, ``rhoa_points``) start from the starting racket's
        means over each station's share of the frame (between the midpoints to its
        neighbours); added masses start at ``mass_start``; position bounds are narrowed to
        keep each strip on the frame (a centre within half a width of an end acts as if at
        that limit).
    law : ContactLaw, optional
        The ball/string law (the paper's linear one when None).
    **fields
        Other :class:`DesignProblem` fields (zone, speeds, swing, constraints, objectives,
        ...); an unknown name is refused naming the nearest.
    """
    v = VariableOptions() if variables is None else variables
    DesignOptions(variables=v, law=law)  # refuses what the variables would not use
    known = [f.name for f in dataclass_fields(DesignProblem) if f.name not in _FROM_VARIABLES]
    check_names("paper_problem", fields, known)
    for name in v.vary:
        check_choice("vary", name, VARY)
    frame = standard_frame() if start is None else start
    length = frame.length
    b = np.asarray(v.boundaries, dtype=float)
    if b.size and (np.any(np.diff(b) <= 0.0) or b[0] <= 0.0 or b[-1] >= 1.0):
        raise InputError(
            f"boundaries = {list(v.boundaries)} x/L is not allowed: must increase within (0, 1)"
        )
    edges = np.concatenate([[0.0], b, [1.0]]) * length
    ei, ra = _resample(frame, edges)
    if v.ei_points:
        ei = _resample(frame, tributary_edges(check_stations("ei_points", v.ei_points)) * length)[0]
    if v.rhoa_points:
        share = tributary_edges(check_stations("rhoa_points", v.rhoa_points)) * length
        ra = _resample(frame, share)[1]
    a = len(v.mass_positions)
    if law is None:
        law_start = [1.0]
    elif isinstance(law, SeriesBallString):
        law_start = [float(law.string_stiffness), float(law.string_cubic)]
    else:
        law_start = []
    p0 = np.concatenate(
        [
            ei,
            ra,
            np.full(a, float(v.mass_start)),
            np.asarray(v.mass_positions, dtype=float),
            law_start,
        ]
    )
    layout = (ei.size, ra.size, a)
    return DesignProblem(
        segment_lengths=tuple(np.diff(edges)),
        start=p0,
        variables=tuple(design_variables(v, layout, length, law, law_start)),
        mass_positions=tuple(v.mass_positions),
        mass_width=v.mass_width,
        link_ei=v.link_ei,
        link_rhoa=v.link_rhoa,
        ei_stations=tuple(v.ei_points),
        rhoa_stations=tuple(v.rhoa_points),
        interpolation=v.interpolation,
        law=law,
        **fields,
    )
