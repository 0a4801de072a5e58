"""Which output times an impact's drawing keeps: evenly spread steps, first and last included
(for the VTK series of :mod:`fem_racket.io.vtk_series` and the string bed's)."""

from __future__ import annotations

import numpy as np

from fem_racket.validation import InputError, show

__all__ = ["check_int", "sample_steps"]


def check_int(name: str, value: object, low: int, high: int | None = None, why: str = "") -> int:
    """``value`` as an int if it is an integer in [low, high] (no upper bound when None); else
    one line naming ``name``, its value and the range (``why`` appended)."""
    ok = isinstance(value, (int, np.integer)) and not isinstance(value, bool)
    if not ok or value < low or (high is not None and value > high):
        rng = f">= {low}" if high is None else f"in [{low}, {high}]"
        raise InputError(f"{name} = {show(value)} is not allowed: must be an integer {rng}{why}")
    return int(value)


def sample_steps(n_times: int, frames: int | None = None) -> np.ndarray:
    """Indices of ``frames`` output times spread evenly over ``n_times``, first and last kept.

    ``None`` keeps every output time.
    """
    if frames is None:
        return np.arange(n_times)
    frames = check_int(
        "frames", frames, 2, n_times, f" (the simulation has {n_times} output times)"
    )
    return np.unique(np.rint(np.linspace(0, n_times - 1, frames)).astype(int))
