"""Where the ball may strike the bed and how fast a swing may move the racket: refused before any
work, in one line, by the command, its run file and the library alike (review H1, L3, M5).

H1: a point whose ball's contact disk (0.02 m) reaches off the meshed bed ended in a traceback
("Point is outside of the mesh"); L3: the refusal printed a range holding the refused value and
no lateral limit. M5: a pivot next to the reference point turned the racket at 1e8 rad/s."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

import fem_racket as fr
from fem_racket.impact.constants import MAX_RACKET_SPEED
from fem_racket.impact.swing_reach import pivot_reach
from fem_racket.validation import InputError
from tests.clirun import one_error, refused_alike, run


def _build(position: float, offset: float = 0.0, **bed):
    return lambda: fr.ImpactProblem.build(
        position=position, offset=offset, strings=fr.StringBed(**bed)
    )


@pytest.mark.parametrize(
    ("argv", "position", "offset", "bed"),
    [
        (["--offset", "0.1", "--position", "0.6"], 0.6, 0.1, {}),
        (["--offset", "0.105", "--head-area", "500"], 0.75, 0.105, "area"),
        (["--offset", "0.12", "--head-width", "0.2"], 0.75, 0.12, {"head_width_m": 0.2}),
    ],
)
def test_disk_off_the_bed_is_refused_naming_the_reachable_offset(
    capsys, argv, position, offset, bed
):
    if bed == "area":  # 500 cm^2 keeping the default head's shape
        s = (500e-4 / (fr.StringBed().area_m2)) ** 0.5
        bed = {"head_length_m": 0.326 * s, "head_width_m": 0.252 * s}
    words = f"offset = {offset} m at position = {position} x/L is not allowed with the string bed"
    argv = ["simulate", "--string-tension", "246", *argv]
    refused_alike(capsys, argv, _build(position, offset, **bed), words, start=True)
    line = one_error(capsys, *argv)
    limit = float(re.search(r"\|offset\| <= ([0-9.]+) m at that position", line).group(1))
    assert limit < offset
    _build(position, limit, **bed)()  # the printed limit is allowed
    with pytest.raises(InputError, match="must lie on the head"):
        _build(position, limit + 2e-4, **bed)()  # and it is the limit (printed to 0.1 mm)
    with pytest.raises(InputError, match=re.escape(words)):
        fr.simulate(position=position, offset=offset, strings=fr.StringBed(**bed))


@pytest.mark.parametrize("position", [0.5, 0.98])
def test_axis_range_printed_holds_only_allowed_positions(capsys, position):
    line = one_error(capsys, "simulate", "--string-tension", "246", "--position", position)
    lo, hi = map(float, re.search(r"positions ([0-9.]+) to ([0-9.]+) x/L", line).groups())
    assert not lo <= position <= hi and f"position = {position} x/L" in line
    for x in (lo, hi):
        _build(x)()  # the printed ends are allowed
    for x in (lo - 2e-3, hi + 2e-3):
        with pytest.raises(InputError, match="must lie on the head"):
            _build(x)()


def test_strung_runs_near_the_reach_still_run(capsys):
    # a point just inside the reach runs (no refusal, no traceback)
    code, _, err = run(capsys, "simulate", "--string-tension", "246", "--position", "0.6",
                       "--offset", "0.078", "--json")  # fmt: skip
    assert code == 0, err


@pytest.mark.parametrize("speed", [10.0, 45.0, -30.0])
def test_pivot_reach_moves_the_fastest_point_at_the_bound(speed):
    # At each end of the refused interval the butt or the tip moves at exactly MAX_RACKET_SPEED
    # (closed form of pivot_reach; round-off 1e-9 relative), inside it faster, outside slower.
    length, ref = 0.68, 0.51
    lo, hi = pivot_reach(speed, ref, length)
    assert lo < ref < hi
    for p in (lo, hi):
        s = fr.Swing(-speed / (ref - p) * p, speed / (ref - p))
        assert s.fastest(length) == pytest.approx(MAX_RACKET_SPEED, rel=1e-9)
    for p in (0.5 * (lo + ref), 0.5 * (ref + hi)):
        with pytest.raises(InputError, match=f"pivot = {p!r} m is not allowed"):
            fr.Swing.from_speed(speed, length, reference=ref / length, pivot=p)
    for p in (lo - 1e-6, hi + 1e-6):
        assert (
            fr.Swing.from_speed(speed, length, reference=ref / length, pivot=p).fastest(length)
            <= MAX_RACKET_SPEED
        )


def test_pivot_by_the_reference_refused_alike(capsys, cwd):
    # M5: --pivot 0.5099999 with --racket-speed 10 printed 1e8 rad/s
    words = "pivot = 0.5099999 m is not allowed with racket_speed = 10.0 m/s"
    swing = lambda: fr.simulate(swing=fr.Swing.from_speed(10.0, 0.68, pivot=0.5099999))  # noqa: E731
    argv = ["--pivot", "0.5099999", "--racket-speed", "10"]
    refused_alike(capsys, ["simulate", *argv, "--json"], swing, words, start=True)
    line = one_error(capsys, "simulate", *argv)
    assert "must be <= 0.4636 m or >= 0.5667 m" in line  # the butt: r/(1 + u), r/(1 - u), u = 0.1
    assert words in one_error(capsys, "sweep", *argv)
    Path("run.toml").write_text("[impact]\nracket_speed_m_s = 10.0\npivot_m = 0.5099999\n")
    words = "run.toml: impact." + words.replace("pivot", "pivot_m", 1)  # the file's key named
    assert words in one_error(capsys, "simulate", "--config", "run.toml")
    with pytest.raises(InputError, match=re.escape(words)):
        fr.load_config("run.toml").simulate()


def test_swing_moving_the_racket_too_fast_refused_by_the_problem():
    # a Swing made directly (no pivot to name): the problem refuses it naming its end speeds
    with pytest.raises(
        InputError, match=r"swing = Swing\(velocity=-50000000.0, omega=100000000.0\)"
    ):
        fr.ImpactProblem.build(swing=fr.Swing(-5e7, 1e8))
    ok = fr.ImpactProblem.build(swing=fr.Swing(-3.0, 40.0))  # tip 24.2 m/s: allowed
    assert np.isfinite(ok.racket_speed)
