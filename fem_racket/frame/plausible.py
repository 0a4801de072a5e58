"""Is this an implement a ball is struck with? Length, mass and stiffness within wide ranges.

A mesh written in millimetres is 1 000 times too long and (with rhoA in kg/m) 1 000 times too
heavy: the paper's racket becomes a 680 m, 342.5 kg beam whose modes are "0.00 Hz", and every
number computed from it is silently meaningless. :func:`check_implement` refuses such a frame
with one line naming the likely unit slip. The ranges are wide enough for every struck
implement (sports' rules and manufacturers' data):

- length :data:`LENGTH_RANGE` 0.1-2.5 m: a table-tennis blade is ~0.16 m long (0.26 m with its
  handle), a tennis racket at most 0.737 m (ITF), a baseball bat at most 1.067 m (MLB), a cricket
  bat at most 0.965 m (MCC Law 5), a golf club at most 1.219 m (R&A), an ice-hockey stick
  ~1.6 m;
- mass :data:`MASS_RANGE` 0.02-3 kg: a badminton racket 0.08 kg, a table-tennis bat ~0.08-0.2 kg,
  a tennis racket 0.25-0.36 kg, a baseball bat 0.9-1.0 kg, a cricket bat 1.1-1.4 kg;
- stiffness: EI / rhoA of every cell within :data:`fem_racket.frame.segments.EI_RANGE` (checked by
  :class:`~fem_racket.frame.mesh.FrameMesh`), and the first free-free bending frequency of a
  uniform beam of this length, mass and mean EI within :data:`FREQUENCY_RANGE` 1 Hz-50 kHz (the
  paper's racket: 122 Hz; EI in N mm^2 taken as N m^2 gives 1 000 times that).

The library accepts any frame (a very heavy one is the clamped limit of the closed-form tests);
the command line and :func:`fem_racket.io.mesh_files.read_mesh` call this check.
"""

from __future__ import annotations

import math

import numpy as np

from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.segments import Frame
from fem_racket.validation import InputError, show

__all__ = [
    "FREQUENCY_RANGE",
    "LENGTH_RANGE",
    "MASS_RANGE",
    "check_fitted_f1",
    "check_implement",
    "mean_ei_frequency",
]

#: Allowed implement length [m].
LENGTH_RANGE = (0.1, 2.5)
#: Allowed implement mass [kg].
MASS_RANGE = (0.02, 3.0)
#: Allowed first free-free bending frequency [Hz] of the uniform beam of the same length, mass
#: and mean EI.
FREQUENCY_RANGE = (1.0, 5e4)
#: beta_1 L of a free-free uniform beam's first bending mode.
_BETA1_L = 4.730040744862704


def _check(where: str, what: str, value: float, rng: tuple[float, float], slip: tuple) -> None:
    """Raise unless ``value`` lies in ``rng``; ``slip`` = (what it would be, slipped unit,
    intended unit, its SI unit): named when the value is 1 to 1 000 times too big."""
    low, high = rng
    if low <= value <= high:
        return
    cause, small, big, unit = slip
    hint = f" ({cause}? {value:.4g} {small} = {value / 1e3:.4g} {big})"
    raise InputError(
        f"{where} {what} = {value:.4g} {unit} is not allowed: must lie in [{low:g}, {high:g}] "
        f"{unit} for a struck implement{hint if high < value <= high * 1e3 else ''}"
    )


def _cells(frame: Frame | FrameMesh) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cell lengths [m], EI [N m^2] and rhoA [kg/m] of a frame or mesh."""
    if isinstance(frame, FrameMesh):
        return np.diff(frame.points), np.asarray(frame.EI), np.asarray(frame.rhoA)
    segs = frame.segments
    return tuple(np.array([getattr(s, k) for s in segs]) for k in ("length", "EI", "rhoA"))


def mean_ei_frequency(frame: Frame | FrameMesh) -> tuple[float, float]:
    """The mean EI [N m^2] of ``frame`` and the first free-free bending frequency [Hz] of the
    uniform beam of its length, mass and that EI (the estimate :func:`check_implement` bounds)."""
    h, ei_cells, rhoa = _cells(frame)
    length = float(np.sum(h))
    mass = float(np.sum(rhoa * h))
    ei = float(np.sum(ei_cells * h) / length)
    return ei, _BETA1_L**2 / (2.0 * math.pi * length**2) * math.sqrt(ei * length / mass)


def _digits(value: float, rounding) -> float:
    """``value`` rounded to 4 significant digits by ``rounding`` (math.ceil or math.floor)."""
    step = 10.0 ** (math.floor(math.log10(value)) - 3)
    return rounding(value / step) * step


def check_fitted_f1(f1: float, frame: Frame | FrameMesh) -> None:
    """Refuse, naming ``f1`` [Hz], a target first frequency whose fitted ``frame`` every reader
    of its mesh would refuse (:func:`check_implement`'s frequency estimate outside
    :data:`FREQUENCY_RANGE`), stating the targets allowed for this racket: at fixed mass the
    estimate is proportional to sqrt(EI), so to the fitted f1."""
    estimate = mean_ei_frequency(frame)[1]
    low, high = FREQUENCY_RANGE
    if low <= estimate <= high:
        return
    if estimate < low:  # rounded up (down) to 4 digits, so the bound printed is allowed
        bound = f"at least {_digits(f1 * low / estimate, math.ceil):.4g}"
    else:
        bound = f"at most {_digits(f1 * high / estimate, math.floor):.4g}"
    raise InputError(
        f"f1 = {show(f1)} Hz is not allowed: must be {bound} Hz for this racket (its mean EI "
        f"then gives the uniform beam's first free-free frequency, {estimate:.4g} Hz here, within "
        f"[{low:g}, {high:g}] Hz, the bound every reader of a mesh applies)",
        parameter="f1",
        value=f1,
    )


def check_implement(frame: Frame | FrameMesh, where: str = "frame") -> Frame | FrameMesh:
    """Return ``frame`` if its length, mass and first free-free frequency are those of an
    implement a ball is struck with (see the module docstring); else raise a one-line
    :class:`InputError` naming ``where``, the quantity, the range and the likely unit slip."""
    h, ei_cells, rhoa = _cells(frame)
    length = float(np.sum(h))
    mass = float(np.sum(rhoa * h))
    _check(where, "length", length, LENGTH_RANGE, ("a mesh in millimetres", "mm", "m", "m"))
    _check(where, "mass", mass, MASS_RANGE, ("rhoA in g/m", "g", "kg", "kg"))
    ei, f1 = mean_ei_frequency(frame)
    low, high = FREQUENCY_RANGE
    if not low <= f1 <= high:
        hint = "EI in N mm^2 instead of N m^2?" if f1 > high else "limp as a string"
        raise InputError(
            f"{where} stiffness: mean EI = {ei:.4g} N m^2 gives a first free-free frequency of "
            f"{f1:.4g} Hz, not allowed: must lie in [{low:g}, {high:g}] Hz ({hint})"
        )
    return frame
