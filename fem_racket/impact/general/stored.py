"""The nodal histories of a batch as the compiled march stores them: case after case.

Every case keeps only the nodes it marched (:func:`fem_racket.impact.general.kernel.march_cases`),
so no array is padded to the longest case while the vouching rule runs cases again; the (C, N)
histories of :class:`~fem_racket.impact.general.march.GeneralOutcome` are laid out once, for the
answers (:func:`laid_out`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Stored", "joined", "laid_out"]


@dataclass(frozen=True, eq=False)
class Stored:
    """Histories F, delta, delta', z, z' (rows of ``store``, (5, T)) of C cases: case c's
    nodes are the columns start[c]:start[c] + length[c]."""

    store: np.ndarray
    start: np.ndarray
    length: np.ndarray

    def take(self, idx: np.ndarray) -> Stored:
        """The histories of the cases ``idx`` (the store shared)."""
        return Stored(self.store, self.start[idx], self.length[idx])


def joined(parts: list[tuple[np.ndarray, Stored]], ncase: int) -> Stored:
    """One :class:`Stored` of ``ncase`` cases from parts (case indices, their histories)."""
    if len(parts) == 1:  # all at once (a frame at rest): the store as it is
        idx, s = parts[0]
        start, length = np.zeros(ncase, dtype=np.int64), np.zeros(ncase, dtype=np.int64)
        start[idx], length[idx] = s.start, s.length
        return Stored(s.store, start, length)
    store = np.concatenate([s.store for _, s in parts], axis=1)
    offsets = np.cumsum([0] + [s.store.shape[1] for _, s in parts])
    start, length = np.zeros(ncase, dtype=np.int64), np.zeros(ncase, dtype=np.int64)
    for (idx, s), shift in zip(parts, offsets, strict=False):
        start[idx], length[idx] = s.start + shift, s.length
    return Stored(store, start, length)


def laid_out(parts: list[tuple[np.ndarray, Stored]], ncase: int) -> dict[str, np.ndarray]:
    """The outcome's histories (C, N) from parts (case indices, their histories): force,
    deflection, rate and state, zero after each case's last node (N its most nodes)."""
    width = max((int(s.length.max(initial=0)) for _, s in parts), default=0)
    out = np.zeros((ncase, 4, width))
    for idx, s in parts:
        for c, first, n in zip(idx.tolist(), s.start.tolist(), s.length.tolist(), strict=True):
            out[c, :, :n] = s.store[:4, first : first + n]
    return {k: out[:, row] for row, k in enumerate(("force", "deflection", "rate", "state"))}
