"""Fine meshes: exact curvature coordinates, h^4 convergence to a round-off floor, determinism,
COR and t_c converged at every accepted element count, and the element limit (issue 12)."""

import time

import numpy as np
import pytest

from fem_racket import FrameMesh, FrameModel, frame_mesh, simulate, standard_frame
from fem_racket.frame import curvature
from fem_racket.frame.continuous import free_free_frequencies
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.mesh import MAX_ELEMENTS
from fem_racket.frame.modal import free_modes, mass_properties
from fem_racket.validation import AccuracyError, InputError


def _coordinates(elements: int) -> curvature._Coordinates:
    fe = assemble_closed_form(frame_mesh(standard_frame(), elements))
    props = mass_properties(fe)
    rigid = np.column_stack(
        [
            fe.rigid_motion(1.0, 0.0) / np.sqrt(props.mass),
            fe.rigid_motion(0.0, 1.0, about=props.cg) / np.sqrt(props.inertia),
        ]
    )
    return curvature._Coordinates(fe, rigid)


def test_curvature_coordinates_are_exact():
    # T_c (cumulative sums) and its transpose (reverse sums) are adjoint, and the assembled K in
    # these coordinates is the closed-form block diagonal EI h / 3 [[1, 1/2], [1/2, 1]].
    c = _coordinates(7)
    fe = c.fe
    T = c.nodal(np.eye(c.size))
    np.testing.assert_allclose(c.nodal_transpose(np.eye(fe.ndof)), T.T, atol=1e-15)
    h, ei = np.diff(fe.mesh.points), fe.mesh.EI
    Kc = np.zeros((c.size, c.size))
    for e in range(h.size):
        Kc[2 * e : 2 * e + 2, 2 * e : 2 * e + 2] = ei[e] * h[e] / 3 * np.array([[1, 0.5], [0.5, 1]])
    np.testing.assert_allclose(T.T @ (fe.K @ T), Kc, atol=1e-12 * np.abs(Kc).max())
    # L L^T = K_c: solve_l and solve_lt invert its triangular factors.
    y = np.random.default_rng(3).standard_normal((c.size, 2))
    np.testing.assert_allclose(c.solve_l(Kc @ c.solve_lt(y)), y, rtol=1e-12)


def test_frequencies_converge_as_h4_down_to_a_round_off_floor():
    # Exact continuous frequencies of the stepped beam (fem_racket.frame.continuous, transfer
    # matrices to round-off). Cubic Hermite: error ~ C h^4 (order 4.00 measured from 40 to 640
    # cells); beyond, round-off ~1e-14 (eps-level: the curvature path has no n^4 growth).
    exact = free_free_frequencies(standard_frame(), 4)
    counts = [20, 40, 80, 160, 320, 640, 1280, 5000]
    err = np.array(
        [free_modes(FrameModel.build(None, n).fe, 4).frequencies / exact - 1 for n in counts]
    )
    order = np.log(err[:-1] / err[1:]) / np.log(np.array(counts[1:]) / counts[:-1])[:, None]
    assert np.all(np.abs(order[1:5] - 4.0) < 0.05)
    bound = np.maximum(1.05 * err[0] * (20.0 / np.array(counts))[:, None] ** 4, 1e-13)
    assert np.all(np.abs(err) <= bound)


def test_fine_mesh_modes_identical_run_to_run():
    # ARPACK's random start vector made every solve differ (f1 122.18-122.36 Hz at 20 000
    # cells); the start vector is now fixed, so two Lanczos solves agree bit for bit.
    a = FrameModel.build(None, 1500).modes()
    b = FrameModel.build(None, 1500).modes()
    assert np.array_equal(a.omega, b.omega)
    assert np.array_equal(a.shapes, b.shapes)


def test_every_returned_mode_passes_the_residual_check(monkeypatch):
    # Backward errors are ~1e-15 (measured); an impossible tolerance makes the check refuse.
    monkeypatch.setattr(curvature, "RESIDUAL_TOL", 0.0)
    with pytest.raises(AccuracyError, match="elements = 300: free-free mode 1") as err:
        FrameModel.build(None, 300).modes(6)
    assert "\n" not in str(err.value)


def test_element_limit_refused_at_once():
    t0 = time.process_time()  # CPU seconds: other processes on the machine do not count
    for n in (MAX_ELEMENTS + 1, 9223372036854775807):
        with pytest.raises(InputError, match=f"elements = {n} .*from 2 to {MAX_ELEMENTS}"):
            FrameModel.build(None, n)
    points = np.linspace(0.0, 0.68, MAX_ELEMENTS + 2)
    cells = np.ones(MAX_ELEMENTS + 1)
    with pytest.raises(InputError, match=f"{MAX_ELEMENTS + 1} cells .*at most {MAX_ELEMENTS}"):
        FrameMesh(points, 146.0 * cells, 0.7 * cells)
    assert time.process_time() - t0 < 1.0


def test_every_mode_of_a_large_mesh_refused():
    # More than half of all modes needs a dense solve: refused above DENSE_MAX (memory).
    n = curvature.DENSE_MAX // 2 + 1
    with pytest.raises(InputError, match=f"modes = {2 * n} is not allowed with {n} elements"):
        FrameModel.build(None, n).modes(None)


@pytest.mark.slow
def test_cor_and_contact_time_converged_up_to_the_element_limit():
    # Issue 12: at 5 000 cells the COR varied in the 4th-5th digit from run to run and at
    # 50 000 it was 0.3696-0.3742. Now every count from 160 up to the limit is within 1e-8
    # (COR) and 1e-7 (relative t_c) of the finest mesh (measured: 2e-9 and 4e-8 at 160, 1e-12
    # from 1 280), the limit itself repeats bit for bit, and its frequencies match the exact ones.
    positions = (0.6, 0.75, 0.9)
    finest = FrameModel.build(None, MAX_ELEMENTS)
    again = FrameModel.build(None, MAX_ELEMENTS)
    ref = [simulate(finest, position=p, output_step=None, tolerance=None) for p in positions]
    rerun = [simulate(again, position=p, output_step=None, tolerance=None) for p in positions]
    assert [r.cor for r in ref] == [r.cor for r in rerun]
    assert [r.contact_time for r in ref] == [r.contact_time for r in rerun]
    exact = free_free_frequencies(standard_frame(), 4)
    np.testing.assert_allclose(finest.modes().frequencies[:4], exact, rtol=1e-13)
    for n in (160, 1280, 20000):
        model = FrameModel.build(None, n)
        for p, r in zip(positions, ref, strict=True):
            s = simulate(model, position=p, output_step=None, tolerance=None)
            assert s.cor == pytest.approx(r.cor, abs=1e-8)
            assert s.contact_time == pytest.approx(r.contact_time, rel=1e-7)


def test_energy_balance_holds_on_a_fine_mesh():
    # Energies sum to the initial kinetic energy to the accuracy of the dashpot-work quadrature
    # (Simpson on 1e-5 s steps: 3.4e-6 at 20 elements). With q^T K q for the strain energy the
    # balance drifted by ~7e-5 at 2 000 elements and 2e-4 at 5 000 (cancellation in K q).
    for n in (20, 2000):
        total = simulate(FrameModel.build(None, n)).energies()["total"]
        assert np.ptp(total) / total[0] < 1e-5
