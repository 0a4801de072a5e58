"""``compare``, ``customise`` and ``map`` (its axis and its face) check a swing's K_CB closing
speed where the ball strikes, as the library does
(:func:`fem_racket.studies.swing_points.check_swing_points`, ImpactProblem's check_swing), not at
the swing's reference point: the command line, the run file's methods and the library accept and
refuse alike, with one line (see tests/cli/test_swing_cli.py for ``simulate``)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from clirun import one_error, refused_alike, run_json

from fem_racket import load_config
from fem_racket.frame.constants import RIGID_EI1
from fem_racket.frame.segments import standard_frame
from fem_racket.studies.compare import Play, Setup, compare
from fem_racket.validation import InputError

# K_CB(V) holds for closing speeds of 1-100 m/s (contact.constants.KCB_SPEED_RANGE). About a
# shoulder 0.5 m beyond the butt, 80 m/s at the reference point 0.75 L (0.51 m) moves x at
# 80 (x + 0.5) / 1.01 m/s: 0.5 L at 66.5 m/s, 0.55 L at 69.2 m/s; with a 30 m/s ball the
# points 0.5-0.55 L close at 96.5-99.2 m/s (< 100) while the reference point, not struck, would
# close at 110 m/s: accepted (the CLI refused it at the reference point; the library ran it).
ACCEPTED = ("--speed", "30", "--racket-speed", "80", "--pivot", "-0.5")
GRID = ("--positions", "0.5:0.55:3", "--point", "0.5", "--elements", "6")
# 75 m/s at 0.75 L about the same shoulder, a 20 m/s ball: the tip (0.68 m) moves at
# 75 x 1.18 / 1.01 = 87.62 m/s and closes at 107.6 m/s (the reference point at 95): refused,
# naming the racket's speed at that impact point (was 'speed = 107.6 m/s ... [1, 100]', the
# engine's, after the work had begun).
REFUSED = ("--speed", "20", "--racket-speed", "75", "--pivot", "-0.5", "--elements", "6")
REFUSED_WORDS = (
    "racket speed at the impact point = 87.62376237623761 m/s is not allowed with speed = "
    "20.0 m/s: the closing speed 107.624 m/s is above the 100 m/s where the paper's K_CB holds"
)
PLAY = "[impact]\nspeed_m_s = {}\nracket_speed_m_s = {}\npivot_m = -0.5\n[frame]\nelements = 6\n"


def _setups():
    return [
        Setup("standard", standard_frame(), elements=6),
        Setup("rigid", standard_frame(RIGID_EI1), elements=6),
    ]


def test_compare_accepts_a_swing_closing_within_kcb_at_every_impact_point(cwd, capsys):
    cli = run_json(capsys, "compare", "standard", "rigid", *ACCEPTED, *GRID, "--out", "c.nc")
    play = Play(speed=30.0, racket_speed=80.0, pivot=-0.5, positions=np.linspace(0.5, 0.55, 3),
                position=0.5)  # fmt: skip
    lib = compare(_setups(), play)
    Path("run.toml").write_text(PLAY.format(30.0, 80.0) + '[compare]\npositions = "0.5:0.55:3"\n'
                                "point = 0.5\n")  # fmt: skip
    from_file = load_config("run.toml").compare(["standard", "rigid"])
    for k, report in enumerate(lib):
        values = report.values()
        assert from_file[k].values() == values  # the run file's method: bit for bit
        for key, value in values.items():  # the CLI's JSON: to its 15 printed digits
            got = cli["rackets"][k][key]
            assert got == (None if value is None else pytest.approx(value, rel=1e-14)), key
    # the swing did play: v_out = e_A v_in + (1 + e_A) v_r > v_r, 66.5 m/s at 0.5 L
    assert cli["rackets"][0]["max_ball_speed_out_m_s"] > 80.0 * 0.84 / 1.01


def test_compare_and_customise_refuse_at_the_impact_point_alike(cwd, capsys):
    Path("run.toml").write_text(PLAY.format(20.0, 75.0))
    argv = ("compare", "standard", "rigid", "--config", "run.toml", "--positions", "0.5:1:5")
    method = load_config("run.toml").compare
    refused_alike(capsys, argv, lambda: method(["standard", "rigid"]), REFUSED_WORDS, start=True)
    assert REFUSED_WORDS in one_error(capsys, "compare", "standard", "rigid", *REFUSED)
    play = Play(speed=20.0, racket_speed=75.0, pivot=-0.5, positions=np.linspace(0.5, 1.0, 5))
    with pytest.raises(InputError, match="^" + REFUSED_WORDS.replace(".", r"\.")):
        compare(_setups(), play)
    cust = ("customise", "--swing-weight", "320", "--places", "12")
    Path("run.toml").write_text(PLAY.format(20.0, 75.0) + "[customise]\nswing_weight = 320\n")
    customise = load_config("run.toml").customise
    refused_alike(capsys, ("customise", "--config", "run.toml"), customise, REFUSED_WORDS)
    assert REFUSED_WORDS in one_error(capsys, *cust, *REFUSED)
    # and config --check finds it before any work (it passed the file: 95 m/s at the reference)
    line = one_error(capsys, "config", "--check", "run.toml")
    assert "fem-racket customise would refuse it: " + REFUSED_WORDS in line
    assert sorted(p.name for p in Path().iterdir()) == ["run.toml"]  # nothing written


@pytest.mark.parametrize("command", ["compare", "customise"])
def test_a_translation_is_named_as_its_option(cwd, capsys, command):
    # a racket translating at --racket-speed moves every point at it: the library's refusal of
    # that speed is named as the option, as simulate names it
    argv = (
        ("compare", "standard", "rigid", "--elements", "6")
        if command == "compare"
        else ("customise", "--swing-weight", "320", "--elements", "6")
    )
    line = one_error(capsys, *argv, "--racket-speed", "90")
    assert line.endswith(
        "error: racket_speed = 90.0 m/s is not allowed with speed = 20.0 m/s: the closing speed "
        "110 m/s is above the 100 m/s where the paper's K_CB holds (give kcb)"
    )
    line = one_error(capsys, *argv, "--racket-speed", "-30")
    assert line.endswith("error: racket_speed = -30 m/s is not allowed with ball speed 20 m/s: "
                         "the two must close (v_in + v_r > 0)")  # fmt: skip


MAP = ("map", "--elements", "6", "--no-files", "--json")


@pytest.mark.parametrize("face", [(), ("--offsets=-0.02,0,0.02",)], ids=["axis", "face"])
def test_map_checks_at_the_impact_points_as_the_library(cwd, capsys, face):
    # accepted: every struck point closes below 100 m/s (was refused at the reference point)
    out = run_json(capsys, *MAP, *ACCEPTED, "--positions", "0.5:0.55:3", *face)
    assert out
    # refused at the tip, naming the racket's speed there (was 'speed = 100.01 m/s ... [1, 100]'
    # for the axis map, the engine's line about the closing speed, after the checks)
    assert REFUSED_WORDS in one_error(capsys, *MAP, *REFUSED, *face)


def test_map_library_refuses_at_the_impact_point():
    from fem_racket.studies.face_map import face_map
    from fem_racket.studies.racket_map import racket_map

    swing = {"speed": 20.0, "racket_speed": 75.0, "pivot": -0.5, "elements": 6}
    with pytest.raises(InputError, match="^" + REFUSED_WORDS.replace(".", r"\.")):
        racket_map(standard_frame(), **swing)
    with pytest.raises(InputError, match="^" + REFUSED_WORDS.replace(".", r"\.")):
        face_map(standard_frame(), positions=np.linspace(0.5, 1.0, 5), offsets=[0.0, 0.02],
                 **{k: v for k, v in swing.items() if k != "elements"})  # fmt: skip
