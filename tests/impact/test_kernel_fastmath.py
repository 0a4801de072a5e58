"""A kernel's machine code does not depend on what its process compiled before (issue 27).

numba caches its internal helpers (complex products, ...) per process without their fastmath
flags: once a function with ``fastmath`` had compiled a complex product (as the linear engine's
root iteration does), the general kernels compiled after it in the same process got fused
multiply-adds, and their answers left the interpreted kernels' by an ulp
(:mod:`fem_racket.impact.kernel_fastmath`). Each test compiles in a new process on an empty
numba cache (``NUMBA_CACHE_DIR`` in ``tmp_path``: the package's cache is not touched), after
such a function, and compares with the kernels' own code interpreted, bit for bit.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

#: Compiled first in the child: a complex product with fastmath, as case_roots has one.
_FUSED = """
from numba import njit

@njit(fastmath={"contract"}, error_model="numpy")
def fused(z, w):
    return z * w

fused(1.0 + 2.0j, 3.0 - 1.0j)
"""

_MODES = """
import json
import numpy as np
from fem_racket.impact.general import jit, kernel_modes

def run():
    rng = np.random.default_rng(27)
    n, h = 200, 1e-5
    w, cs = rng.uniform(1e3, 1e6, n), rng.standard_normal((3, 4, 4))
    y = rng.standard_normal(n) + 1j * rng.standard_normal(n)
    Gw, c1, c2 = kernel_modes.weights(w, h, cs)
    modal = (np.exp(1j * w * h), np.linspace(0.5, 2.0, n), Gw)
    rig = kernel_modes.advance(y, (0.1, 2.0), np.array([1.0, 2.0, -0.5, 3.0]), 1, modal,
                               (20.0, h, c1, c2))
    return [Gw, c1, c2, y, np.array(rig)]

interpreted = run()
FUSED
jit._compile()
print(json.dumps([bool(np.array_equal(a, b)) for a, b in zip(interpreted, run())]))
"""

_IMPACT = """
import json, sys
from fem_racket import FrameModel
from fem_racket.contact.presets import PRESETS
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.law_impact import receptance
name, x, v = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
law, model = PRESETS[name], FrameModel.build(None, 20)
alone = solve_general(law, receptance(model, x, 0.057), v)  # the first lone impact: interpreted
interpreted = "numba" not in sys.modules
FUSED
batch = solve_general(law, receptance(model, [x, x], 0.057), v)  # compiled
keys = ("contact_time", "ball_velocity", "impulse", "peak_force")
out = {k: [float(getattr(alone, k)[0]), float(getattr(batch, k)[0])] for k in keys}
print(json.dumps(out | {"interpreted": interpreted}))
"""


def _child(code: str, cache, *args: object) -> object:
    """The JSON a new process prints, numba caching into the empty folder ``cache``."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path), NUMBA_CACHE_DIR=str(cache))
    run = subprocess.run(
        [sys.executable, "-c", code.replace("FUSED", _FUSED), *map(str, args)],
        capture_output=True, text=True, check=True, env=env,
    )  # fmt: skip
    return json.loads(run.stdout)


def test_mode_kernels_after_a_fastmath_function_match_their_code_interpreted(tmp_path):
    # weights: real x complex products (unaffected); advance: complex x complex (fused before)
    assert _child(_MODES, tmp_path) == [True] * 5


@pytest.mark.slow
def test_an_impact_compiled_after_a_fastmath_function_matches_the_interpreted_one(tmp_path):
    # the case: COR 0.1846719513970374 compiled, 0.18467195139703765 interpreted;
    # here the peak force moved by 3e-12 N and the contact time by an ulp (~30 s: a compile)
    out = _child(_IMPACT, tmp_path, "kawazoe-1997-nonlinear", 0.75, 30.0)
    assert out.pop("interpreted") is True
    for key, (alone, batch) in out.items():
        assert alone == batch, key
