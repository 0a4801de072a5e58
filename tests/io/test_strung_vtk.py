"""The strung impact as a VTK series: frame, ball and the string bed as a deforming surface."""

import json

import numpy as np
import pytest

from fem_racket.impact.strung.impact import simulate_strung
from fem_racket.io.strung_vtk import strung_fields, write_strung_vtk
from fem_racket.strings.bed import StringBed
from fem_racket.strings.membrane import bed_mesh, disk_load


@pytest.fixture(scope="module")
def strung(standard_model):
    return simulate_strung(standard_model, StringBed(tension_n=240.0), position=0.78, speed=25.0)


def test_bed_field_is_the_bed_at_the_point(strung, standard_model):
    # The drawn bed, averaged over the ball's disk, is the frame's deflection at the impact
    # point plus the bed's deflection there (the shapes' values at the point are the a_j the
    # integrator used; the pseudo-mode's shape is its static residual, scaled to a_p).
    p = strung.point
    mesh = bed_mesh(p.strings.head_length_m, p.strings.head_width_m, p.refine)
    x = (p.position - 0.74) * standard_model.mesh.length
    q = disk_load(mesh, np.array([[x, 0.0]]), p.strings.load_radius_m)[:, 0]
    eta = strung.coordinates[:, 1:][:, p.bed]
    assert np.allclose((eta @ p.bed_shapes.T) @ q, strung.bed_deflection, rtol=0, atol=1e-12)
    nodes, bed = strung_fields(strung, standard_model)
    assert nodes.shape == (strung.t.size, standard_model.mesh.n_elements + 1)
    assert bed.shape == (strung.t.size, mesh.basis.mesh.p.shape[1])
    # the edge moves as one, with the frame's deflection at the impact point
    frame = strung.coordinates[:, 1:][:, ~p.bed] @ standard_model.modes(None).all_shapes.T
    w_i = frame @ standard_model.fe.point_vector(p.position * standard_model.mesh.length)
    edge = bed[:, mesh.basis.mesh.boundary_nodes()]
    assert np.allclose(edge, w_i[:, None], rtol=0, atol=1e-15)
    assert np.abs(w_i).max() > 1e-4  # the frame does move


def test_series_opens_in_pyvista(strung, standard_model, tmp_path):
    import pyvista as pv

    path = write_strung_vtk(strung, standard_model, tmp_path / "vtk", frames=5)
    reader = pv.get_reader(str(path))
    assert reader.time_values[0] == 0.0
    assert reader.time_values[-1] == pytest.approx(strung.contact_time, rel=1e-12)
    reader.set_active_time_point(2)
    parts = reader.read()
    assert len(parts) == 3
    bed = parts[2]
    assert bed.n_cells == 1024 and "deflection [m]" in bed.point_data
    assert 'name="strings"' in path.read_text()
    meta = json.loads((path.parent / "provenance.json").read_text())
    assert meta["parameters"]["stringbed_stiffness_n_m"] == strung.point.bed_stiffness


def test_hoop_edge_follows_the_frame_along_the_head(standard_model):
    # edge "hoop": each edge point of the drawn bed moves with the frame's deflection at its x
    r = simulate_strung(standard_model, StringBed(edge="hoop"), position=0.8, speed=25.0)
    p = r.point
    mesh = bed_mesh(p.strings.head_length_m, p.strings.head_width_m, p.refine)
    nodes, bed = strung_fields(r, standard_model)
    frame = r.coordinates[:, 1:][:, ~p.bed] @ standard_model.modes(None).all_shapes.T
    L = standard_model.mesh.length
    vertices = mesh.basis.mesh.p
    edge = mesh.basis.mesh.boundary_nodes()
    w_edge = (
        frame
        @ standard_model.fe.field_matrix(
            p.strings.head_centre * L + vertices[0, edge], 0
        ).T.toarray()
    )
    assert np.allclose(bed[:, edge], w_edge, rtol=0, atol=1e-14)
