"""What the frame is made of: uniform segments, the stepped beam, the paper's presets.

All quantities in SI. Positions along the frame are measured from the grip end. The paper's
standard racket (Kawazoe & Kanda 1997, section 2.2) is a free-free stepped beam, L = 680 mm with
a step at 204 mm: EI1 = 146 N m^2, EI2 = 0.88 EI1, rhoA1 = 0.696 kg/m, rhoA2 = 0.458 kg/m.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace

import numpy as np

from fem_racket.frame.constants import PAPER_EI1, RIGID_EI1
from fem_racket.frame.rigidity import Rigidity
from fem_racket.validation import InputError, check_positive, check_range, show

__all__ = [
    "BENDING",
    "EI_RANGE",
    "GJ_RANGE",
    "EI_RATIO",
    "PAPER_EI1",
    "RHOA1",
    "RHOA2",
    "RIGID_EI1",
    "TORSION",
    "Frame",
    "Segment",
    "STANDARD_TORSION",
    "TorsionSegment",
    "check_ei_factor",
    "check_stiffness",
    "standard_ei1_range",
    "rigid_frame",
    "standard_frame",
]

#: EI2 / EI1 of the paper's stepped beam (section 2.2).
EI_RATIO = 0.88
#: Mass per length of the paper's grip and top sides [kg/m] (section 2.2).
RHOA1, RHOA2 = 0.696, 0.458
#: Allowed EI / rhoA [m^4/s^2] of every segment or cell (it sets the frequencies: omega ~
#: sqrt(EI / rhoA) / L^2; the paper's racket has 210). Above 1e9 the frame is rigid to 1e-10 in
#: COR while the exact path's sum rules lose accuracy (sweep and simulate differed by 2e-9 at
#: 7e6 x the paper's EI, 4e-8 at 7e11 x, and at 7e17 x the closed form is ill-conditioned);
#: 1e-6 is a frame limp as a string (COR -0.778, equal in every path).
EI_RANGE = (1e-6, 1e9)
#: Allowed GJ / rhoIp [m^2/s^2] of every torsion segment or cell (the square of the torsion wave
#: speed; the standard racket's head has 6.6e4, its handle 7.9e5). 1e15 is rigid to ~1e-9 in
#: e_A off axis; 1e-3 is limp.
GJ_RANGE = (1e-3, 1e15)


#: Bending: EI over rhoA.
BENDING = Rigidity("EI", "rhoA", "kg/m", "m^4/s^2", EI_RANGE)
#: Torsion: GJ over rhoIp.
TORSION = Rigidity("GJ", "rhoIp", "kg m", "m^2/s^2", GJ_RANGE)


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
        BENDING.check_piece(self)


@dataclass(frozen=True)
class TorsionSegment:
    """A uniform piece of the frame in torsion about its long axis (St Venant).

    Parameters
    ----------
    length : float
        Segment length [m].
    GJ : float
        Torsional rigidity [N m^2].
    rhoIp : float
        Polar mass moment per unit length about the long axis [kg m].
    """

    length: float
    GJ: float
    rhoIp: float

    def __post_init__(self) -> None:
        TORSION.check_piece(self)


@dataclass(frozen=True)
class Frame:
    """A free-free stepped beam: segments listed from the grip end to the tip.

    Parameters
    ----------
    segments : tuple of Segment
        At least one segment.
    torsion : tuple of TorsionSegment, optional
        The frame in torsion, grip end first, over the same length (its steps need not be the
        bending steps); None: no torsion data (impacts on the long axis only).
    """

    segments: tuple[Segment, ...]
    torsion: tuple[TorsionSegment, ...] | None = None

    def __post_init__(self) -> None:
        segments = _pieces("segments", self.segments, Segment)
        if not segments:
            raise InputError("segments = () is not allowed: must hold at least one Segment")
        object.__setattr__(self, "segments", segments)
        if self.torsion is not None:
            torsion = _pieces("torsion", self.torsion, TorsionSegment)
            total = float(sum(s.length for s in torsion))
            if not torsion or abs(total - self.length) > 1e-9 * self.length:
                raise InputError(
                    f"torsion segments' length = {total:g} m is not allowed: must equal the "
                    f"frame's {self.length:g} m"
                )
            object.__setattr__(self, "torsion", torsion)

    @property
    def length(self) -> float:
        """Total length L [m]."""
        return float(sum(s.length for s in self.segments))

    @property
    def steps(self) -> np.ndarray:
        """Coordinates of the segment boundaries including both ends [m]."""
        return _boundaries(self.segments)

    def scaled(self, ei_factor: float = 1.0, rhoa_factor: float = 1.0) -> Frame:
        """Return a frame with every segment's EI and rhoA (and rhoIp) multiplied by the given
        factors."""
        check_positive("ei_factor", ei_factor)
        check_positive("rhoa_factor", rhoa_factor)
        check_ei_factor(ei_factor, [s.EI / s.rhoA for s in self.segments])
        seg = tuple(
            replace(s, EI=s.EI * ei_factor, rhoA=s.rhoA * rhoa_factor) for s in self.segments
        )
        torsion = None
        if self.torsion is not None:  # the same material, denser: rhoIp scales as rhoA
            torsion = tuple(replace(s, rhoIp=s.rhoIp * rhoa_factor) for s in self.torsion)
        return Frame(seg, torsion)

    @property
    def torsion_steps(self) -> np.ndarray:
        """Coordinates of the torsion segments' boundaries including both ends [m]."""
        if self.torsion is None:
            raise InputError("torsion: this frame has none (no GJ, rhoIp)")
        return _boundaries(self.torsion)


def _pieces(name: str, items: Iterable[object], kind: type) -> tuple:
    """``items`` as a tuple, or a one-line :class:`InputError` naming the first that is not a
    ``kind``."""
    pieces = tuple(items)
    for piece in pieces:
        if not isinstance(piece, kind):
            raise InputError(f"{name} item {show(piece)} is not allowed: must be a {kind.__name__}")
    return pieces


def _boundaries(pieces: tuple[Segment, ...] | tuple[TorsionSegment, ...]) -> np.ndarray:
    """Coordinates of the pieces' boundaries including both ends [m]."""
    return np.concatenate([[0.0], np.cumsum([s.length for s in pieces])])


def check_stiffness(name: str, ei: float, rhoa: float) -> float:
    """Return ``ei`` [N m^2] if EI / rhoA lies in EI_RANGE, else raise naming ``name``."""
    return BENDING.check(name, ei, rhoa)


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


#: The standard racket in torsion: grip (handle), throat, head ring. The paper gives no torsion
#: data; these are assumptions chosen so that the polar moment is 17.5 kg cm^2 (measured
#: twistweights 15.2 and 19.7 kg cm^2: Rogowski et al. 2014, PLoS ONE 9(8) e104785) and the first
#: free-free torsion frequency 380 Hz (rackets: typically 300-450 Hz, DESIGN section 10), with
#: the polar mass in the head: rhoIp = rhoA r^2 with r = 14 mm for the handle (0.696 kg/m); the
#: throat's arms spread from the shaft to the head (mean rhoIp 1.0e-3 kg m); the head ring (the
#: 0.34 m from 0.5 L to the tip) carries the rest, 4.66e-3 kg m, about its mass (0.458 kg/m,
#: 0.156 kg) at r ~ 0.1 m, i.e. a ring ~0.25 m wide. GJ of the handle: a carbon tube with
#: G/E = 0.385 (quasi-isotropic, nu = 0.3) has GJ = 2 (G/E) EI = 0.77 x 146 N m^2. Throat and
#: head: an equivalent GJ of 390 N m^2 (the ring's sides bending out of plane, joined by the
#: strings), which puts the first free-free torsion mode at 380 Hz (exact: 380.3 Hz).
STANDARD_TORSION = (
    TorsionSegment(0.204, 112.0, 1.4e-4),
    TorsionSegment(0.136, 390.0, 1.0e-3),
    TorsionSegment(0.340, 390.0, 4.66e-3),
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
        Grip side 0.204 m with rhoA1 = 0.696 kg/m, top side 0.476 m with rhoA2 = 0.458 kg/m;
        in torsion :data:`STANDARD_TORSION` (assumptions, see there).
    """
    if ei2 is None:
        ei1 = check_range("ei1", ei1, *standard_ei1_range(), unit="N m^2")
        ei2 = EI_RATIO * ei1
    else:
        ei1 = check_stiffness("ei1", check_positive("ei1", ei1, "N m^2"), RHOA1)
        ei2 = check_stiffness("ei2", check_positive("ei2", ei2, "N m^2"), RHOA2)
    return Frame((Segment(0.204, ei1, RHOA1), Segment(0.476, ei2, RHOA2)), STANDARD_TORSION)


def rigid_frame() -> Frame:
    """The paper's 'rigid' frame: EI1 = 9999 N m^2, EI2 = 0.88 EI1, same masses."""
    return standard_frame(RIGID_EI1)
