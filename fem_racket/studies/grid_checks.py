"""Whole-grid checks of a sweep: every case valid before any work, so that none fails on its
input mid-sweep (:class:`fem_racket.studies.grid.SweepSpec` calls them when it is built)."""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.frame.head import DEFAULT_HEAD
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.segments import (
    EI_RATIO,
    RHOA1,
    RHOA2,
    Frame,
    check_ei_factor,
    check_stiffness,
    standard_ei1_range,
    standard_frame,
)
from fem_racket.frame.torsion import check_off_axis
from fem_racket.impact.closing import check_kcb_closing, closing_speed
from fem_racket.impact.incidence import Incidence, check_kcb_normal
from fem_racket.impact.swing import Swing, check_racket_speed
from fem_racket.studies.grid_values import STRING_AXES
from fem_racket.studies.map_options import check_at_rest
from fem_racket.studies.sweep_physics import LATERAL_AXES, given
from fem_racket.validation import check_range, show

__all__ = ["check_incidences", "check_offsets", "check_rigidity", "check_swings"]


def check_rigidity(spec: Any) -> None:
    """Every frame of the grid (EI1, EI2 or the custom frame's EI, times ei_factor) with
    EI / rhoA within EI_RANGE, so that no case fails on it mid-sweep."""
    if isinstance(spec.frame, FrameMesh):
        ratio = spec.frame.EI / spec.frame.rhoA
    elif isinstance(spec.frame, Frame):
        ratio = [s.EI / s.rhoA for s in spec.frame.segments]
    else:
        ei1 = np.atleast_1d(spec.values["ei1"])
        if spec.ei2 is None:
            for v in (ei1.min(), ei1.max()):
                check_range("ei1", float(v), *standard_ei1_range(), unit="N m^2")
            ei2 = ei1 * EI_RATIO
        else:
            for v in (ei1.min(), ei1.max()):
                check_stiffness("ei1", float(v), RHOA1)
            ei2 = np.atleast_1d(check_stiffness("ei2", spec.ei2, RHOA2))
        ratio = np.concatenate([ei1 / RHOA1, ei2 / RHOA2])
    factors = np.atleast_1d(spec.values["ei_factor"])
    for f in (float(np.min(factors)), float(np.max(factors))):
        check_ei_factor(f, ratio)


def check_offsets(spec: Any) -> None:
    """Every (position, offset) of the grid on the head outline (or on the axis), and a
    frame with torsion data when any offset, side angle or side spin is not 0 (a ball across
    the face turns the racket about the face normal: its polar moment), so that no case fails
    mid-sweep."""
    y = np.atleast_1d(spec.values["offset"])
    across = [
        n for n in LATERAL_AXES
        if spec.values.get(n) is not None and np.any(np.atleast_1d(spec.values[n]) != 0.0)
    ]  # fmt: skip
    if np.all(y == 0.0) and not across:
        return
    frame = spec.frame if spec.frame is not None else standard_frame()
    name = across[0] if across else "offset"
    values = np.atleast_1d(spec.values[name]).tolist()
    unit = {"offset": " m", "side_angle": " deg", "side_spin": " rpm"}[name]
    given = f"{name} = {show(values[0] if len(values) == 1 else values)}{unit}"
    check_off_axis(frame, given, allowed="sweep it at 0")  # the racket's yaw needs GJ, rhoIp
    if np.all(y == 0.0):
        return
    head = DEFAULT_HEAD.on_frame(float(frame.length))
    for x in np.atleast_1d(spec.values["position"]):
        for v in y:
            head.check(float(x) * head.frame_length_m, float(v))


def check_swings(spec: Any) -> None:
    """Every swing of the grid valid (a racket speed within :data:`MAX_RACKET_SPEED`, no pivot
    at its reference point), closing on the slowest ball at every impact point and, where K_CB
    follows from the closing speed (the paper's law without kcb, no string bed), within the
    paper's K_CB speeds at the fastest: so that no case fails on it mid-sweep (named as the
    racket speed, not as the closing speed it derives)."""
    v = spec.values
    for racket_speed in np.atleast_1d(v["racket_speed"]).tolist():
        check_racket_speed(racket_speed)
    if np.all(np.atleast_1d(v["racket_speed"]) == 0.0):
        # a swing's point without a swing would be dropped (the maps' rule)
        check_at_rest(0.0, v["reference"] if "reference" in spec.given else None, v["pivot"])
        return
    frame = spec.frame if spec.frame is not None else standard_frame()
    length = float(frame.length)
    x = np.atleast_1d(v["position"]) * length
    slowest = float(np.min(v["speed"]))
    pivots = [None] if v["pivot"] is None else np.atleast_1d(v["pivot"]).tolist()
    for speed in np.atleast_1d(v["racket_speed"]).tolist():
        for ref in np.atleast_1d(v["reference"]).tolist():
            for pivot in pivots:
                swing = Swing.from_speed(speed, length, reference=ref, pivot=pivot)
                closing_speed(slowest, float(np.min(swing.speed_at(x))))
                fastest = float(np.max(v["speed"])) + float(np.max(swing.speed_at(x)))
                if _kcb_from_speed(spec):
                    ball = float(np.max(v["speed"]))
                    check_kcb_closing(ball, speed, fastest, "racket_speed")


def check_incidences(spec: Any) -> None:
    """An oblique grid's steepest incidence on the slowest ball keeps the ball's normal speed
    within the paper's K_CB speeds where K_CB follows from it (the paper's law without kcb, no
    string bed, the racket at rest), named as the angle rather than the normal speed it
    derives: so that no case fails on it mid-sweep."""
    v = spec.values
    angles = {
        n: np.abs(np.atleast_1d(v[n])).max()
        for n in ("angle", "side_angle")
        if v.get(n) is not None
    }
    if not angles or not _kcb_from_speed(spec) or np.any(np.atleast_1d(v["racket_speed"]) != 0.0):
        return
    steepest = Incidence(**{n: float(a) for n, a in angles.items()})
    check_kcb_normal(steepest, float(np.min(v["speed"])))


def _kcb_from_speed(spec: Any) -> bool:
    """Whether the cases' K_CB follows from their closing speed: the paper's law without kcb,
    no string bed."""
    v = spec.values
    return spec.law is None and v.get("kcb") is None and not given(v, STRING_AXES)
