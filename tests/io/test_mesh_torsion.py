"""Mesh files with torsion cell data GJ and rhoIp, and ``modes`` reporting torsion."""

import meshio
import numpy as np
import pytest

from fem_racket.frame.mesh import frame_mesh
from fem_racket.frame.segments import standard_frame
from fem_racket.io.mesh_files import read_mesh, write_mesh
from fem_racket.validation import InputError
from tests.clirun import run, run_json


def test_round_trip_keeps_torsion(tmp_path):
    mesh = frame_mesh(standard_frame(), 25)
    back = read_mesh(write_mesh(mesh, tmp_path / "m.vtu"))
    for k in ("points", "EI", "rhoA", "GJ", "rhoIp"):
        assert np.array_equal(getattr(back, k), getattr(mesh, k))


def test_one_torsion_array_alone_is_refused(tmp_path):
    mesh = frame_mesh(standard_frame(), 4)
    pts = np.zeros((5, 3))
    pts[:, 0] = mesh.points
    cells = [("line", np.column_stack([np.arange(4), np.arange(1, 5)]))]
    data = {"EI": [mesh.EI], "rhoA": [mesh.rhoA], "GJ": [mesh.GJ]}
    meshio.write(tmp_path / "m.vtu", meshio.Mesh(pts, cells, cell_data=data))
    with pytest.raises(InputError, match="cell data 'GJ' without 'rhoIp'"):
        read_mesh(tmp_path / "m.vtu")


def test_modes_reports_twist_weight_and_torsion_frequencies(capsys):
    data = run_json(capsys, "modes", "--count", "2")
    # the standard racket's assumed torsion (fem_racket.frame.segments.STANDARD_TORSION)
    assert data["twist_weight_kg_cm2"] == pytest.approx(17.4896, rel=1e-12)
    assert data["polar_moment_kg_m2"] == pytest.approx(17.4896e-4, rel=1e-12)
    assert len(data["torsion_frequencies_hz"]) == 2
    assert 300 < data["torsion_frequencies_hz"][0] < 450
    code, out, _ = run(capsys, "modes")
    assert "17.49 kg cm^2" in out and "380.34" in out
