"""``fem-racket sweep`` and ``map`` with a 3-D oblique ball (``--side-angle``, ``--side-spin``)
and the sweep of a strung racket struck obliquely: each case is ``simulate``'s (1e-12), bad
input is refused in one line (exit 2)."""

from __future__ import annotations

import csv

import pytest

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate_oblique import simulate_oblique
from tests.clirun import refused_before_any_file, run, run_json

#: The spin map's CSV columns of a ball in the plane of the long axis (as before the side axes).
PLANE_COLUMNS = [
    "racket", "position [x/L]", "offset [m]", "spin out [rpm]", "angle out [deg]",
    "ball speed out [m/s]", "contact regime [-]",
]  # fmt: skip


def _close(got: float, want: float) -> None:
    assert got == pytest.approx(want, rel=1e-12, abs=1e-12)


def test_sweep_over_side_angle_and_side_spin(cwd, capsys):
    import netCDF4

    argv = ["--angle", "20", "--side-angle", "-10:10:5", "--side-spin", "0,1000", "--out", "s.nc"]
    code, out, err = run(capsys, "sweep", *argv)
    assert code == 0, err
    assert "10 impacts (side_angle 5 x side_spin 2)" in out
    with netCDF4.Dataset(cwd / "s.nc") as ds:
        assert ds["side_angle"].units == "deg" and ds["side_spin"].units == "rpm"
        assert ds["side_spin_out_rpm"].units == "rpm"
        assert ds["side_angle_out_deg"].units == "deg"
        assert ds["racket_yaw_rate_rad_s"].units == "rad/s"
        assert ds.angle_deg == 20.0
        got = {k: ds[k][:] for k in ("side_spin_out_rpm", "side_angle_out_deg", "spin_out_rpm")}
    for i, j in ((0, 1), (3, 0), (4, 1)):
        b, w = (-10.0, -5.0, 0.0, 5.0, 10.0)[i], (0.0, 1000.0)[j]
        ref = simulate_oblique(incidence=Incidence(angle=20.0, side_angle=b, side_spin=w))
        for key, values in got.items():
            _close(float(values[i, j]), ref.summary()[key])


def test_sweep_of_a_strung_racket_struck_obliquely_is_simulates(cwd, capsys):
    ball = ["--string-tension", "250", "--angle", "20", "--spin", "500"]
    code, out, err = run(capsys, "sweep", *ball, "--speed", "20,25", "--out", "s.csv")
    assert code == 0, err
    with open(cwd / "s.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    one = run_json(capsys, "simulate", *ball, "--speed", "25")
    for key in ("spin_out_rpm", "angle_out_deg", "cor", "stringbed_stiffness_n_m"):
        column = next(c for c in rows[1] if c.startswith(key + " "))
        _close(float(rows[1][column]), one[key])
    assert rows[1]["contact_regime [-]"] == one["contact_regime"]


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["sweep", "--angle", "20", "--side-angle", "90"], "side_angle = 90.0 deg is not allowed"),
        (["sweep", "--side-angle", "-95,0"], "side_angle = -95.0 deg is not allowed"),
        (["sweep", "--side-spin", "fast"], "side_spin = 'fast' is not allowed"),
        (
            ["sweep", "--string-tension", "250", "--side-spin", "0,300"],
            "side_spin = [0.0, 300.0] is not allowed with string_tension (a string bed)",
        ),
        (["map", "--angle", "20", "--side-angle", "95"], "side_angle = 95"),
        (["map", "--side-spin", "500", "--racket-speed", "5"], "racket_speed is not allowed"),
    ],
)
def test_bad_side_input_is_refused_in_one_line(cwd, capsys, argv, words):
    line = refused_before_any_file(capsys, *argv)
    assert words in line, line


def test_map_of_a_3d_oblique_ball(cwd, capsys):
    inc = ["--angle", "20", "--side-angle", "10", "--side-spin", "500"]
    grid = ["--positions", "0.6,0.75,0.9", "--offsets", "-0.05,0,0.05"]
    code, out, err = run(capsys, "map", *inc, *grid, "--out", "s.csv", "s.png")
    assert code == 0, err
    assert "side spin out" in out and "side angle out" in out and "racket yaw rate" in out
    with open(cwd / "s.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    incidence = Incidence(angle=20.0, side_angle=10.0, side_spin=500.0)
    pairs = {
        "spin out [rpm]": "spin_out_rpm",
        "side spin out [rpm]": "side_spin_out_rpm",
        "side angle out [deg]": "side_angle_out_deg",
        "racket yaw rate [rad/s]": "racket_yaw_rate_rad_s",
    }
    for r in rows[::4]:  # each point is the single 3-D oblique impact there
        x, y = float(r["position [x/L]"]), float(r["offset [m]"])
        ref = simulate_oblique(incidence=incidence, position=x, offset=y).summary()
        for column, key in pairs.items():
            _close(float(r[column]), ref[key])
        assert r["contact regime [-]"] == ref["contact_regime"]


def test_map_in_the_plane_keeps_its_columns(cwd, capsys):
    grid = ["--positions", "0.6,0.9", "--offsets", "-0.05,0.05"]
    code, out, err = run(
        capsys, "map", "--angle", "20", "--side-angle", "0", *grid, "--out", "p.csv"
    )
    assert code == 0, err
    assert "side spin out" not in out
    with open(cwd / "p.csv", newline="") as fh:
        assert next(csv.reader(fh)) == PLANE_COLUMNS
