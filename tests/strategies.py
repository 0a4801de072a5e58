"""Hypothesis strategies and profiles shared by the property tests.

The ``ci`` profile (default) is derandomized: the same examples every run, so CI is
reproducible; ``HYPOTHESIS_PROFILE=explore`` searches new ones. Frames are 1 to
``max_segments`` uniform segments of a 0.5-0.8 m frame (the paper's is 0.68 m), EI 50-3000 N m^2
(the range of the paper's Fig 13), rhoA 0.2-1.2 kg/m (the paper's 0.458 and 0.696 inside it).
"""

from __future__ import annotations

import os

import numpy as np
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st

from fem_racket import Frame, Segment

settings.register_profile(
    "ci",
    derandomize=True,
    database=None,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("explore", deadline=None, max_examples=200)
PROFILE = os.environ.get("HYPOTHESIS_PROFILE", "ci")
settings.load_profile(PROFILE)


@st.composite
def frames(draw, max_segments: int = 5) -> Frame:
    """A random valid frame (see the module docstring)."""
    n = draw(st.integers(1, max_segments))
    length = draw(st.floats(0.5, 0.8))
    shares = np.array([draw(st.floats(0.2, 1.0)) for _ in range(n)])
    ei = [draw(st.floats(50.0, 3000.0)) for _ in range(n)]
    rhoa = [draw(st.floats(0.2, 1.2)) for _ in range(n)]
    lengths = length * shares / shares.sum()
    return Frame(tuple(Segment(float(h), e, r) for h, e, r in zip(lengths, ei, rhoa, strict=True)))
