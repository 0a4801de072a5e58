"""What the frame is made of: uniform segments, the stepped beam, the paper's presets.

All quantities in SI. Positions along the frame are measured from the grip end. The paper's
standard racket (Kawazoe & Kanda 1997, section 2.2) is a free-free stepped beam, L = 680 mm with
a step at 204 mm: EI1 = 146 N m^2, EI2 = 0.88 EI1, rhoA1 = 0.696 kg/m, rhoA2 = 0.458 kg/m.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from fem_racket.validation import InputError, check_positive, check_range

__all__ = [
    "EI_RANGE",
    "EI_RATIO",
    "PAPER_EI1",
    "RIGID_EI1",
    "Frame",
    "Segment",
    "check_ei_factor",
    "rigid_frame",
    "standard_frame",
]

#: EI2 / EI1 of the paper's stepped beam (section 2.2).
EI_RATIO = 0.88
#: EI1 of the paper's standard racket [N m^2] (section 2.2).
PAPER_EI1 = 146.0
#: EI1 of the paper's "rigid" racket [N m^2] (section 3.1).
RIGID_EI1 = 9999.0
#: Bending rigidities [N m^2] the tool accepts. Above 1e9 (7e6 x the paper's racket) the frame is
#: rigid to 1e-10 in COR while the exact path's sum rules lose accuracy (sweep and simulate differ
#: by 2e-9 at 1e12 and 4e-8 at 1e14, and at 1e20 the closed form is ill-conditioned); 1e-6 is
#: a frame limp as a string (COR -0.778, equal in every path).
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
        object.__setattr__(self, "EI", check_range("EI", self.EI, *EI_RANGE, unit="N m^2"))
        object.__setattr__(self, "rhoA", check_positive("rhoA", self.rhoA, "kg/m"))


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
                raise InputError(f"segments item {seg!r} is not allowed: must be a Segment")
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
        check_ei_factor(ei_factor, [s.EI for s in self.segments])
        return Frame(
            tuple(replace(s, EI=s.EI * ei_factor, rhoA=s.rhoA * rhoa_factor) for s in self.segments)
        )


def check_ei_factor(ei_factor: float, ei: Sequence[float] | np.ndarray) -> float:
    """Return ``ei_factor`` if every rigidity in ``ei`` [N m^2] times it stays in EI_RANGE."""
    f = check_positive("ei_factor", ei_factor)
    low, high = float(np.min(ei)) * f, float(np.max(ei)) * f
    if not (EI_RANGE[0] <= low and high <= EI_RANGE[1]):
        raise InputError(
            f"ei_factor = {ei_factor!r} is not allowed: the scaled EI "
            f"({low:.3g} to {high:.3g} N m^2) must lie in [{EI_RANGE[0]:g}, {EI_RANGE[1]:g}] N m^2"
        )
    return f


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
    ei1 = check_range("ei1", ei1, *EI_RANGE, unit="N m^2")
    ei2 = EI_RATIO * ei1 if ei2 is None else check_range("ei2", ei2, *EI_RANGE, unit="N m^2")
    return Frame((Segment(0.204, ei1, 0.696), Segment(0.476, ei2, 0.458)))


def rigid_frame() -> Frame:
    """The paper's 'rigid' frame: EI1 = 9999 N m^2, EI2 = 0.88 EI1, same masses."""
    return standard_frame(RIGID_EI1)
