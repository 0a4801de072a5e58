"""Torsion of the frame: FE modes against the exact stepped shaft, polar moment, cell data."""

import numpy as np
import pytest

from fem_racket.frame.mesh import FrameMesh, frame_from_mesh, frame_mesh, insert_nodes
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import (
    STANDARD_TORSION,
    Frame,
    Segment,
    TorsionSegment,
    standard_frame,
)
from fem_racket.frame.torsion import TorsionModel
from fem_racket.frame.torsion_exact import torsion_frequencies
from fem_racket.validation import InputError

# A stepped shaft with its torsion steps on the bending steps (nodes of every mesh below).
SHAFT = Frame(
    (Segment(0.2, 100.0, 0.7), Segment(0.3, 100.0, 0.5), Segment(0.2, 100.0, 0.5)),
    (TorsionSegment(0.2, 150.0, 2e-4), TorsionSegment(0.3, 400.0, 1e-3),
     TorsionSegment(0.2, 300.0, 5e-3)),
)  # fmt: skip


def test_exact_uniform_shaft():
    # free-free uniform shaft: omega_n = n pi sqrt(GJ / rhoIp) / L (any vibration text)
    f = torsion_frequencies([TorsionSegment(0.5, 10.0, 1e-3)], 4)
    np.testing.assert_allclose(f, np.arange(1, 5) * 100.0 / 2 / 0.5, rtol=1e-13)


@pytest.mark.parametrize("order", [1, 2])
def test_frequencies_converge_at_the_elements_order(order):
    # Lagrange elements of order p: eigenvalue error O(h^2p) (Strang & Fix 1973, ch. 6)
    exact = torsion_frequencies(SHAFT.torsion, 4)
    errors = []
    for n in (14, 28, 56):
        tm = TorsionModel(frame_mesh(SHAFT, n), order)
        errors.append(np.abs(tm.modes(4).frequencies - exact) / exact)
    rates = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(rates > 2 * order - 0.2) and np.all(rates[-1] > 2 * order - 0.1), rates
    assert np.all(errors[-1] < (5e-3 if order == 1 else 2e-5))


def test_modes_are_mass_normalised_and_totals_match_the_modal_sums():
    tm = TorsionModel(frame_mesh(SHAFT, 14))
    m = tm.modes()
    K, M = tm.matrices
    np.testing.assert_allclose(m.shapes.T @ (M @ m.shapes), np.eye(m.omega.size), atol=1e-10)
    assert tm.polar_moment == pytest.approx(0.2 * 2e-4 + 0.3 * 1e-3 + 0.2 * 5e-3, rel=1e-14)
    one = np.ones(tm.ndof)
    assert one @ (M @ one) == pytest.approx(tm.polar_moment, rel=1e-13)  # the roll is exact
    assert np.abs(K @ one).max() < 1e-9
    x = np.array([0.05, 0.33, 0.61])
    th = tm.point_matrix(x) @ m.shapes
    totals = tm.static_totals(x)
    np.testing.assert_allclose(totals[:, 0], (th**2 / m.omega**2).sum(axis=1), rtol=1e-9)
    np.testing.assert_allclose(totals[:, 1], (th**2).sum(axis=1), rtol=1e-9)


def test_sparse_solver_agrees_with_dense(monkeypatch):
    import fem_racket.frame.torsion as torsion

    dense = TorsionModel(frame_mesh(SHAFT, 28)).modes(5)
    monkeypatch.setattr(torsion, "DENSE_LIMIT", 10)
    sparse = TorsionModel(frame_mesh(SHAFT, 28)).modes(5)
    np.testing.assert_allclose(sparse.omega, dense.omega, rtol=1e-10)
    np.testing.assert_allclose(np.abs(sparse.shapes), np.abs(dense.shapes), atol=1e-7)
    # and repeats to the last bit: Lanczos starts from a fixed vector (fem_racket.lanczos)
    again = TorsionModel(frame_mesh(SHAFT, 28)).modes(5)
    assert np.array_equal(again.omega, sparse.omega) and np.array_equal(again.shapes, sparse.shapes)


def test_standard_racket_assumptions_in_the_literature_ranges():
    tm = FrameModel.build().torsion
    # twistweight 15-20 kg cm^2: Rogowski et al. 2014 (PLoS ONE e104785) measured 15.2 and 19.7
    assert 15.0 <= tm.polar_moment * 1e4 <= 20.0
    # first free-free torsion frequency 300-450 Hz (DESIGN section 10, typical range)
    f1 = torsion_frequencies(STANDARD_TORSION, 1)[0]
    assert 300.0 <= f1 <= 450.0
    assert tm.modes(1).frequencies[0] == pytest.approx(f1, rel=1e-4)


def test_cell_data_follow_the_mesh():
    mesh = frame_mesh(standard_frame(), 25)  # 0.5 L is no node: a mixed cell
    ip = float(np.sum(mesh.rhoIp * np.diff(mesh.points)))
    exact = sum(s.length * s.rhoIp for s in STANDARD_TORSION)
    assert ip == pytest.approx(exact, rel=1e-14)  # the polar moment is kept exactly
    finer = insert_nodes(mesh, [0.61])
    assert finer.GJ.size == mesh.GJ.size + 1
    back = frame_from_mesh(frame_mesh(standard_frame(), 20))
    for got, want in zip(back.torsion, STANDARD_TORSION, strict=True):
        assert (got.GJ, got.rhoIp) == (want.GJ, want.rhoIp)
        assert got.length == pytest.approx(want.length, rel=1e-14)
    assert FrameModel.build().scaled(2.0).torsion.polar_moment == pytest.approx(exact)


def test_refusals():
    with pytest.raises(InputError, match="only one given"):
        FrameMesh([0.0, 1.0], [1.0], [1.0], GJ=[1.0])
    with pytest.raises(InputError, match="GJ / rhoIp"):
        FrameMesh([0.0, 1.0], [1.0], [1.0], GJ=[1e20], rhoIp=[1.0])
    with pytest.raises(InputError, match="must equal the frame's"):
        Frame((Segment(0.5, 1.0, 1.0),), (TorsionSegment(0.4, 1.0, 1e-3),))
    with pytest.raises(InputError, match="no cell data GJ"):
        _ = FrameModel.build(Frame((Segment(0.5, 1.0, 1.0),))).torsion
