"""``--add-mass LOCATION:GRAMS`` and ``[[frame.lead]]``: lead on the commands that take a racket."""

from __future__ import annotations

import json

import pytest
from clirun import file_refused_alike, one_error, run, run_json

from fem_racket import frame_mesh, standard_frame
from fem_racket.frame.catalogue import catalogue
from fem_racket.frame.head import DEFAULT_HEAD
from fem_racket.frame.lead import Lead, add_lead
from fem_racket.frame.specs import KG_CM2


def modes_json(capsys, *argv):
    return run_json(capsys, "modes", "--count", "1", *argv)


def test_modes_reports_swing_weight_and_the_lead(capsys):
    base = modes_json(capsys)
    # the paper's racket: about 301 kg cm^2 (DESIGN.md section 8)
    assert base["swing_weight_kg_cm2"] == pytest.approx(301.08, abs=0.01)
    # the standard racket's torsion data: an assumption of fem_racket.frame.segments (17.49)
    assert base["twist_weight_kg_cm2"] == pytest.approx(base["polar_moment_kg_m2"] / KG_CM2)
    got = modes_json(capsys, "--add-mass", "3/9:10", "--add-mass", "0.32:5")
    mesh = frame_mesh(standard_frame(), 20)
    want = catalogue(add_lead(mesh, [Lead("3/9", 0.01), Lead("0.32", 0.005)], DEFAULT_HEAD))
    assert got["mass_kg"] == pytest.approx(base["mass_kg"] + 0.015, rel=1e-13)
    assert got["swing_weight_kg_cm2"] == pytest.approx(want.swing_weight / KG_CM2, rel=1e-13)
    assert got["cg_m"] == pytest.approx(want.balance, rel=1e-13)
    assert got["frequencies_hz"][0] == pytest.approx(want.f1, rel=1e-12)
    # 10 g at 3/9: 5 g at r = 0.126 m on each side; 0.32 m is on the axis
    r = DEFAULT_HEAD.width_m / 2
    tw = base["twist_weight_kg_cm2"] + 0.010 * r**2 / KG_CM2
    assert got["twist_weight_kg_cm2"] == pytest.approx(tw, rel=1e-12)


def test_run_file_lead_is_the_command_line_lead(capsys, tmp_path):
    toml = tmp_path / "run.toml"
    toml.write_text(
        '[frame]\nlead = [{ place = "3/9", mass_g = 10 }, { place = "12", mass_g = 4 }]\n'
    )
    from_file = modes_json(capsys, "--config", toml)
    from_line = modes_json(capsys, "--add-mass", "3/9:10", "--add-mass", "12:4")
    assert from_file == from_line
    # the command line replaces the file's list
    assert modes_json(capsys, "--config", toml, "--add-mass", "12:4")["mass_kg"] == pytest.approx(
        from_line["mass_kg"] - 0.010, rel=1e-13
    )


def test_map_with_lead_at_the_tip_moves_the_best_point_tipward(capsys, tmp_path):
    # Cross 2001 (Sports Eng 4): 30 g at the tip moves the maximum toward the tip
    spots = []
    for extra in ([], ["--add-mass", "12:30"]):
        out = tmp_path / f"m{len(extra)}.csv"
        code, text, err = run(
            capsys, "map", "--json", "--out", out, "--positions", "0.5:1:41", *extra
        )
        assert code == 0, err
        spots.append(json.loads(text)["max_apparent_cor_x_over_l"])
    assert spots[1] > spots[0]


@pytest.mark.parametrize(
    ("args", "says"),
    [
        (["--add-mass", "3/9"], "LOCATION:GRAMS"),
        (["--add-mass", "13:4"], "place = '13' is not allowed"),
        (["--add-mass", "0.9:4"], "within [0, 0.68]"),
    ],
)
def test_bad_lead_is_one_line(capsys, args, says):
    code, _, err = run(capsys, "modes", *args)
    assert code == 2 and says in err and len(err.splitlines()) == 1


def test_a_lead_at_the_frames_length_is_the_tip(capsys):
    # the standard frame's length, the sum of its cells, is 0.6799999999999999 m: 0.68 m (the
    # interval printed, [0, 0.68]) was refused though the tip, place 12, is x = L
    tip = modes_json(capsys, "--add-mass", "12:5")
    assert modes_json(capsys, "--add-mass", "0.68:5") == tip
    line = one_error(capsys, "modes", "--add-mass", "0.6801:5")
    assert "place = '0.6801' is not allowed" in line and "within [0, 0.68]" in line, line


def test_a_lead_of_0_g_is_refused_alike(capsys, cwd):
    # 0 g changes nothing: an option without effect is refused (check_grams' words)
    line = one_error(capsys, "modes", "--add-mass", "12:0")
    assert "add-mass = '12:0' is not allowed: must be > 0 g" in line, line
    file_refused_alike(
        capsys,
        '[frame]\nlead = [{ place = "12", mass_g = 0 }]\n',
        ["modes", "--config", "run.toml"],
        lambda config: config.modes(),
        "frame.lead[0].mass_g = 0.0 is not allowed: must be > 0 g",
    )
