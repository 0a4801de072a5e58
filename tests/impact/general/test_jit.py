"""A process's first lone impact runs the kernels interpreted (issue 27: ``simulate --law``
without numba's start-up): the same answers as the compiled kernels, numba never imported.

Each case runs in a new process (only the first solve of a process is interpreted) and is
compared with the compiled kernels in this one. The interpreted code is the kernels' own,
operation for operation, so the answers agree to round-off (observed: bit for bit).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from fem_racket import FrameModel
from fem_racket.contact.presets import PRESETS, get_law
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.law_impact import receptance

_CHILD = """
import json, sys
from fem_racket import FrameModel
from fem_racket.contact.presets import PRESETS, get_law
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.law_impact import receptance
name, x, v = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
law = PRESETS[name] if name in PRESETS else get_law(name)
out = solve_general(law, receptance(FrameModel.build(None, 20), x, 0.057), v)
keys = ("contact_time", "ball_velocity", "impulse", "peak_force")
print(json.dumps({k: float(getattr(out, k)[0]) for k in keys} | {"numba": "numba" in sys.modules}))
"""

# a memory state and a cut force (hysteretic), an ODE state (series), a force end condition
# with damping (Hunt-Crossley)
CASES = [
    ("kawazoe-1997-nonlinear", 0.75, 20.0),
    ("series", 0.6, 30.0),
    ("hunt-crossley", 0.9, 40.0),
]


@pytest.mark.parametrize(("name", "x", "v"), CASES)
def test_lone_impact_interpreted_matches_compiled(name, x, v):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    run = subprocess.run(
        [sys.executable, "-c", _CHILD, name, str(x), str(v)],
        capture_output=True, text=True, check=True, env=env,
    )  # fmt: skip
    child = json.loads(run.stdout)
    assert child.pop("numba") is False  # interpreted: numba not even imported
    model = FrameModel.build(None, 20)
    law = PRESETS[name] if name in PRESETS else get_law(name)
    rec = receptance(model, [x, x], 0.057)
    out = solve_general(law, rec, v)  # a batch: compiled
    for key, value in child.items():
        # the same floating-point operations: round-off only (bits observed)
        np.testing.assert_allclose(value, getattr(out, key)[0], rtol=1e-13, atol=0.0)
