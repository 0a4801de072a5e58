"""Where and how fast the ball strikes the frame."""

from __future__ import annotations

from dataclasses import dataclass

from fem_racket.validation import check_finite, check_positive, check_range

__all__ = ["Impact"]


@dataclass(frozen=True)
class Impact:
    """Where and how fast the ball strikes.

    Parameters
    ----------
    position : float
        Impact point as x/L from the grip end, in [0, 1].
    speed : float
        Ball speed V_B0 [m/s] towards the stationary frame, > 0.
    offset : float
        Lateral distance of the impact point from the long axis [m] (0: on it, the paper's);
        checked against the head outline where the frame is known
        (:func:`fem_racket.impact.offaxis.check_offsets`).
    """

    position: float
    speed: float
    offset: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(
            self, "position", check_range("position", self.position, 0.0, 1.0, unit="x/L")
        )
        object.__setattr__(self, "speed", check_positive("speed", self.speed, "m/s"))
        object.__setattr__(self, "offset", check_finite("offset", self.offset, "m"))
