"""What the run-file tests share: a strung racket's run file, and a run's numbers compared with
the command's JSON output to its printed digits."""

from __future__ import annotations

import json
import math

import pytest

#: A racket strung with an 18x20 bed, struck at 0.76 L at 25 m/s (issue 25's bed).
BED = """
[frame]
elements = 8
[strings]
tension_n = 270.0
pattern = "18x20"
[impact]
position_x_over_l = 0.76
speed_m_s = 25.0
"""

#: The CLI's JSON numbers are printed to 15 significant digits (fem_racket.cli.common.print_json)
REL = 1e-12


def same(a, b, path=""):
    """Assert ``a`` (the library's, as JSON) equals ``b`` (the command's JSON) key for key,
    numbers to :data:`REL`."""
    if isinstance(a, dict):
        assert set(a) == set(b), path
        for k in a:
            same(a[k], b[k], f"{path}.{k}")
    elif isinstance(a, list):
        assert len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            same(x, y, f"{path}[{i}]")
    elif isinstance(a, float) and isinstance(b, float) and math.isfinite(a):
        assert a == pytest.approx(b, rel=REL, abs=1e-300), path
    else:
        assert a == b, path


def py_json(obj):
    """``obj`` as the commands print it in JSON (NaN and inf as null, arrays as lists)."""
    from fem_racket.outputs.jsonable import json_ready

    return json.loads(json.dumps(json_ready(obj)))
