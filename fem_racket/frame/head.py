"""The racket's head: the outline of the string face, an ellipse on the frame's long axis.

Positions on the face are (x, y): x along the frame from the grip end [m], y the lateral offset
from the long axis [m] (positive toward one side; the frame is symmetric, so the sign only says
which way the racket rolls). The string face is the ellipse

    ((x - x_c) / (length / 2))^2 + (y / (width / 2))^2 <= 1

Defaults: a "100 in^2" (645 cm^2) head, the most common size, with the string bed 0.326 m long
and 0.252 m wide (area pi/4 x 0.326 x 0.252 = 645.2 cm^2; ITF rules, appendix II: the strung
surface may not exceed 39.4 cm by 29.2 cm). Its centre sits at 0.74 L of the paper's 0.680 m
frame (x_c = 0.503 m), so the bed spans x = 0.340 m (0.5 L) to 0.666 m, 14 mm below the tip
for the head frame's profile. These are typical dimensions (assumptions): the paper gives no
head geometry.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from fem_racket.validation import InputError, check_positive, check_range, show

__all__ = ["DEFAULT_HEAD", "HeadOutline"]


@dataclass(frozen=True)
class HeadOutline:
    """The string face: an ellipse centred on the long axis.

    Parameters
    ----------
    length_m : float
        Length of the string bed along the frame [m].
    width_m : float
        Width of the string bed across the frame [m].
    centre : float
        Centre of the ellipse as x/L from the grip end.
    frame_length_m : float
        Frame length L [m] that ``centre`` refers to.
    """

    length_m: float = 0.326
    width_m: float = 0.252
    centre: float = 0.74
    frame_length_m: float = 0.680

    def __post_init__(self) -> None:
        check_positive("head length", self.length_m, "m")
        check_positive("head width", self.width_m, "m")
        check_positive("frame length", self.frame_length_m, "m")
        check_range("head centre", self.centre, 0.0, 1.0, unit="x/L")
        lo, hi = self.x_range
        if lo < 0.0 or hi > self.frame_length_m:
            raise InputError(
                f"head length = {show(self.length_m)} m is not allowed with centre "
                f"{show(self.centre)} x/L: the head ({lo:.4g} to {hi:.4g} m) must lie on the "
                f"frame (0 to {self.frame_length_m:.4g} m)",
                parameter="head length",
                value=self.length_m,
            )

    def on_frame(self, frame_length_m: float) -> HeadOutline:
        """The same head (size and centre x/L) on a frame of length ``frame_length_m`` [m]."""
        return replace(self, frame_length_m=frame_length_m)

    @property
    def centre_m(self) -> float:
        """Centre x_c of the ellipse from the grip end [m]."""
        return self.centre * self.frame_length_m

    @property
    def x_range(self) -> tuple[float, float]:
        """First and last x of the string face [m]."""
        return self.centre_m - self.length_m / 2.0, self.centre_m + self.length_m / 2.0

    @property
    def area_m2(self) -> float:
        """Area of the string face, pi/4 x length x width [m^2]."""
        return math.pi / 4.0 * self.length_m * self.width_m

    def half_width(self, x: float | np.ndarray) -> np.ndarray:
        """Largest |y| [m] on the face at ``x`` [m]; NaN off the face's length."""
        s = (np.asarray(x, dtype=float) - self.centre_m) / (self.length_m / 2.0)
        inside = np.abs(s) <= 1.0
        with np.errstate(invalid="ignore"):
            return np.where(inside, 0.5 * self.width_m * np.sqrt(1.0 - s * s), np.nan)

    def contains(self, x: float | np.ndarray, y: float | np.ndarray) -> np.ndarray:
        """True where (x, y) [m] lies on the string face (boundary included)."""
        s = (np.asarray(x, dtype=float) - self.centre_m) / (self.length_m / 2.0)
        r = np.asarray(y, dtype=float) / (self.width_m / 2.0)
        return s * s + r * r <= 1.0 + 1e-12

    def check(self, x: float, y: float) -> float:
        """Return ``y`` [m] if (x, y) is on the face or y = 0 (an impact on the long axis, the
        paper's, is allowed anywhere along it); else raise naming the offset and what is
        allowed at x."""
        y = float(y)
        if y == 0.0 or bool(self.contains(x, y)):
            return y
        hw = float(self.half_width(x))
        lo, hi = self.x_range
        allowed = (
            f"|offset| <= {hw:.4g} m at x = {x:.4g} m"
            if math.isfinite(hw)
            else f"0 at x = {x:.4g} m (the face spans x = {lo:.4g} to {hi:.4g} m)"
        )
        raise InputError(
            f"offset = {show(y)} m is not allowed: the point must lie on the head "
            f"({self.length_m:g} m x {self.width_m:g} m ellipse): {allowed}",
            parameter="offset",
            value=y,
        )


#: The default head: 100 in^2 (645 cm^2) on the paper's 0.680 m frame.
DEFAULT_HEAD = HeadOutline()
