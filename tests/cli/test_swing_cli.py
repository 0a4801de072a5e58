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


# K_CB(V) holds for closing speeds of 1-100 m/s (contact.constants.KCB_SPEED_RANGE); a racket
# turning about a pivot closes on the ball at the impact point's own speed. About a shoulder
# 0.5 m beyond the butt, 80 m/s at the reference point 0.75 L moves the point 0.5 L of the
# standard racket (L = 0.68 m) at 80 (0.34 + 0.5) / (0.51 + 0.5) = 66.5 m/s and the tip at
# 93.5 m/s (< 100 m/s, the racket's bound): with a 30 m/s ball it closes at 96.5 m/s. The CLI
# refused it at the reference point's 110 m/s; the library and a run file ran it.
ACCEPTED = ("--speed", "30", "--position", "0.5", "--racket-speed", "80", "--pivot", "-0.5")
# The same swing at 75 m/s struck at 0.95 L with a 20 m/s ball closes at 105.1 m/s there (95
# m/s at the reference point): refused alike, at the impact point's speed.
REFUSED = ("--speed", "20", "--position", "0.95", "--racket-speed", "75", "--pivot", "-0.5")
REFUSED_WORDS = (
    "racket speed at the impact point = 85.0990099009901 m/s is not allowed with speed = "
    "20.0 m/s: the closing speed 105.099 m/s is above the 100 m/s where the paper's K_CB holds"
)


def _run_file(path, speed, position, racket_speed):
    path.write_text(
        f"[impact]\nspeed_m_s = {speed}\nposition_x_over_l = {position}\n"
        f"racket_speed_m_s = {racket_speed}\npivot_m = -0.5\n"
    )
    return path


def test_the_kcb_closing_speed_is_the_impact_points_on_the_cli_a_run_file_and_the_library(
    capsys, tmp_path
):
    from fem_racket import load_config

    swing = Swing.from_speed(80.0, 0.68, pivot=-0.5)
    lib = simulate(speed=30.0, position=0.5, swing=swing, output_step=None)
    assert lib.racket_speed_at_impact == pytest.approx(80.0 * 0.84 / 1.01, rel=1e-12)
    cli = run_json(capsys, "simulate", *ACCEPTED)
    path = _run_file(tmp_path / "ok.toml", 30.0, 0.5, 80.0)
    from_file = run_json(capsys, "simulate", "--config", path)
    assert cli["cor"] == from_file["cor"] == lib.apparent_cor
    assert load_config(path).simulate().apparent_cor == lib.apparent_cor


def test_a_closing_speed_beyond_kcb_at_the_impact_point_is_refused_alike(capsys, tmp_path):
    from clirun import one_error, refused_alike

    from fem_racket import load_config
    from fem_racket.validation import InputError

    assert REFUSED_WORDS in one_error(capsys, "simulate", *REFUSED)
    path = _run_file(tmp_path / "bad.toml", 20.0, 0.95, 75.0)
    refused_alike(capsys, ["simulate", "--config", path], load_config(path).simulate, REFUSED_WORDS)
    swing = Swing.from_speed(75.0, 0.68, pivot=-0.5)
    with pytest.raises(InputError, match="^" + REFUSED_WORDS.replace(".", r"\.")):
        simulate(speed=20.0, position=0.95, swing=swing, output_step=None)
    # a translation moves the impact point at --racket-speed: its refusal names the option, as
    # a run file names its key (the closing refusal too: "racket speed at the impact point")
    path = _run_file(tmp_path / "away.toml", 20.0, 0.75, -30.0)
    path.write_text(path.read_text().replace("pivot_m = -0.5\n", ""))
    words = "racket_speed_m_s = -30 m/s is not allowed with ball speed 20 m/s: the two must close"
    refused_alike(capsys, ["simulate", "--config", path], load_config(path).simulate, words)
    line = one_error(capsys, "simulate", "--racket-speed", "-30")
    assert ": error: " + words.replace("_m_s", "") in line, line
