"""A frame's torsion from its twistweight (and, optionally, its first torsion frequency).

The torsion profile is the standard racket's (:data:`~fem_racket.frame.segments.STANDARD_TORSION`:
handle, throat, head ring) stretched to the frame's length, its rhoIp scaled by a so that the
polar moment about the long axis I_p = int rhoIp dx is the twistweight asked for, and its GJ by
a c so that the first free-free torsion frequency (exact, :mod:`fem_racket.frame.torsion_exact`)
is the one asked for (c = 1, the profile's own, when none is). The shape of the profile is an
assumption (the standard racket's, see there); only I_p and the first frequency are fitted.

Reachable: 0 < I_p <= M (W/2)^2 (all of the frame's mass M on the head's widest line, W the head
width); the frequency as far as every GJ / rhoIp stays in GJ_RANGE.
"""

from __future__ import annotations

import math

from fem_racket.frame.head import DEFAULT_HEAD
from fem_racket.frame.segments import (
    GJ_RANGE,
    STANDARD_TORSION,
    Frame,
    TorsionSegment,
)
from fem_racket.frame.torsion_exact import torsion_frequencies
from fem_racket.validation import InputError, check_positive

__all__ = ["fit_torsion"]


def fit_torsion(
    frame: Frame,
    twist_weight: float,
    frequency: float | None = None,
    head_width: float | None = None,
) -> Frame:
    """``frame`` with torsion segments of polar moment ``twist_weight`` [kg m^2] and first
    free-free torsion frequency ``frequency`` [Hz] (the stretched profile's own when None).

    Raises
    ------
    InputError
        One line naming the unreachable value and the reachable range.
    """
    width = DEFAULT_HEAD.width_m if head_width is None else check_positive("head width", head_width)
    length = frame.length
    mass = sum(s.length * s.rhoA for s in frame.segments)
    top = mass * (width / 2.0) ** 2
    ip = check_positive("twist weight", twist_weight, "kg m^2")
    if ip > top:
        raise InputError(
            f"twist weight = {ip * 1e4:.4g} kg cm^2 is not allowed: must lie in (0, "
            f"{top * 1e4:.4g}] kg cm^2 (the frame's {mass:.4g} kg on the head's widest line, "
            f"{width:g} m)"
        )
    stretch = length / sum(s.length for s in STANDARD_TORSION)
    ip0 = sum(s.length * s.rhoIp for s in STANDARD_TORSION) * stretch
    a = ip / ip0
    base = [TorsionSegment(s.length * stretch, s.GJ * a, s.rhoIp * a) for s in STANDARD_TORSION]
    c = 1.0
    if frequency is not None:
        f = check_positive("torsion frequency", frequency, "Hz")
        f0 = float(torsion_frequencies(base, 1)[0])
        ratios = [s.GJ / s.rhoIp for s in base]
        lo = f0 * math.sqrt(GJ_RANGE[0] / min(ratios))
        hi = f0 * math.sqrt(GJ_RANGE[1] / max(ratios))
        if not lo <= f <= hi:
            raise InputError(
                f"torsion frequency = {f:g} Hz is not allowed: must lie in [{lo:.4g}, {hi:.4g}] "
                "Hz (GJ / rhoIp within GJ_RANGE)"
            )
        c = (f / f0) ** 2
    torsion = tuple(TorsionSegment(s.length, s.GJ * c, s.rhoIp) for s in base)
    last = torsion[-1]  # the lengths sum to the frame's exactly
    head = sum(s.length for s in torsion[:-1])
    torsion = (*torsion[:-1], TorsionSegment(length - head, last.GJ, last.rhoIp))
    return Frame(frame.segments, torsion)
