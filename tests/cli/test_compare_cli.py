"""``fem-racket compare``: A A shows zero differences; B - A as the physics says; the files."""

from __future__ import annotations

import numpy as np
import pytest
from clirun import file_refused_alike, run, run_json

from fem_racket.frame.head import DEFAULT_HEAD
from fem_racket.frame.lead import lead_moments
from fem_racket.frame.specs import KG_CM2

FAST = ("--positions", "0.5:1:21")


def compare_json(capsys, tmp_path, *argv):
    return run_json(capsys, "compare", *argv, *FAST, "--out", tmp_path / "c.nc")


def test_compare_a_a_shows_zero_differences(capsys, tmp_path):
    data = compare_json(capsys, tmp_path, "standard", "standard")
    names = [r["name"] for r in data["rackets"]]
    assert names == ["standard", "standard (2)"]
    (diff,) = data["differences"].values()
    for key, value in diff.items():
        assert value is None or value == 0.0, key
    import xarray as xr

    with xr.open_dataset(tmp_path / "c.nc") as ds:
        assert np.all(ds["apparent_cor_difference"].values == 0.0)
        assert np.all(ds["ball_speed_out_difference_m_s"].values == 0.0)
        assert ds["swing_weight_kg_cm2"].values[0] == pytest.approx(301.08, abs=0.01)


def test_lead_at_12_shows_as_its_own_difference(capsys, tmp_path):
    data = compare_json(capsys, tmp_path, "standard", "standard+12:10", "--racket-speed", "20")
    ((name, diff),) = data["differences"].items()
    assert name == "standard+12:10"
    assert diff["mass_kg"] == pytest.approx(0.010, rel=1e-12)
    head = DEFAULT_HEAD
    want = 0.010 * lead_moments("12", head)[2] / KG_CM2
    assert diff["swing_weight_kg_cm2"] == pytest.approx(want, rel=1e-9)
    # Cross 2001 (Sports Eng 4): lead at the tip of a swung racket raises the best ball speed
    assert diff["max_ball_speed_out_m_s"] > 0.0
    assert data["rackets"][1]["contact_time_s"] > 0.0


def test_run_file_setups_bring_their_own_ball(capsys, tmp_path):
    light = tmp_path / "light.toml"
    light.write_text('[ball]\nmass_kg = 0.056\n[frame]\nlead = [{ place = "3/9", mass_g = 6 }]\n')
    data = compare_json(capsys, tmp_path, "standard", light)
    diff = data["differences"]["light"]
    assert diff["ball_mass_kg"] == pytest.approx(-0.001, rel=1e-9)
    assert diff["mass_kg"] == pytest.approx(0.006, rel=1e-12)
    bad = tmp_path / "bad.toml"
    bad.write_text("[impact]\nspeed_m_s = 30\n")
    code, _, err = run(capsys, "compare", "standard", bad, *FAST, "--out", tmp_path / "x.nc")
    assert code == 2 and "[impact] is not allowed in a compared set-up" in err


@pytest.mark.parametrize("suffix", [".png", ".svg", ".pdf"])
def test_one_page_figure(capsys, tmp_path, suffix):
    out = tmp_path / f"c{suffix}"
    code, text, err = run(capsys, "compare", "standard", "rigid", *FAST, "--out", out)
    assert code == 0, err
    assert out.stat().st_size > 1000 and "swing weight [kg cm^2]" in text


@pytest.mark.parametrize(
    ("argv", "says"),
    [
        (["standard"], "need at least 2"),
        (["standard", "rigid", "--out", "c.txt"], "must end in .png, .svg, .pdf, .nc"),
        (["standard", "nofile.vtu"], "no such file"),
        (["standard", "standard+13:4"], "place = '13'"),
    ],
)
def test_bad_compare_input_is_one_line(capsys, tmp_path, monkeypatch, argv, says):
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, "compare", *argv, *FAST)
    assert code == 2 and says in err and len(err.splitlines()) == 1, err
    assert not list(tmp_path.glob("output/*"))


def test_face_maps_compare_and_lead_at_3_9_lifts_the_sides(capsys, tmp_path):
    face = ("--offsets", "-0.1:0.1:5", "--positions", "0.6:0.9:7")
    nc = tmp_path / "f.nc"
    data = run_json(
        capsys, "compare", "standard", "standard", "standard+3/9:10", *face, "--out", nc
    )
    assert data["differences"]["standard (2)"]["power_area_cm2"] == 0.0
    import xarray as xr

    with xr.open_dataset(nc) as ds:
        d = ds["apparent_cor_face_difference"].values
        assert np.all(d[0][np.isfinite(d[0])] == 0.0)  # A - A: zero on the whole face
        # Brody 2005: more twistweight, less energy in roll: e_A rises off the axis
        assert np.nanmin(d[1][[0, -1]]) > 0.0
        assert ds["apparent_cor_face"].dims == ("racket", "offset", "position")


def test_a_run_files_impact_position_is_refused_not_skipped(capsys, cwd):
    # F11: it states compare's --point (the contact time, the handle shock), which the command
    # did not read from it (the point stayed 0.75): refused alike, as other unused keys are;
    # [compare] point sets the point, and the position at its default changes nothing
    file_refused_alike(
        capsys,
        "[impact]\nposition_x_over_l = 0.6\n",
        ["compare", "standard", "rigid", "--config", "run.toml", "--out", "a.png"],
        lambda config: config.compare(["standard", "rigid"], "a.png"),
        "impact.position_x_over_l = 0.6 is not allowed with fem-racket compare: it has no such "
        "option, so the key would be ignored; remove it",
    )
    (cwd / "run.toml").write_text("[impact]\nposition_x_over_l = 0.75\n[compare]\npoint = 0.6\n")
    argv = ("compare", "standard", "rigid", *FAST)
    by_file = run_json(capsys, *argv, "--config", "run.toml", "--out", "f.nc")["rackets"]
    by_option = run_json(capsys, *argv, "--point", "0.6", "--out", "o.nc")["rackets"]
    at_075 = run_json(capsys, *argv, "--out", "d.nc")["rackets"]
    assert by_file == by_option and by_file[0]["contact_time_s"] != at_075[0]["contact_time_s"]
