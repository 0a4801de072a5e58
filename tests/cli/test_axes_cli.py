"""``fem-racket sweep`` over string-bed and oblique axes, and ``fem-racket map --angle``: the
spin over the face (issue 25 item 3, issue 26 item 4)."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate_oblique import simulate_oblique
from tests.clirun import refused_before_any_file, run


def test_sweep_writes_the_oblique_outputs_with_units(cwd, capsys):
    import netCDF4

    code, out, err = run(capsys, "sweep", "--angle", "20,40", "--spin", "0,2000", "--out", "o.nc")
    assert code == 0, err
    assert "4 impacts (angle 2 x spin 2)" in out
    with netCDF4.Dataset(cwd / "o.nc") as ds:
        assert ds["spin_out_rpm"].units == "rpm" and ds["angle_out_deg"].units == "deg"
        assert ds["ball_speed_out_m_s"].units == "m/s"
        assert "slide" in ds["contact_regime"].flag_meanings
        spin = ds["spin_out_rpm"][:]
    ref = simulate_oblique(incidence=Incidence(angle=40.0, spin=2000.0), speed=20.0).summary()
    assert spin[1, 1] == ref["spin_out_rpm"]


def test_sweep_writes_the_bed_outputs(cwd, capsys):
    code, out, err = run(
        capsys, "sweep", "--string-tension", "220,270", "--pattern", "16x19,18x20", "--position",
        "0.74", "--out", "s.csv",
    )  # fmt: skip
    assert code == 0, err
    with open(cwd / "s.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [r["pattern [-]"] for r in rows] == ["16x19", "18x20"] * 2
    k = [float(r["stringbed_stiffness_n_m [N/m]"]) for r in rows]
    assert k[2] / k[0] == pytest.approx(270 / 220, rel=1e-12)  # k ~ T (membrane)


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (
            ["sweep", "--string-tension", "250", "--angle", "20", "--side-angle", "5"],
            "side_angle = 5.0 is not allowed with string_tension",
        ),
        (["sweep", "--pattern", "16x19", "--kcb", "3e4"], "kcb is not allowed with pattern"),
        (["sweep", "--angle", "95"], "angle = 95.0 deg is not allowed"),
        (["map", "--angle", "40", "--power-fraction", "0.9"], "power_fraction is not allowed"),
        (["map", "--angle", "40", "--racket-speed", "5"], "racket_speed is not allowed with"),
    ],
)
def test_what_cannot_combine_is_refused(cwd, capsys, argv, words):
    assert words in refused_before_any_file(capsys, *argv)


def test_map_draws_the_spin_over_the_face(cwd, capsys):
    inc = ["--angle", "40", "--spin", "-3820", "--speed", "25"]
    grid = ["--positions", "0.6,0.75,0.9", "--offsets", "-0.05,0,0.05"]
    code, out, err = run(capsys, "map", *inc, *grid, "--out", "s.csv", "s.png", "s.nc")
    assert code == 0, err
    assert "spin out max" in out and "contact regimes" in out
    assert (cwd / "s.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with open(cwd / "s.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 9
    incidence = Incidence(angle=40.0, spin=-3820.0)
    for r in rows[::4]:  # each point is the single oblique impact there
        x, y = float(r["position [x/L]"]), float(r["offset [m]"])
        ref = simulate_oblique(incidence=incidence, speed=25.0, position=x, offset=y).summary()
        assert float(r["spin out [rpm]"]) == ref["spin_out_rpm"]
        assert r["contact regime [-]"] == ref["contact_regime"]
    spins = np.array([float(r["spin out [rpm]"]) for r in rows])
    assert np.all(np.isfinite(spins))
