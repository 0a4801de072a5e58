"""A racket from its specification: mass, balance, swing weight and first frequency.

Players and shops describe a racket by its length L, mass M, balance point B (the centre of
gravity, from the butt), swing weight SW (moment of inertia about an axis 0.10 m from the butt,
quoted in kg cm^2) and often the first free-free frequency f1. For a frame with mass per length
rhoA(x) these are moments of one distribution::

    M  = int rhoA dx,   B = int rhoA x dx / M,   SW = int rhoA (x - a)^2 dx   (a = 0.10 m)

so the centre-of-gravity inertia is I_CG = SW - M (B - a)^2 (parallel axes). The mass data are
linear in rhoA: three numbers fix three segment densities.

Parametrisation (a documented assumption, not a measured racket): three uniform segments,
handle 0-0.30 L (the paper's step at 204 mm of 680 mm), throat 0.30-0.60 L and head 0.60-1.0 L.
Their densities rhoA_k solve the 3 x 3 linear system above exactly; each must be at least
:data:`RHOA_FLOOR` of the mean density M/L (a racket has material everywhere), which bounds the
balance and, for a given balance, the swing weight (:func:`spec_bounds`). Bending rigidity keeps
the paper's shape (Kawazoe & Kanda 1997, section 2.2): EI1 on the handle, 0.88 EI1 beyond it;
EI1 is the paper's 146 N m^2 unless f1 is given, in which case it is scaled so the FE model's
first free-free frequency is f1 (frequencies scale with sqrt(EI) at fixed mass, so the scaling
is exact). Fed the paper racket's own figures, the fit returns the paper racket (its two segments
are three segments with equal throat and head densities).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.frame.constants import FIT_ELEMENTS as DEFAULT_ELEMENTS
from fem_racket.frame.constants import KG_CM2
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import FrameModel
from fem_racket.frame.plausible import check_fitted_f1
from fem_racket.frame.segments import EI_RATIO, PAPER_EI1, Frame, Segment
from fem_racket.validation import InputError, check_positive, show

__all__ = [
    "RHOA_FLOOR",
    "SEGMENT_BOUNDS",
    "SWING_AXIS",
    "RacketSpec",
    "balance_point",
    "fit_racket",
    "racket_spec",
    "spec_bounds",
    "swing_weight",
]

#: Axis of the swing weight from the butt [m] (the industry convention).
SWING_AXIS = 0.10
#: Segment boundaries of the fit as x/L (handle | throat | head).
SEGMENT_BOUNDS = (0.0, 0.30, 0.60, 1.0)
#: Smallest fitted segment density, as a fraction of the mean density M/L.
RHOA_FLOOR = 0.05
#: EI of the throat and head relative to the handle (the paper's EI2/EI1).
EI_SHAPE = (1.0, EI_RATIO, EI_RATIO)
#: Handle EI when no f1 is given: the paper's standard racket [N m^2].
DEFAULT_EI1 = PAPER_EI1


def _cells(frame: Frame | FrameMesh | FrameModel) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Start, end [m] and rhoA [kg/m] of every uniform piece."""
    if isinstance(frame, FrameModel):
        frame = frame.mesh
    if isinstance(frame, FrameMesh):
        return frame.points[:-1], frame.points[1:], np.asarray(frame.rhoA)
    if isinstance(frame, Frame):
        s = frame.steps
        return s[:-1], s[1:], np.array([seg.rhoA for seg in frame.segments])
    raise InputError(f"frame = {frame!r} is not allowed: must be a Frame, FrameMesh or FrameModel")


def _moments(a: np.ndarray, b: np.ndarray, axis: float) -> np.ndarray:
    """Rows: int dx, int (x - axis) dx, int (x - axis)^2 dx over each piece [a, b]."""
    a, b = a - axis, b - axis
    return np.vstack([b - a, (b**2 - a**2) / 2.0, (b**3 - a**3) / 3.0])


def balance_point(frame: Frame | FrameMesh | FrameModel) -> float:
    """Balance point (centre of gravity) from the butt [m]."""
    a, b, ra = _cells(frame)
    m0, m1, _ = _moments(a, b, 0.0) @ ra
    return float(m1 / m0)


def swing_weight(frame: Frame | FrameMesh | FrameModel, axis: float = SWING_AXIS) -> float:
    """Moment of inertia about an axis ``axis`` [m] from the butt [kg m^2].

    Multiply by 1e4 for the kg cm^2 of racket catalogues (the paper's racket: ~301 kg cm^2).
    """
    a, b, ra = _cells(frame)
    return float(_moments(a, b, axis)[2] @ ra)


@dataclass(frozen=True)
class RacketSpec:
    """A racket's catalogue numbers, SI.

    Attributes
    ----------
    length : float
        L [m].
    mass : float
        M [kg].
    balance : float
        Balance point from the butt [m].
    swing_weight : float
        Inertia about the axis 0.10 m from the butt [kg m^2] (1e-4 x the kg cm^2 figure).
    f1 : float or None
        First free-free bending frequency [Hz].
    """

    length: float
    mass: float
    balance: float
    swing_weight: float
    f1: float | None = None

    def __post_init__(self) -> None:
        check_positive("length", self.length, "m")
        check_positive("mass", self.mass, "kg")
        check_positive("balance", self.balance, "m")
        check_positive("swing_weight", self.swing_weight, "kg m^2")
        if self.f1 is not None:
            check_positive("f1", self.f1, "Hz")

    def as_dict(self) -> dict[str, float | None]:
        """JSON-ready, units in the keys (swing weight in kg cm^2 as quoted)."""
        return {
            "length_m": self.length,
            "mass_kg": self.mass,
            "balance_m": self.balance,
            "swing_weight_kg_cm2": self.swing_weight / KG_CM2,
            "f1_hz": self.f1,
        }


def racket_spec(
    frame: Frame | FrameMesh | FrameModel, *, elements: int = DEFAULT_ELEMENTS
) -> RacketSpec:
    """The catalogue numbers of a frame; f1 from its FE model (``elements`` cells for a Frame)."""
    model = frame if isinstance(frame, FrameModel) else FrameModel.build(frame, elements)
    a, b, ra = _cells(frame)
    m = float(np.sum(ra * (b - a)))
    f1 = float(model.modes(1).frequencies[0])
    return RacketSpec(float(b[-1]), m, balance_point(frame), swing_weight(frame), f1)


def _system(length: float) -> np.ndarray:
    x = np.asarray(SEGMENT_BOUNDS) * length
    return _moments(x[:-1], x[1:], SWING_AXIS)


def spec_bounds(length: float, mass: float, balance: float | None = None) -> dict[str, tuple]:
    """Ranges the parametrisation can reach: balance [m] for (L, M), and swing weight
    [kg m^2] for (L, M, balance) when ``balance`` is given.

    Every segment density at least RHOA_FLOOR M / L: the remaining mass placed in one segment
    gives the balance extremes; with the balance fixed the densities lie on a line whose ends
    (one density at the floor) give the swing-weight extremes.
    """
    A = _system(length)
    floor = RHOA_FLOOR * mass / length
    spare = mass - floor * A[0].sum()
    out: dict[str, tuple] = {}
    cg = [(floor * A[1].sum() + spare * A[1, k] / A[0, k]) / mass + SWING_AXIS for k in range(3)]
    out["balance"] = (min(cg), max(cg))
    if balance is not None:
        if not out["balance"][0] < balance < out["balance"][1]:
            return out
        r0 = np.linalg.lstsq(A[:2], [mass, mass * (balance - SWING_AXIS)], rcond=None)[0]
        n = np.linalg.svd(A[:2])[2][-1]
        # r0 + t n >= floor for every segment
        lo, hi = -np.inf, np.inf
        for rk, nk in zip(r0, n, strict=True):
            t = (floor - rk) / nk
            lo, hi = (max(lo, t), hi) if nk > 0 else (lo, min(hi, t))
        sw = sorted(float(A[2] @ (r0 + t * n)) for t in (lo, hi))
        out["swing_weight"] = (sw[0], sw[1])
    return out


def fit_racket(
    length: float,
    mass: float,
    balance: float,
    swing_weight: float,
    f1: float | None = None,
    *,
    elements: int = DEFAULT_ELEMENTS,
) -> Frame:
    """A three-segment frame with the given catalogue numbers (module docstring).

    Parameters
    ----------
    length, mass, balance, swing_weight : float
        As :class:`RacketSpec` (SI: m, kg, m, kg m^2).
    f1 : float, optional
        First free-free frequency [Hz]; the paper's EI1 = 146 N m^2 shape when None.
    elements : int
        Cells of the FE model on which f1 is matched.

    Returns
    -------
    Frame
        Mass, balance and swing weight exact to round-off; f1 on a mesh of ``elements`` cells
        to ~1e-12.

    Raises
    ------
    InputError
        When no frame of this parametrisation has these numbers, naming the reachable range.
    """
    spec = RacketSpec(length, mass, balance, swing_weight, f1)
    if not 0.0 < balance < length:
        raise InputError(
            f"balance = {show(balance)} m is not allowed: must lie in (0, {length:g}) m"
        )
    bounds = spec_bounds(length, mass, balance)
    lo, hi = bounds["balance"]
    if not lo < balance < hi:
        raise InputError(
            f"balance = {show(balance)} m is not allowed: for length {length:g} m and mass "
            f"{mass:g} kg it must lie in ({lo:.4g}, {hi:.4g}) m"
        )
    lo, hi = bounds["swing_weight"]
    if not lo <= swing_weight <= hi:
        raise InputError(
            f"swing weight = {swing_weight / KG_CM2:.6g} kg cm^2 is not allowed: for mass "
            f"{mass:g} kg and balance {balance:g} m it must lie in "
            f"[{lo / KG_CM2:.4g}, {hi / KG_CM2:.4g}] kg cm^2"
        )
    A = _system(length)
    rhoa = np.linalg.solve(A, [mass, mass * (balance - SWING_AXIS), swing_weight])
    seg_len = np.diff(np.asarray(SEGMENT_BOUNDS) * length)

    def frame(ei1: float) -> Frame:
        return Frame(
            tuple(
                Segment(float(lk), ei1 * s, float(r))
                for lk, s, r in zip(seg_len, EI_SHAPE, rhoa, strict=True)
            )
        )

    base = frame(DEFAULT_EI1)
    if spec.f1 is None:
        return base
    f_base = FrameModel.build(base, elements).modes(1).frequencies[0]
    fitted = frame(DEFAULT_EI1 * (spec.f1 / f_base) ** 2)
    check_fitted_f1(spec.f1, fitted)  # as every reader of its mesh would
    return fitted
