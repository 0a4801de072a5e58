"""VTK time series: written, then read back with meshio and pyvista against the simulation."""

import json

import meshio
import numpy as np
import pytest
import pyvista as pv
from scipy.interpolate import CubicHermiteSpline

from fem_racket import InputError, impact_series, simulate, write_vtk_series
from fem_racket.io.vtk_series import BALL_RADIUS, FRAME_FIELDS, field_name
from fem_racket.io.vtk_steps import sample_steps
from fem_racket.outputs import json_ready

# 0.769 L is a node of mode 1 and not a mesh node with 20 elements (nodes every L/20).
POSITION = 0.769
# Values are stored as float64 and computed by the same formulas: only round-off differs.
# 1e-12 relative is ~1e4 ulp of slack for the sums inside the Hermite evaluation.
RTOL = 1e-12


@pytest.fixture(scope="module")
def result(standard_model):
    # 5e-5 s output step: ~80 steps, enough to test every step quickly.
    return simulate(standard_model, position=POSITION, output_step=5e-5)


@pytest.fixture(scope="module")
def export(result, tmp_path_factory):
    folder = tmp_path_factory.mktemp("vtk") / "impact"
    pvd = write_vtk_series(result, folder, subdivide=6)
    return folder, pvd


def _frame_and_ball(reader, k):
    reader.set_active_time_point(k)
    blocks = reader.read()
    assert blocks.n_blocks == 2
    return blocks[0], blocks[1]


def _impact_point(grid, x_i):
    hit = np.flatnonzero(np.abs(grid.points[:, 0] - x_i) < 1e-12)
    assert hit.size == 1, "the impact point must be a point of the polyline"
    return int(hit[0])


def test_pyvista_reads_every_step_at_the_simulation_times(result, export):
    _, pvd = export
    reader = pv.get_reader(str(pvd))
    assert reader.number_time_points == result.t.size
    np.testing.assert_array_equal(reader.time_values, result.t)  # exact: repr() round-trips


def test_pyvista_impact_point_deflection_equals_history(result, export):
    _, pvd = export
    reader = pv.get_reader(str(pvd))
    x_i = result.x_impact
    w_i = result.impact_point_displacement
    for k in (0, 1, result.t.size // 3, result.t.size // 2, result.t.size - 1):
        frame, ball = _frame_and_ball(reader, k)
        j = _impact_point(frame, x_i)
        assert frame.point_data["deflection [m]"][j] == pytest.approx(w_i[k], rel=RTOL, abs=1e-15)
        assert frame.points[j, 2] == pytest.approx(w_i[k], rel=RTOL, abs=1e-15)  # scale 1
        assert frame.field_data["TimeValue"][0] == result.t[k]
        # The ball: a sphere of radius R_B around (x_i, 0, u_B - R_B), carrying v_B and F.
        lo, hi = np.array(ball.bounds).reshape(3, 2).T
        centre = 0.5 * (lo + hi)
        np.testing.assert_allclose(
            centre, [x_i, 0.0, result.ball_displacement[k] - BALL_RADIUS], atol=1e-12
        )
        np.testing.assert_allclose(hi[2] - lo[2], 2 * BALL_RADIUS, rtol=1e-12)
        assert ball.point_data["ball velocity [m/s]"][0] == result.ball_velocity[k]
        # One colour map for both blocks: the ball carries its own displacement as deflection.
        assert ball.point_data["deflection [m]"][0] == result.ball_displacement[k]
        assert (
            "frame velocity [m/s]" in frame.point_data and "velocity [m/s]" not in ball.point_data
        )
        assert ball.point_data["contact force [N]"][0] == result.force[k]


def test_meshio_reads_every_file_with_fields_and_times(result, export):
    folder, _ = export
    frames = sorted(folder.glob("frame_*.vtu"))
    balls = sorted(folder.glob("ball_*.vtu"))
    assert len(frames) == len(balls) == result.t.size
    w_i = result.impact_point_displacement
    for k in (0, result.t.size // 2, result.t.size - 1):
        m = meshio.read(frames[k])
        assert set(m.point_data) == {"deflection [m]", "slope [rad]", "frame velocity [m/s]"}
        assert set(m.cell_data) == {"curvature [1/m]", "bending moment [N m]", "EI [N m^2]"}
        assert m.field_data["TimeValue"][0] == result.t[k]
        j = _impact_point(m, result.x_impact)
        assert m.point_data["deflection [m]"][j] == pytest.approx(w_i[k], rel=RTOL, abs=1e-15)
        b = meshio.read(balls[k])
        assert b.point_data["contact force [N]"][0] == result.force[k]


def test_polyline_is_the_hermite_interpolant(result, export):
    """Against scipy's cubic Hermite spline through the FE nodal deflections and slopes."""
    folder, _ = export
    fe = result.model.fe
    nodes = result.model.mesh.points
    k = result.t.size // 2
    q = result.frame_displacement[k]
    spline = CubicHermiteSpline(nodes, q[fe.deflection_dofs], q[fe.slope_dofs])
    m = meshio.read(folder / f"frame_{k:04d}.vtu")
    x = m.points[:, 0]
    assert x.size == 6 * (nodes.size - 1) + 2  # 6 segments per element + the impact point
    scale = np.abs(spline(x)).max()
    np.testing.assert_allclose(m.point_data["deflection [m]"], spline(x), atol=1e-12 * scale)
    slope = spline.derivative()(x)
    np.testing.assert_allclose(m.point_data["slope [rad]"], slope, atol=1e-12 * np.abs(slope).max())
    # Curvature and moment per segment, at its midpoint; EI of the element holding it.
    mid = 0.5 * (x[1:] + x[:-1])
    kappa = spline.derivative(2)(mid)
    curv = m.cell_data["curvature [1/m]"][0]
    np.testing.assert_allclose(curv, kappa, atol=1e-9 * np.abs(kappa).max())
    EI = m.cell_data["EI [N m^2]"][0]
    np.testing.assert_array_equal(np.unique(EI), np.unique(result.model.mesh.EI))
    np.testing.assert_allclose(m.cell_data["bending moment [N m]"][0], EI * curv, rtol=1e-15)
    # Not straight lines between nodes: inside elements the shape differs from the chord.
    chord = np.interp(x, nodes, q[fe.deflection_dofs])
    assert np.abs(m.point_data["deflection [m]"] - chord).max() > 1e-3 * scale


def test_provenance_sidecar(result, export):
    folder, _ = export
    meta = json.loads((folder / "provenance.json").read_text())
    assert meta["software"] == "fem_racket"
    params = meta["parameters"]
    assert meta["results"]["cor"] == result.cor
    assert meta["used"] == json_ready(result.settings())  # 27400.0, not 27399.999999999993
    assert meta["used"]["position_x_over_l"] == POSITION
    assert params["steps"] == result.t.size
    assert params["time_s"] == result.t.tolist()
    assert set(FRAME_FIELDS) <= set(params["frame_fields"])


def test_frames_keep_first_and_last(result, tmp_path):
    pvd = write_vtk_series(result, tmp_path / "few", frames=7, scale=5.0)
    reader = pv.get_reader(str(pvd))
    assert reader.number_time_points == 7
    t = np.array(reader.time_values)
    assert t[0] == 0.0 and t[-1] == result.contact_time
    assert np.all(np.isin(t, result.t))
    frame, _ = _frame_and_ball(reader, 6)
    j = _impact_point(frame, result.x_impact)
    w = result.impact_point_displacement[-1]
    assert frame.points[j, 2] == pytest.approx(5.0 * w, rel=RTOL)  # geometry exaggerated
    assert frame.point_data["deflection [m]"][j] == pytest.approx(w, rel=RTOL)  # field true


def test_exaggerated_ball_keeps_its_true_compression(result):
    s = impact_series(result, frames=5, scale=10.0)
    w_i = result.impact_point_displacement[s.steps]
    delta = result.deflection[s.steps]
    np.testing.assert_allclose(s.ball_z + BALL_RADIUS - 10.0 * w_i, delta, atol=1e-15)


def test_sample_steps():
    np.testing.assert_array_equal(sample_steps(5), np.arange(5))
    np.testing.assert_array_equal(sample_steps(11, 3), [0, 5, 10])
    for bad in (1, 12, 2.5, True):
        with pytest.raises(InputError, match="frames"):
            sample_steps(11, bad)


def test_field_names():
    assert field_name("moment") == "bending moment [N m]"
    assert field_name("curvature [1/m]") == "curvature [1/m]"
    with pytest.raises(InputError, match="field = 'stress'"):
        field_name("stress")


def test_existing_output_is_refused_then_replaced(result, tmp_path):
    folder = tmp_path / "out"
    write_vtk_series(result, folder, frames=3)
    stamp = (folder / "provenance.json").read_text()
    with pytest.raises(InputError, match="already exists"):
        write_vtk_series(result, folder, frames=4)
    assert (folder / "provenance.json").read_text() == stamp
    write_vtk_series(result, folder, frames=4, overwrite=True)
    assert len(list(folder.glob("frame_*.vtu"))) == 4
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]  # no temporaries left


def test_overwrite_never_deletes_a_foreign_folder(result, tmp_path):
    (tmp_path / "mine.txt").write_text("keep")
    with pytest.raises(InputError, match="not one this program wrote"):
        write_vtk_series(result, tmp_path, frames=3, overwrite=True)
    assert (tmp_path / "mine.txt").read_text() == "keep"


def test_bad_input_leaves_nothing(result, tmp_path):
    for kwargs in ({"frames": 10_000}, {"scale": -1.0}, {"subdivide": 0}, {"field": "x"}):
        with pytest.raises(InputError):
            write_vtk_series(result, tmp_path / "out", **kwargs)
    assert list(tmp_path.iterdir()) == []


def test_vtu_files_are_the_bytes_pyvista_would_write(result, export, tmp_path):
    # Written by Python from VTK's in-memory output (so a full disk is an OSError, not a crash
    # inside VTK): the same file as pyvista's own save, byte for byte.
    folder, _ = export
    series = impact_series(result, subdivide=6)
    series.ball_grid(3).save(tmp_path / "ball.vtu")
    assert (folder / "ball_0003.vtu").read_bytes() == (tmp_path / "ball.vtu").read_bytes()
