"""A sweep's file states what its cases used: the swing's reference point only with a swing
(the racket at rest has none: a Swing's reference is None then), and on a string bed under the
paper's law the ball's own law (``kawazoe-1997-ball``, as ``simulate --string-tension`` names
it), not the paper's K_CB "from the speed" and clamped-COR zeta the bed replaces."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from fem_racket.contact.bed_ball import kawazoe_ball
from fem_racket.impact.simulate import simulate
from fem_racket.strings.bed import StringBed
from fem_racket.studies.sweep import sweep
from fem_racket.validation import InputError
from tests.clirun import run_json


def test_no_reference_without_a_swing():
    assert "reference_x_over_l" not in sweep(position=[0.6, 0.7]).attrs
    # with a swing (fixed, or swept through rest) the reference point is the swing's
    assert sweep(position=[0.6, 0.7], racket_speed=10.0).attrs["reference_x_over_l"] == 0.75
    swept = sweep(position=0.7, racket_speed=[0.0, 10.0], reference=0.6)
    assert swept.attrs["reference_x_over_l"] == 0.6


def test_the_command_s_files_alike(cwd, capsys):
    run_json(capsys, "sweep", "--positions", "0.6,0.7", "--out", "s.csv", "--quiet")
    assert "reference_x_over_l" not in json.loads(Path("s.csv.json").read_text())
    run_json(capsys, "sweep", "--positions", "0.6,0.7", "--out", "s.nc", "--quiet")
    import xarray as xr

    with xr.open_dataset("s.nc") as ds:
        assert "reference_x_over_l" not in ds.attrs and ds.attrs["racket_speed_m_s"] == 0.0


def test_a_strung_sweep_states_the_ball_s_law(standard_model):
    ds = sweep(position=[0.6, 0.7], string_tension=246.0)
    attrs = ds.attrs
    assert "kcb_n_m" not in attrs and "zeta" not in attrs  # the paper's law's: not used
    assert attrs["ball_law"] == "kawazoe-1997-ball" and attrs["contact_law"] == "linear"
    one = simulate(standard_model, position=0.7, strings=StringBed(tension_n=246.0)).summary()
    assert attrs["contact_kcb_n_m"] == one["kcb_n_m"]  # the ball's spring and damping used
    assert attrs["contact_zeta"] == one["zeta"] and attrs["contact_ccb_n_s_m"] == one["ccb_n_s_m"]
    assert float(ds.cor.sel(position=0.7)) == pytest.approx(one["cor"], rel=1e-12)
    masses = sweep(position=0.7, string_tension=246.0, ball_mass=[0.057, 0.06]).attrs
    assert masses["contact_zeta"] == [kawazoe_ball(m).zeta for m in (0.057, 0.06)]


def test_the_command_s_summary(cwd, capsys):
    out = run_json(capsys, "sweep", "--string-tension", "246", "--positions", "0.6,0.7",
                   "--out", "s.csv", "--quiet")  # fmt: skip
    assert out["ball_law"] == "kawazoe-1997-ball" and out["contact_law"] == "linear"
    attrs = json.loads(Path("s.csv.json").read_text())
    assert "kcb_n_m" not in attrs and attrs["ball_law"] == "kawazoe-1997-ball"
    # no bed: the paper's K_CB from the speed, as before, and no ball law
    out = run_json(capsys, "sweep", "--positions", "0.6,0.7", "--out", "p.csv", "--quiet")
    assert "ball_law" not in out
    assert json.loads(Path("p.csv.json").read_text())["kcb_n_m"].startswith("from the speed")


def test_a_strung_sweep_states_its_tolerances_truly():
    attrs = sweep(position=0.7, string_tension=246.0).attrs
    # the strung racket's exact solution keeps every mode (the solver refuses a tolerance)
    assert attrs["modes_kept"] == "all (string bed: every frame mode)"
    assert attrs["tolerance"] == "all modes"
    assert "within 'tolerance'" not in attrs["tolerances"]
    assert "every frame and string-bed mode" in attrs["tolerances"]
    assert "tolerance, rtol, atol unused" in attrs["tolerances"]
    with pytest.raises(InputError, match="tolerance = 0.001 is not allowed with a string bed"):
        sweep(position=0.7, string_tension=246.0, tolerance=1e-3)
    plain = sweep(position=[0.6, 0.7]).attrs  # no bed: the engine's tolerance, as before
    assert plain["tolerance"] == 1e-6 and "within 'tolerance'" in plain["tolerances"]
