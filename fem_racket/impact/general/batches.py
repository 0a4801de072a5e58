"""Batches that span frames and law parameters: one general-integrator call for many groups.

The compiled march (:mod:`fem_racket.impact.general.kernel`) takes every case with its own
modes and law parameters, so the cases of many frames (a sweep's EI axis, a design
population) go to one call: :func:`stack_receptances` gives one
:class:`~fem_racket.impact.general.receptance.Receptance` with a row of frequencies per case
(shorter rows padded with modes of infinite frequency and zero shape, which the cut-off never
keeps and the pseudo-mode's sums ignore), :func:`stack_laws` one law with a parameter per case.
"""

from __future__ import annotations

from dataclasses import fields, replace

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.general.receptance import Receptance

__all__ = ["stack_laws", "stack_receptances"]


def stack_receptances(parts: list[Receptance]) -> Receptance:
    """The cases of ``parts`` in order, each with its frame's frequencies (rows of omega)."""
    width = max(p.a.shape[1] for p in parts)
    sizes = [p.a.shape[0] for p in parts]
    omega, a = np.full((sum(sizes), width), np.inf), np.zeros((sum(sizes), width))
    start = 0
    for p, n in zip(parts, sizes, strict=True):
        m = p.a.shape[1]
        omega[start : start + n, :m], a[start : start + n, :m] = p.omega, p.a
        start += n
    return Receptance(
        omega,
        a,
        np.concatenate([p.rigid for p in parts]),
        np.concatenate([p.ball_mass for p in parts]),
    )


def stack_laws(laws: list[ContactLaw], counts: list[int]) -> ContactLaw:
    """One law of the class of ``laws`` whose numeric parameters hold ``counts[i]`` values of
    ``laws[i]`` in order (other fields, such as a separation criterion, must agree)."""
    kind = type(laws[0])
    if any(type(law) is not kind for law in laws):
        raise ValueError("laws of one batch must be of one class")
    values = {}
    for f in fields(laws[0]):
        first = getattr(laws[0], f.name)
        if isinstance(first, str):
            if any(getattr(law, f.name) != first for law in laws):
                raise ValueError(f"laws of one batch differ in {f.name}")
            continue
        values[f.name] = np.concatenate(
            [np.broadcast_to(np.asarray(getattr(law, f.name), dtype=float), (n,))
             for law, n in zip(laws, counts, strict=True)]
        )  # fmt: skip
    return replace(laws[0], **values)
