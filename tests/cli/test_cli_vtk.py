"""``export-vtk`` and ``animate`` in-process: exit codes, files written, nothing partial."""

import json

import numpy as np
import pytest
import pyvista as pv
from clirun import refused_before_any_file, run

from fem_racket import simulate


def test_export_vtk_writes_the_simulated_impact(capsys, tmp_path, standard_model):
    out = tmp_path / "vtk"
    code, stdout, err = run(
        capsys, "export-vtk", "--out", out, "--position", 0.6, "--speed", 30,
        "--frames", 12, "--subdivide", 4, "--scale", 3, "--field", "moment",
    )  # fmt: skip
    assert code == 0, err
    n = len(list(out.iterdir()))  # 12 frames and 12 balls, the .pvd and provenance.json
    assert (n, stdout) == (26, f"wrote {out}/ (26 files; open impact.pvd in ParaView)\n")
    expected = simulate(standard_model, position=0.6, speed=30.0)
    reader = pv.get_reader(str(out / "impact.pvd"))
    assert reader.number_time_points == 12
    assert reader.time_values[-1] == expected.contact_time
    reader.set_active_time_point(11)
    frame = reader.read()[0]
    assert frame.active_scalars_name == "bending moment [N m]"
    j = int(np.argmin(np.abs(frame.points[:, 0] - expected.x_impact)))
    w = expected.impact_point_displacement[-1]
    assert frame.point_data["deflection [m]"][j] == pytest.approx(w, rel=1e-12)
    assert frame.points[j, 2] == pytest.approx(3 * w, rel=1e-12)
    meta = json.loads((out / "provenance.json").read_text())
    assert meta["used"]["speed_m_s"] == 30.0 and meta["parameters"]["subdivide"] == 4


def test_animate_gif(capsys, tmp_path):
    out = tmp_path / "a.gif"
    code, stdout, err = run(
        capsys, "animate", "--out", out, "--frames", 3, "--size", "320x160", "--fps", 5
    )
    assert code == 0, err
    assert out.is_file() and (tmp_path / "a.gif.json").is_file()
    assert json.loads((tmp_path / "a.gif.json").read_text())["parameters"]["fps"] == 5.0


def test_animate_needs_gif_or_mp4(capsys, cwd):
    line = refused_before_any_file(capsys, "animate", "--out", "a.avi")
    assert "must end in .gif or .mp4" in line


@pytest.mark.parametrize("command", ["export-vtk", "animate"])
def test_existing_output_needs_overwrite(capsys, tmp_path, command):
    out = tmp_path / ("out" if command == "export-vtk" else "a.gif")
    small = ["--frames", "2"] + (["--size", "160x160"] if command == "animate" else [])
    assert run(capsys, command, "--out", out, *small)[0] == 0
    before = sorted(p.name for p in tmp_path.rglob("*"))
    code, _, err = run(capsys, command, "--out", out, *small)
    assert code == 2 and "--overwrite" in err
    assert sorted(p.name for p in tmp_path.rglob("*")) == before
    assert run(capsys, command, "--out", out, *small, "--overwrite")[0] == 0
    assert sorted(p.name for p in tmp_path.rglob("*")) == before
