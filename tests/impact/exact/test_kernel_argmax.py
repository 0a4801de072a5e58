"""The peak force's grid maximum (:func:`fem_racket.impact.exact.kernel_events._argmax`) is
``np.argmax`` of the first ``n`` values, as numba and numpy compute it: the first NaN, else the
first of equal largest values (issue 27: written out so that the cached engine names no
``numba.np.arraymath``, whose import loads scipy.linalg)."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.impact.exact.kernel_events import _argmax


@pytest.mark.parametrize("seed", range(6))
def test_argmax_is_numpys(seed):
    rng = np.random.default_rng(seed)
    for _ in range(200):
        vals = rng.integers(-3, 4, size=int(rng.integers(1, 12))).astype(float)  # ties
        if rng.random() < 0.3:
            vals[rng.integers(vals.size)] = np.nan
        n = int(rng.integers(1, vals.size + 1))
        expected = int(np.argmax(vals[:n]))
        assert _argmax(vals, n) == expected  # compiled
        assert _argmax.py_func(vals, n) == expected
