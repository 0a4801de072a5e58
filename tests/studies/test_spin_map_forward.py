"""``map --angle 0`` printed ``angle out 0.000 to 180.0 deg``: the 180 is no artifact but the
points where the free racket's COR is negative (near the tip and the rim its effective mass is
small, so the ball keeps moving forward: ``simulate --position 0.96`` prints a rebound speed of
-1.58 m/s), whose outgoing angle from the outward face normal is 180 head-on (over 90 with an
angle). The convention is stated in the angle's label and, where such points exist, in the
printed line. A head-on, spinless spin map runs, as ``simulate --angle 0 --spin 0`` does (the
contact's own options are refused there, as simulate refuses them)."""

from __future__ import annotations

import numpy as np
import pytest
from clirun import run_ok

from fem_racket.frame.model import FrameModel
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate import simulate
from fem_racket.studies.spin_map import SPIN_FIELDS, spin_map

POSITIONS = [0.7, 0.96]


@pytest.fixture(scope="module")
def head_on():
    model = FrameModel.build()
    return model, spin_map(model, positions=POSITIONS, offsets=[0.0, 0.01], incidence=Incidence())


def test_the_180_is_where_the_ball_keeps_moving_forward(head_on):
    model, m = head_on
    for k, x in enumerate(POSITIONS):  # the axis row against the normal impact alone
        rebound = simulate(model, position=x).summary()["rebound_speed_m_s"]
        assert m.fields["spin_out_rpm"][0, k] == 0.0
        assert m.fields["ball_speed_out_m_s"][0, k] == pytest.approx(abs(rebound), rel=1e-9)
        assert m.fields["angle_out_deg"][0, k] == (180.0 if rebound < 0.0 else 0.0)
    assert (
        simulate(model, position=0.96).summary()["rebound_speed_m_s"]
        < 0.0
        < simulate(model, position=0.7).summary()["rebound_speed_m_s"]
    )
    ahead = int(np.count_nonzero(m.fields["angle_out_deg"] == 180.0))
    assert m.forward() == (ahead, 4) and ahead >= 1
    assert "outward face normal" in SPIN_FIELDS["angle_out_deg"][1]


def test_the_printed_line_states_the_convention(cwd, capsys, head_on):
    _, m = head_on
    ahead, points = m.forward()
    out = run_ok(capsys, "map", "--angle", "0", "--positions", "0.7,0.96", "--offsets",
                 "0,0.01", "--no-files")  # fmt: skip
    line = next(ln for ln in out.splitlines() if "angle out" in ln)
    assert line.split() == ["angle", "out", "0.000", "to", "180.0", "deg", "(>", "90:", "the",
                            "ball", "keeps", "moving", "forward,", "COR", "<", "0,", "at",
                            str(ahead), "of", str(points), "points)"]  # fmt: skip
    # where every ball rebounds the line is as before
    out = run_ok(capsys, "map", "--angle", "30", "--positions", "0.6,0.7", "--offsets",
                 "0,0.01", "--no-files")  # fmt: skip
    line = next(ln for ln in out.splitlines() if "angle out" in ln)
    assert line.endswith(" deg") and "moving forward" not in line
