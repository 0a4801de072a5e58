"""The assembled frame without scipy or scikit-fem: DOF numbering, diagonals, products.

Impacts and modes run on :class:`~fem_racket.frame.fe.FrameFE`'s diagonals (no scipy.sparse, no
scikit-fem: the command line starts faster, tests/cli/test_startup.py); these tests hold them to
the sparse matrices and to scikit-fem's assembly they replace.
"""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.frame.fe import FrameFE, nodal_dofs
from fem_racket.frame.forms import assemble
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.mesh import frame_mesh, graded_mesh
from fem_racket.frame.segments import standard_frame


@pytest.fixture(params=["uniform", "graded"])
def mesh(request):
    if request.param == "uniform":
        return frame_mesh(standard_frame(), 20)
    return graded_mesh(standard_frame(), 24)


def test_dofs_are_numbered_as_scikit_fem_numbers_them(mesh):
    fe = assemble_closed_form(mesh)
    u, ux = nodal_dofs(mesh.points.size)
    assert np.array_equal(fe.basis.nodal_dofs, np.vstack([u, ux]))
    assert fe.ndof == fe.basis.N


def test_closed_form_matrices_match_scikit_fem(mesh):
    # the same integrals; scikit-fem's global-monomial shape functions lose ~4e-12 (relative,
    # largest entry) at 20 elements (measured, fem_racket/frame/hermite.py), so 1e-10
    exact, fem = assemble_closed_form(mesh), assemble(mesh)
    for a, b in ((exact.K, fem.K), (exact.M, fem.M)):
        assert abs(a - b).max() <= 1e-10 * abs(b).max()
        # the same stored couplings, so sparse solvers see the same pattern
        assert np.array_equal(a.indptr, b.indptr) and np.array_equal(a.indices, b.indices)


def test_diagonals_round_trip_through_the_sparse_matrices(mesh):
    fe = assemble(mesh)
    again = FrameFE.from_matrices(mesh, fe.K, fe.M)
    for a, b in ((again.K, fe.K), (again.M, fe.M)):
        assert np.array_equal(a.indptr, b.indptr) and np.array_equal(a.indices, b.indices)
        assert np.array_equal(a.data, b.data)


def test_mass_product_is_the_sparse_product_to_the_bit(mesh):
    fe = assemble_closed_form(mesh)
    q = np.random.default_rng(7).standard_normal((fe.ndof, 5))
    assert np.array_equal(fe.mass_product(q), fe.M @ q)
    assert np.array_equal(fe.mass_product(q[:, 0]), fe.M @ q[:, 0])


def test_field_values_are_the_sparse_product_to_the_bit(mesh):
    fe = assemble_closed_form(mesh)
    q = np.random.default_rng(8).standard_normal((fe.ndof, 3))
    x = np.array([0.0, 0.1234, mesh.points[7], mesh.length])
    for order in (0, 1, 2):
        assert np.array_equal(fe.field_values(x, q, order), fe.field_matrix(x, order) @ q)
        assert np.array_equal(
            fe.field_values(x, q[:, 1], order), fe.field_matrix(x, order) @ q[:, 1]
        )
    assert np.array_equal(fe.point_vector(0.3), fe.field_matrix(np.array([0.3])).toarray()[0])


def test_scaled_model_scales_the_stiffness_alone():
    from fem_racket.frame.model import FrameModel

    model = FrameModel.build(standard_frame(), 20)
    scaled = model.scaled(2.5)
    assert np.array_equal(scaled.fe.K.toarray(), model.fe.K.toarray() * 2.5)
    assert np.array_equal(scaled.fe.M.toarray(), model.fe.M.toarray())
