"""What the frame is made of: uniform segments, the stepped beam, the paper's presets.

All quantities in SI. Positions along the frame are measured from the grip end. The paper's
standard racket (Kawazoe & Kanda 1997, section 2.2) is a free-free stepped beam, L = 680 mm with
a step at 204 mm: EI1 = 146 N m^2, EI2 = 0.88 EI1, rhoA1 = 0.696 kg/m, rhoA2 = 0.458 kg/m.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from fem_racket.validation import InputError, check_positive, check_range, show

__all__ = [
    "EI_RANGE",
    "EI_RATIO",
    "PAPER_EI1",
    "RHOA1",
    "RHOA2",
    "RIGID_EI1",
    "Frame",
    "Segment",
    "check_ei_factor",
    "check_stiffness",
    "standard_ei1_range",
    "rigid_frame",
    "standard_frame",
]

#: EI2 / EI1 of the paper's stepped beam (section 2.2).
EI_RATIO = 0.88
#: EI1 of the paper's standard racket [N m^2] (section 2.2).
PAPER_EI1 = 146.0
#: Mass per length of the paper's grip and top sides [kg/m] (section 2.2).
RHOA1, RHOA2 = 0.696, 0.458
#: EI1 of the paper's "rigid" racket [N m^2] (section 3.1).
RIGID_EI1 = 9999.0
#: Allowed EI / rhoA [m^4/s^2] of every segment or cell (it sets the frequencies: omega ~
#: sqrt(EI / rhoA) / L^2; the paper's racket has 210). Above 1e9 the frame is rigid to 1e-10 in
#: COR while the exact path's sum rules lose accuracy (sweep and simulate differed by 2e-9 at
#: 7e6 x the paper's EI, 4e-8 at 7e11 x, and at 7e17 x the closed form is ill-conditioned);
#: 1e-6 is a frame limp as a string (COR -0.778, equal in every path).
EI_RANGE = (1e-6, 1e9)


@dataclass(frozen=True)
class Segment:
    """A uniform piece of the frame.

    Parameters
    ----------
    length : float
        Segment length [m].
    EI : float
        Bending rigidity [N m^2].
    rhoA : float
        Mass per unit length [kg/m].
    """

    length: float
    EI: float
    rhoA: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "length", check_positive("segment length", self.length, "m"))
        object.__setattr__(self, "EI", check_positive("EI", self.EI, "N m^2"))
        object.__setattr__(self, "rhoA", check_positive("rhoA", self.rhoA, "kg/m"))
        check_stiffness("EI", self.EI, self.rhoA)


@dataclass(frozen=True)
class Frame:
    """A free-free stepped beam: segments listed from the grip end to the tip.

    Parameters
    ----------
    segments : tuple of Segment
        At least one segment.
    """

    segments: tuple[Segment, ...]

    def __post_init__(self) -> None:
        segments = tuple(self.segments)
        if not segments:
            raise InputError("segments = () is not allowed: must hold at least one Segment")
        for seg in segments:
            if not isinstance(seg, Segment):
                raise InputError(f"segments item {show(seg)} is not allowed: must be a Segment")
        object.__setattr__(self, "segments", segments)

    @property
    def length(self) -> float:
        """Total length L [m]."""
        return float(sum(s.length for s in self.segments))

    @property
    def steps(self) -> np.ndarray:
        """Coordinates of the segment boundaries including both ends [m]."""
        return np.concatenate([[0.0], np.cumsum([s.length for s in self.segments])])

    def scaled(self, ei_factor: float = 1.0, rhoa_factor: float = 1.0) -> Frame:
        """Return a frame with every segment's EI and rhoA multiplied by the given factors."""
        check_positive("ei_factor", ei_factor)
        check_positive("rhoa_factor", rhoa_factor)
        check_ei_factor(ei_factor, [s.EI / s.rhoA for s in self.segments])
        return Frame(
            tuple(replace(s, EI=s.EI * ei_factor, rhoA=s.rhoA * rhoa_factor) for s in self.segments)
        )


def check_stiffness(name: str, ei: float, rhoa: float) -> float:
    """Return ``ei`` [N m^2] if EI / rhoA lies in EI_RANGE, else raise naming ``name``."""
    low, high = EI_RANGE[0] * rhoa, EI_RANGE[1] * rhoa
    if not low <= ei <= high:
        raise InputError(
            f"{name} = {show(ei)} N m^2 is not allowed with rhoA = {rhoa:g} kg/m: must lie in "
            f"[{low:.3g}, {high:.3g}] N m^2 (EI / rhoA in [{EI_RANGE[0]:g}, {EI_RANGE[1]:g}] "
            "m^4/s^2)"
        )
    return ei


def check_ei_factor(ei_factor: float, ei_per_rhoa: Sequence[float] | np.ndarray) -> float:
    """Return ``ei_factor`` if every EI / rhoA [m^4/s^2] in ``ei_per_rhoa`` times it stays in
    EI_RANGE."""
    f = check_positive("ei_factor", ei_factor)
    low, high = float(np.min(ei_per_rhoa)) * f, float(np.max(ei_per_rhoa)) * f
    if not (EI_RANGE[0] <= low and high <= EI_RANGE[1]):
        raise InputError(
            f"ei_factor = {show(ei_factor)} is not allowed: the scaled EI / rhoA ({low:.3g} to "
            f"{high:.3g} m^4/s^2) must lie in [{EI_RANGE[0]:g}, {EI_RANGE[1]:g}] m^4/s^2"
        )
    return f


def standard_ei1_range() -> tuple[float, float]:
    """Allowed EI1 [N m^2] of the standard frame with EI2 = 0.88 EI1 (both sides in EI_RANGE)."""
    return (
        EI_RANGE[0] * max(RHOA1, RHOA2 / EI_RATIO),
        EI_RANGE[1] * min(RHOA1, RHOA2 / EI_RATIO),
    )


def standard_frame(ei1: float = PAPER_EI1, ei2: float | None = None) -> Frame:
    """The paper's stepped beam (section 2.2): L = 680 mm, step at 204 mm from the grip.

    Parameters
    ----------
    ei1 : float
        Grip-side bending rigidity EI1 [N m^2]; the paper's standard racket has 146.
    ei2 : float, optional
        Top-side rigidity EI2 [N m^2]; defaults to 0.88 * EI1 as in the paper (128.5 for 146).

    Returns
    -------
    Frame
        Grip side 0.204 m with rhoA1 = 0.696 kg/m, top side 0.476 m with rhoA2 = 0.458 kg/m.
    """
    if ei2 is None:
        ei1 = check_range("ei1", ei1, *standard_ei1_range(), unit="N m^2")
        ei2 = EI_RATIO * ei1
    else:
        ei1 = check_stiffness("ei1", check_positive("ei1", ei1, "N m^2"), RHOA1)
        ei2 = check_stiffness("ei2", check_positive("ei2", ei2, "N m^2"), RHOA2)
    return Frame((Segment(0.204, ei1, RHOA1), Segment(0.476, ei2, RHOA2)))


def rigid_frame() -> Frame:
    """The paper's 'rigid' frame: EI1 = 9999 N m^2, EI2 = 0.88 EI1, same masses."""
    return standard_frame(RIGID_EI1)
