"""The swing options on the command line: --racket-speed, --reference, --pivot."""

from __future__ import annotations

import pytest
from clirun import run, run_json

from fem_racket import simulate
from fem_racket.impact.swing import Swing


def test_simulate_with_a_swing_is_the_library_call(capsys):
    argv = ("simulate", "--racket-speed", "25", "--pivot", "0.08", "--position", "0.8")
    data = run_json(capsys, *argv)
    ref = simulate(position=0.8, swing=Swing.from_speed(25.0, 0.68, pivot=0.08), output_step=None)
    assert data["ball_speed_out_m_s"] == ref.ball_speed_out
    assert data["apparent_cor"] == ref.apparent_cor == data["cor"]
    assert data["racket_speed_at_impact_m_s"] == ref.racket_speed_at_impact
    assert data["pivot_m"] == pytest.approx(0.08, rel=1e-14)
    code, out, _ = run(capsys, *argv)
    assert "ball speed out" in out and "m/s" in out


def test_a_racket_at_rest_reports_zero_racket_speed(capsys):
    data = run_json(capsys, "simulate")
    assert data["racket_speed_at_impact_m_s"] == 0.0
    assert data["ball_speed_out_m_s"] == data["rebound_speed_m_s"]


def test_swing_from_a_run_file(capsys, tmp_path):
    f = tmp_path / "run.toml"
    f.write_text("[impact]\nracket_speed_m_s = 25.0\npivot_m = 0.08\nposition_x_over_l = 0.8\n")
    from_file = run_json(capsys, "simulate", "--config", f)
    argv = ("simulate", "--racket-speed", "25", "--pivot", "0.08", "--position", "0.8")
    assert from_file == run_json(capsys, *argv)


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (("--racket-speed", "-30"), "the two must close"),
        (("--racket-speed", "10", "--pivot", "0.51"), "pivot = 0.51 m is not allowed"),
        (("--reference", "1.5"), "reference = 1.5"),
        (("--racket-speed", "nan"), "racket_speed = nan"),
    ],
)
def test_bad_swing_is_one_line_exit_2(capsys, argv, message):
    code, _, err = run(capsys, "simulate", *argv)
    assert code == 2
    assert message in err and len(err.strip().splitlines()) == 1
