"""Which meshes a refinement study builds: the frame as segments and the element counts it can
take (:func:`refinable`)."""

from __future__ import annotations

import logging
from collections.abc import Sequence
from typing import Any

import numpy as np

from fem_racket.frame.mesh import MAX_ELEMENTS, FrameMesh, frame_from_mesh
from fem_racket.frame.segments import Frame, standard_frame
from fem_racket.validation import InputError, show

__all__ = ["refinable"]

log = logging.getLogger(__name__)


def _check_elements(elements: Sequence[int]) -> np.ndarray:
    allowed = f"must be a list of integers from 1 to {MAX_ELEMENTS}"
    try:
        counts = [int(n) for n in elements]
    except (TypeError, ValueError):
        raise InputError(f"elements = {show(elements)} is not allowed: {allowed}") from None
    bad = [
        n
        for n, e in zip(counts, elements, strict=True)
        if not 1 <= n <= MAX_ELEMENTS or isinstance(e, bool) or n != e
    ]
    if not counts or bad:
        raise InputError(f"elements = {show(list(elements))} is not allowed: {allowed}")
    return np.unique(counts)


def refinable(frame: Any, elements: Sequence[int]) -> tuple[Frame, np.ndarray, tuple[int, ...]]:
    """(the frame as segments, the element counts to build, the counts skipped as fewer than its
    segments) for a study of ``frame`` (a Frame, FrameMesh or None: the paper's racket)."""
    counts = _check_elements(elements)
    if frame is None:
        frame = standard_frame()
    if isinstance(frame, FrameMesh):
        frame = frame_from_mesh(frame)
    if not isinstance(frame, Frame):
        raise InputError(f"frame = {show(frame)} is not allowed: must be a Frame or a FrameMesh")
    n_seg = len(frame.segments)
    skipped = tuple(int(n) for n in counts if n < n_seg)
    if skipped:
        log.warning("skipping element counts %s: fewer than the %d segments", skipped, n_seg)
    counts = counts[counts >= n_seg]
    if counts.size == 0:
        raise InputError(
            f"elements = {show(list(elements))} is not allowed: need a count >= {n_seg} "
            f"(one per segment)"
        )
    return frame, counts, skipped
