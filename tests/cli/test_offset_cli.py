"""--offset on simulate, export-vtk and run files; refused with a hand (issue 24)."""

import numpy as np
import pytest

from tests.clirun import run, run_json


def test_simulate_offset_prints_roll_and_torsion(capsys):
    s = run_json(capsys, "simulate", "--position", "0.74", "--offset", "0.05")
    assert s["offset_m"] == 0.05
    # rigid roll of the angular impulse: I_p Omega = y m_B (V + v_out), I_p = 17.4896 kg cm^2
    J = 0.057 * (20.0 + s["rebound_speed_m_s"])
    assert s["roll_rate_rad_s"] == pytest.approx(0.05 * J / 17.4896e-4, rel=1e-9)
    assert 0.0 < s["torsion_energy_share"] < 1.0
    code, out, _ = run(capsys, "simulate", "--position", "0.74", "--offset", "-0.05")
    assert code == 0 and "roll rate after impact" in out and "-" in out.split("roll rate")[1]
    assert "offset_m" not in run_json(capsys, "simulate", "--position", "0.74")  # today's output


def test_offset_refusals(capsys):
    code, _, err = run(capsys, "simulate", "--offset", "0.05", "--grip", "firm")
    assert code == 2 and "not allowed with a hand" in err
    code, _, err = run(capsys, "simulate", "--position", "0.3", "--offset", "0.01")
    assert code == 2 and err.count("\n") == 1 and "face spans x" in err


def test_run_file_offset(capsys, tmp_path):
    f = tmp_path / "run.toml"
    f.write_text("[impact]\nposition_x_over_l = 0.74\noffset_m = 0.04\n", encoding="utf-8")
    assert run_json(capsys, "simulate", "--config", f)["offset_m"] == 0.04


def test_export_vtk_writes_the_twist(capsys, tmp_path):
    import pyvista as pv

    out = tmp_path / "vtk"
    code, _, _ = run(capsys, "export-vtk", "--position", "0.74", "--offset", "0.05", "--out", out)
    assert code == 0
    frame = pv.read(sorted(out.glob("frame_*.vtu"))[-1])
    ball = pv.read(sorted(out.glob("ball_*.vtu"))[-1])
    assert np.max(np.abs(frame.point_data["twist [rad]"])) > 0.0
    assert ball.center[1] == pytest.approx(0.05, abs=1e-12)  # the ball at its offset
    # the face as a surface: z = w(x) + y theta(x), so across the face z changes by y theta
    face = pv.read(sorted(out.glob("face_*.vtu"))[-1])
    pts, z, th = face.points, face.point_data["displacement [m]"], face.point_data["twist [rad]"]
    x0 = pts[np.argmax(pts[:, 1]), 0]  # the widest station: its two rim points
    row = np.isclose(pts[:, 0], x0)
    hi, lo = np.argmax(np.where(row, pts[:, 1], -1)), np.argmin(np.where(row, pts[:, 1], 1))
    assert z[hi] - z[lo] == pytest.approx((pts[hi, 1] - pts[lo, 1]) * th[hi], rel=1e-12)
    assert "face_0000.vtu" in (out / "impact.pvd").read_text()


def test_fit_twist_weight_round_trips_through_modes(capsys, tmp_path):
    out = tmp_path / "r.vtu"
    spec = ["--length", "0.685", "--mass", "0.318", "--balance", "0.320", "--swing-weight", "316"]
    code, _, _ = run(capsys, "fit", *spec, "--twist-weight", "16", "--torsion-frequency", "400",
                     "--out", out)  # fmt: skip
    assert code == 0
    m = run_json(capsys, "modes", "--mesh", out)
    assert m["twist_weight_kg_cm2"] == pytest.approx(16.0, rel=1e-12)  # cells keep I_p exactly
    # the exact stepped shaft has 400 Hz; P2 elements on the 40-cell mesh within 1e-5
    assert m["torsion_frequencies_hz"][0] == pytest.approx(400.0, rel=1e-5)
    code, _, err = run(capsys, "fit", *spec, "--twist-weight", "60", "--out", tmp_path / "x.vtu")
    assert code == 2 and "must lie in (0, 50.49] kg cm^2" in err
    code, _, err = run(capsys, "fit", *spec, "--torsion-frequency", "400", "--out",
                       tmp_path / "y.vtu")  # fmt: skip
    assert code == 2 and "without --twist-weight" in err
