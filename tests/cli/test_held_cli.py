"""A hand on the grip from the command line: ``simulate --grip`` and the hand's parameters."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest
from clirun import run_json, run_ok

from fem_racket.cli.text import significant
from fem_racket.frame.hand import GRIPS, Hand
from fem_racket.impact.held.basis import held_basis
from fem_racket.impact.held.grip import simulate_held
from fem_racket.impact.held.modal import held_contact
from fem_racket.impact.held.run import hand_summary
from fem_racket.impact.held.shock import DEFAULT_WINDOW, contact_peak, grip_peak, vibration_rms
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.swing import Swing
from fem_racket.outputs import json_ready


def simulate_json(capsys, *argv):
    """``fem-racket simulate ARGV --json`` (exit 0): the printed JSON."""
    return run_json(capsys, "simulate", *argv)


@pytest.fixture(scope="module")
def exact(standard_model):
    """The library's exact held impacts (every mode) at the CLI's defaults."""
    return {
        g: held_contact(held_basis(standard_model.fe, h), position=0.75, speed=20.0, tolerance=None)
        for g, h in GRIPS.items()
    }


@pytest.mark.parametrize("grip", list(GRIPS))
def test_exact_output_is_the_library_call(capsys, exact, grip):
    c = exact[grip]
    data = simulate_json(capsys, "--grip", grip)
    # Same computation: equal to round-off.
    assert data["cor"] == pytest.approx(c.cor, rel=1e-13)
    assert data["contact_time_s"] == pytest.approx(c.contact_time, rel=1e-13)
    assert data["peak_force_n"] == pytest.approx(contact_peak(c), rel=1e-13)
    assert data["peak_grip_force_n"] == pytest.approx(grip_peak(c, DEFAULT_WINDOW), rel=1e-13)
    assert data["grip_vibration_rms_n"] == pytest.approx(
        vibration_rms(c, DEFAULT_WINDOW), rel=1e-13
    )
    assert data["rebound_speed_m_s"] == pytest.approx(-c.rebound_velocity, rel=1e-13)
    assert data["hand"] == json_ready(hand_summary(GRIPS[grip])) and data["hand"]["grip"] == grip
    assert data["modes"] == c.modes
    text = run_ok(capsys, "simulate", "--grip", grip)
    for name, value in [
        ("coefficient of restitution", significant(c.cor, 6)),
        ("contact time", significant(c.contact_time * 1e3, 5)),
        ("rebound speed", significant(-c.rebound_velocity, 5)),
        ("peak grip force", significant(grip_peak(c, DEFAULT_WINDOW), 4)),
        ("grip vibration RMS", significant(vibration_rms(c, DEFAULT_WINDOW), 4)),
        ("hand", f"{grip} grip"),
    ]:
        line = next(ln for ln in text.splitlines() if ln.startswith(name + " "))
        assert line.split()[len(name.split())] == value.split()[0], line


def test_cvode_output_is_the_library_call(capsys, standard_model):
    hand = GRIPS["firm"]
    ref = simulate_held(
        ImpactProblem.build(standard_model, hand=hand, position=0.6, speed=30.0), solver="cvode"
    )
    data = simulate_json(
        capsys, "--grip", "firm", "--solver", "cvode", "--position", "0.6", "--speed", "30"
    )
    assert data["cor"] == pytest.approx(ref.cor, rel=1e-12)
    assert data["contact_time_s"] == pytest.approx(ref.contact_time, rel=1e-12)
    # The peak forces are root-found between the output times (audit A7): at least the samples'.
    assert data["peak_force_n"] == pytest.approx(ref.peak_force, rel=1e-12)
    assert data["peak_force_n"] >= np.max(ref.contact_force) * (1 - 1e-12)
    # The window's peak covers the contact's samples and the free vibration after it.
    assert data["peak_grip_force_n"] >= np.max(np.abs(ref.grip_force)) * (1 - 1e-12)
    assert data["solver"] == "cvode" and data["modes"] == standard_model.fe.ndof + 2


# The integrators' shock measures do not depend on --output-step (audit A7: peaks root-found,
# the RMS exact between the samples; tests/impact/held/test_held_peak.py): ~1e-8 from the exact.
@pytest.mark.parametrize("grip", list(GRIPS))
def test_exact_and_cvode_agree_through_the_cli(capsys, tmp_path, grip):
    common = ("--grip", grip, "--position", "0.8")
    a = simulate_json(capsys, *common)
    out = tmp_path / "cvode.json"
    b = simulate_json(
        capsys, *common, "--solver", "cvode", "--out", str(out), "--output-step", "5e-7"
    )
    for key in ("cor", "contact_time_s", "rebound_speed_m_s", "peak_force_n"):
        assert b[key] == pytest.approx(a[key], rel=1e-6), key
    for key in ("peak_grip_force_n", "grip_vibration_rms_n"):
        assert b[key] == pytest.approx(a[key], rel=1e-6), key


@pytest.mark.parametrize("solver", ["cvode", pytest.param("bdf", marks=pytest.mark.slow)])
def test_exact_and_integrators_agree_for_a_swinging_held_racket(capsys, solver):
    # The swing is superposed on the stationary impact at the closing speed (exact) or the
    # integration starts from the swing's velocity field, hand included (cvode, bdf): they agree to
    # the integrator's tolerance; v_out = e_A v_in + (1 + e_A) v_r (Brody, Cross & Lindsey
    # 2002, ch. 11). Shock measures root-found / exact between the 1e-5 s samples (audit A7):
    # within 5e-8 (the exact peak's own grid and zoom ~1e-8; they were 1e-3 apart when sampled).
    swing = ("--grip", "firm", "--racket-speed", "15", "--pivot", "0.08", "--speed", "25")
    a = simulate_json(capsys, *swing)
    b = simulate_json(capsys, *swing, "--solver", solver)
    v_r = a["racket_speed_at_impact_m_s"]
    assert v_r == pytest.approx(Swing.from_speed(15.0, 0.68, pivot=0.08).speed_at(0.75 * 0.68))
    e = a["apparent_cor"]
    assert a["ball_speed_out_m_s"] == pytest.approx(e * 25.0 + (1 + e) * v_r, rel=1e-14)
    for key in ("apparent_cor", "ball_speed_out_m_s", "contact_time_s"):
        assert b[key] == pytest.approx(a[key], rel=1e-6), key
    for key in ("peak_grip_force_n", "grip_vibration_rms_n"):
        assert b[key] == pytest.approx(a[key], rel=5e-8), key
    # The closing speed sets K_CB: the same impact as a racket at rest struck at v_in + v_r.
    still = simulate_json(capsys, "--grip", "firm", "--speed", str(25.0 + v_r))
    assert still["cor"] == pytest.approx(a["apparent_cor"], rel=1e-12)
    assert still["peak_grip_force_n"] == pytest.approx(a["peak_grip_force_n"], rel=1e-12)


def test_out_writes_histories_and_the_hand_in_the_provenance(capsys, tmp_path, standard_model):
    out = tmp_path / "held.csv"
    custom = ("--grip", "loose", "--grip-damping", "150", "--shock-window", "0.02")
    run_ok(capsys, "simulate", *custom, "--out", str(out))
    meta = json.loads((tmp_path / "held.csv.json").read_text())
    hand = Hand(stiffness=1e5, damping=150.0)
    assert meta["used"]["hand"] == json_ready(hand_summary(hand))
    assert meta["used"]["hand"]["grip"] == "custom"
    assert meta["used"]["shock_window_s"] == 0.02
    assert meta["parameters"]["grip_damping"] == 150.0
    assert meta["summary"]["grip_vibration_rms_n"] == meta["results"]["grip_vibration_rms_n"]
    with open(out, newline="") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], np.array(rows[1:], dtype=float)
    assert header == [
        "time [s]",
        "contact force [N]",
        "grip force [N]",
        "grip force rigid part [N]",
        "grip force vibration part [N]",
    ]
    t = data[:, 0]
    c = held_contact(held_basis(standard_model.fe, hand), tolerance=None)
    assert t[-1] == pytest.approx(0.02) and np.any(t == c.contact_time)
    grip, rigid = c.grip_force(t)
    np.testing.assert_allclose(data[:, 2], grip, rtol=0, atol=1e-12 * np.max(np.abs(grip)))
    np.testing.assert_allclose(data[:, 4], data[:, 2] - data[:, 3], rtol=0, atol=1e-12)
    assert np.all(data[t > c.contact_time, 1] == 0.0) and np.all(data[t > c.contact_time, 3] == 0)


def test_run_file_round_trip(capsys, tmp_path):
    f = tmp_path / "run.toml"
    f.write_text(
        '[hand]\ngrip = "firm"\nmass_kg = 0.4\ngrip_end_m = 0.11\nshock_window_s = 0.03\n'
        "[impact]\nspeed_m_s = 30.0\n"
    )
    from_file = simulate_json(capsys, "--config", str(f))
    argv = ("--grip", "firm", "--hand-mass", "0.4", "--grip-end", "0.11", "--speed", "30")
    assert from_file == simulate_json(capsys, *argv, "--shock-window", "0.03")
    assert from_file["hand"]["mass_kg"] == 0.4 and from_file["shock_window_s"] == 0.03
    # The command line overrides the file.
    assert (
        simulate_json(capsys, "--config", str(f), "--grip-end", "0.12")["hand"]["grip_end_m"]
        == 0.12
    )
    check = run_ok(capsys, "config", "--check", str(f))
    assert 'hand_grip = "firm"' in check and "grip_end = 0.11" in check


def test_without_a_hand_simulate_is_unchanged(capsys):
    data = simulate_json(capsys)
    assert "hand" not in data and "peak_grip_force_n" not in data
