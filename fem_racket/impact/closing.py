"""The speed at which ball and strings meet, v_in + v_r [m/s], and its checks: the two must
close, and where K_CB follows from it (the paper's law without kcb) it must lie within the
speeds the paper gives K_CB for (:data:`~fem_racket.contact.constants.KCB_SPEED_RANGE`).
:mod:`fem_racket.impact.swing` gives the impact point's speed v_r of a swing.
"""

from __future__ import annotations

from fem_racket.contact.constants import KCB_SPEED_RANGE
from fem_racket.validation import InputError, show

__all__ = ["check_kcb_closing", "closing_speed"]


def closing_speed(speed: float, racket_speed: float) -> float:
    """Speed at which ball and strings meet, v_in + v_r [m/s]; > 0 or an InputError."""
    c = float(speed) + float(racket_speed)
    if not c > 0.0:
        raise InputError(
            f"racket speed at the impact point = {racket_speed:g} m/s is not allowed with ball "
            f"speed {speed:g} m/s: the two must close (v_in + v_r > 0)",
            parameter="racket speed at the impact point",
            value=racket_speed,
        )
    return c


def check_kcb_closing(speed: float, racket_speed: float, closing: float, name: str) -> None:
    """Refuse a swing whose closing speed ``closing`` [m/s] (of the ball's ``speed`` and the
    racket's) is outside the speeds the paper gives K_CB for, where K_CB follows from it (the
    paper's law without kcb): named as the racket speed (``name`` = ``racket_speed`` [m/s]), not
    as the closing speed it derives. One that does not close is :func:`closing_speed`'s to
    refuse."""
    low, high = KCB_SPEED_RANGE
    if 0.0 < closing < low or closing > high:
        side = f"above the {high:g}" if closing > high else f"below the {low:g}"
        raise InputError(
            f"{name} = {show(racket_speed)} m/s is not allowed with speed = {show(speed)} m/s: "
            f"the closing speed {closing:g} m/s is {side} m/s where the paper's K_CB holds "
            "(give kcb)",
            parameter=name,
            value=racket_speed,
        )
