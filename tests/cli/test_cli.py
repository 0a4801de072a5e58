"""The CLI, called in-process: JSON contracts and tables with units (bad input: its catalogue)."""

import json

import pytest
from clirun import run, run_json

from fem_racket import simulate


def test_simulate_json_contract(capsys):
    data = run_json(capsys, "simulate", "--speed", "20", "--position", "0.75")
    for key in (
        "cor",
        "contact_time_s",
        "rebound_speed_m_s",
        "peak_force_n",
        "solver",
        "elements",
        "position_x_over_l",
        "speed_m_s",
    ):
        assert key in data
    assert data["solver"] == "exact"
    assert data["elements"] == 20
    # The library call the command wraps: without --out, no histories.
    ref = simulate(position=0.75, speed=20.0, output_step=None)
    assert data["cor"] == ref.cor
    assert data["contact_time_s"] == ref.contact_time
    assert data["peak_force_n"] == ref.peak_force
    assert data["rebound_speed_m_s"] == pytest.approx(data["cor"] * 20.0)


def test_simulate_table_has_units(capsys):
    code, out, _ = run(capsys, "simulate", "--speed", "30", "--position", "0.6", "--ei1", "300")
    assert code == 0
    assert "coefficient of restitution" in out
    assert "ms" in out and "m/s" in out and " N" in out


def test_simulate_options_reach_the_library(capsys):
    _, a, _ = run(
        capsys,
        "simulate",
        "--json",
        "--solver",
        "cvode",
        "--separation",
        "force",
        "--ei1",
        "500",
        "--ei2",
        "300",
        "--ball-mass",
        "0.058",
        "--kcb",
        "30000",
        "--zeta",
        "0.05",
        "--elements",
        "10",
    )
    data = json.loads(a)
    assert data["solver"] == "cvode"
    assert data["separation"] == "force"
    assert data["elements"] == 10
    assert data["kcb_n_m"] == 30000.0
    assert data["zeta"] == 0.05
    assert data["ball_mass_kg"] == 0.058


def test_modes_json_contract(capsys):
    data = run_json(capsys, "modes")
    assert data["mass_kg"] == pytest.approx(0.360, abs=5e-4)
    assert data["cg_x_over_l"] == pytest.approx(0.453, abs=5e-4)
    assert data["frequencies_hz"][:2] == pytest.approx([122.1, 337.2], abs=0.05)
    assert data["frequencies_hz"] == sorted(data["frequencies_hz"])
    assert len(data["nodes_x_over_l"][0]) == 2 and len(data["nodes_x_over_l"][1]) == 3


def test_modes_table(capsys):
    code, out, _ = run(capsys, "modes")
    assert code == 0
    assert "122.14" in out and "Hz" in out and "kg" in out
