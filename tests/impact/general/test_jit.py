"""A process's first lone impact runs the kernels interpreted (issue 27: ``simulate --law``
without numba's start-up): the same answers as the compiled kernels, numba never imported.

Each case runs in a new process (only the first solve of a process is interpreted) and is
compared with the compiled kernels in this one. The interpreted code is the kernels' own,
operation for operation (integer powers written out as numba multiplies them), so the answers
agree bit for bit.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from fem_racket import FrameModel
from fem_racket.contact.presets import PRESETS, get_law
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.general.jit import INTERPRETED_NODES
from fem_racket.impact.law_impact import receptance

_CHILD = """
import json, sys
from fem_racket import FrameModel
from fem_racket.contact.presets import PRESETS, get_law
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.law_impact import receptance
name, x, v, steps = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4:]
law = PRESETS[name] if name in PRESETS else get_law(name)
rec = receptance(FrameModel.build(None, 20), x, 0.057)
out = solve_general(law, rec, v, steps=int(steps[0]) if steps else None)
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


def _child(*args: object) -> dict:
    """The outcome of a lone impact solved first in a new process, and whether numba loaded."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    run = subprocess.run(
        [sys.executable, "-c", _CHILD, *map(str, args)],
        capture_output=True, text=True, check=True, env=env,
    )  # fmt: skip
    return json.loads(run.stdout)


def _compare(child: dict, out) -> None:
    """The child's outcome against the first case of ``out`` (compiled)."""
    for key, value in child.items():
        assert value == getattr(out, key)[0], key  # the same operations: the same bits


@pytest.mark.parametrize(("name", "x", "v"), CASES)
def test_lone_impact_interpreted_matches_compiled(name, x, v):
    child = _child(name, x, v)
    assert child.pop("numba") is False  # interpreted: numba not even imported
    law = PRESETS[name] if name in PRESETS else get_law(name)
    rec = receptance(FrameModel.build(None, 20), [x, x], 0.057)
    _compare(child, solve_general(law, rec, v))  # a batch: compiled


def test_long_run_of_a_lone_impact_compiles():
    # 600 steps per contact time over twice its estimate: 1 201 nodes, over INTERPRETED_NODES
    assert 2 * 600 + 1 > INTERPRETED_NODES
    name, x, v = CASES[0]
    child = _child(name, x, v, 600)
    assert child.pop("numba") is True
    rec = receptance(FrameModel.build(None, 20), [x, x], 0.057)
    _compare(child, solve_general(PRESETS[name], rec, v, steps=600))
