"""Mesh-refinement study: observed order, COR convergence, CLI and script."""

import time
from pathlib import Path

import numpy as np
import pytest
from clirun import run_json
from script_loader import load_script

from fem_racket import FrameModel, frame_mesh, simulate, standard_frame
from fem_racket.cli import main
from fem_racket.frame.continuous import free_free_frequencies
from fem_racket.frame.hermite import assemble_closed_form, strain_energy
from fem_racket.studies.refine import refinement_study
from fem_racket.validation import InputError

ROOT = Path(__file__).resolve().parents[2]
#: scikit-fem's own convergence tests accept the rate within +-0.1 (tests/test_convergence.py,
#: e.g. limits = (1.9, 2.1)); cubic Hermite eigenvalues converge as h^4.
ORDER_TOL = 0.1


@pytest.fixture(scope="module")
def study():
    return refinement_study(None, (10, 20, 40, 80), family="uniform", positions=(0.75, 0.769))


def test_observed_order_is_four(study):
    assert study.observed_order == pytest.approx([4.0] * 4, abs=ORDER_TOL)
    # From 20 elements on every pair is in the asymptotic range.
    assert study.observed_order_pairs[1:] == pytest.approx(np.full((2, 4), 4.0), abs=ORDER_TOL)
    assert np.all(study.relative_error > 0)  # Rayleigh-Ritz: FE frequencies bound from above


def test_graded_meshes_converge_at_order_four():
    s = refinement_study(None, (20, 40, 80), family="graded", positions=(0.75,))
    assert s.observed_order == pytest.approx([4.0] * 4, abs=ORDER_TOL)


def test_closed_form_matrices_match_scikit_fem():
    # Same integrals; scikit-fem's global-coordinate Hermite basis adds round-off that grows
    # with refinement (4e-12 relative at 20 cells, measured), so compare at 20 cells.
    mesh = frame_mesh(standard_frame(), 20)
    ref = FrameModel.build(mesh).fe
    fe = assemble_closed_form(mesh)
    assert abs(fe.K - ref.K).max() <= 1e-10 * abs(ref.K).max()
    assert abs(fe.M - ref.M).max() <= 1e-10 * abs(ref.M).max()
    q = np.random.default_rng(1).standard_normal(fe.ndof)
    assert strain_energy(fe, q) == pytest.approx(q @ (fe.K @ q), rel=1e-10)


def test_low_modes_at_320_elements():
    # FE error of mode 1 at 320 cells is 3.3e-11 (h^4 from 5.2e-10 at 160); an eigen-solver on
    # the assembled K, M is off by ~1e-8 there, the curvature-coordinate path by ~1e-14.
    model = FrameModel.build(frame_mesh(standard_frame(), 320))
    exact = free_free_frequencies(standard_frame(), 4)
    err = model.modes(6).frequencies[:4] / exact - 1
    assert np.all(err > 0)
    assert err[0] == pytest.approx(3.26e-11, abs=1e-11)


def test_cor_converges_and_impact_points_inside_elements(study):
    # 0.769 L is never a node of these meshes; COR still converges: the changes fall by 5-30x
    # per halving (pre-asymptotic at 10-20 cells, then ~h^4 down to the 80-mode truncation
    # level of ~5e-8; measured).
    dc = study.change(study.cor)
    assert np.all(dc[2] < dc[1] / 4)
    assert np.all(dc[3] < dc[2] / 8)
    assert dc[3, 1] < 1e-6
    with_node = refinement_study(
        None, (80,), family="uniform", positions=(0.769,), impact_nodes=True
    )
    assert with_node.elements[0] == 81  # one cell split at the impact point
    # Both converge to the same COR: the difference is within the last change (2e-7).
    assert with_node.cor[0, 0] == pytest.approx(study.cor[-1, 1], abs=2 * dc[3, 1])
    # Richardson is given only where the observed order is 3-5, and then close to the finest.
    rich, order = study.richardson(study.cor), study.observed_order_of(study.cor)
    trusted = (order >= 3) & (order <= 5)
    assert np.all(np.isnan(rich[~trusted]))
    assert rich[trusted] == pytest.approx(study.cor[-1][trusted], abs=1e-6)


def test_default_mesh_cor_close_to_converged(study):
    # The paper's 20 elements: COR within 1e-6 of the 80-element value at 0.75 L.
    default = simulate(None, position=0.75, speed=20.0, output_step=None).cor
    assert default == pytest.approx(study.cor[-1, 0], abs=1e-6)


def test_bad_study_input():
    with pytest.raises(InputError, match="family"):
        refinement_study(None, (5, 10), family="random")
    with pytest.raises(InputError, match="elements"):
        refinement_study(None, (5, 0))
    with pytest.raises(InputError, match="position"):
        refinement_study(None, (5, 10), positions=(1.5,))
    # issue 21.3: the uniform family grades nothing, so a grading is refused, not ignored
    with pytest.raises(InputError, match=r"grading = 2.0 is not allowed with family 'uniform'"):
        refinement_study(None, (5,), family="uniform", grading=2.0)


def test_cli_refine_json_contract(tmp_path, capsys):
    argv = ["refine", "--elements", "5", "10", "20", "--positions", "0.75"]
    argv += ["--csv", str(tmp_path / "r.csv"), "--plot", str(tmp_path / "r.png")]
    data = run_json(capsys, *argv)
    for key in (
        "elements",
        "frequencies_hz",
        "exact_frequencies_hz",
        "observed_order",
        "cor",
        "contact_time_s",
    ):
        assert key in data
    assert data["elements"] == [5, 10, 20]
    assert np.shape(data["frequencies_hz"]) == (3, 4)
    assert np.shape(data["cor"]) == (3, 1)
    assert data["graded"]["elements"] == [5, 10, 20]
    assert (tmp_path / "r.csv").read_text().startswith("family,elements,f1_hz")
    assert (tmp_path / "r.png").stat().st_size > 10_000
    # Outputs exist now: a second run refuses to replace them (before doing the work).
    t0 = time.process_time()  # CPU seconds: other processes on the machine do not count
    assert main(argv) == 2
    assert time.process_time() - t0 < 1.0
    assert "already exists" in capsys.readouterr()[1]


def test_cli_refine_table_and_mesh(capsys):
    mesh = ROOT / "meshes" / "tapered_racket.vtu"
    argv = ["refine", "--mesh", str(mesh), "--elements", "4", "8", "16", "--no-files"]
    assert main([*argv, "--family", "uniform", "--positions", "0.7"]) == 0
    out = capsys.readouterr()[0]
    assert "exact frequencies [Hz]" in out and "Richardson" in out
    lines = [ln.split() for ln in out.splitlines()]
    assert [r[0] for r in lines if r and r[0] in ("4", "8", "16")][:2] == ["8", "16"]  # 4 < 8


def test_convergence_script_quick(tmp_path):
    mod = load_script("convergence")
    out = mod.main(["--quick", "--out", str(tmp_path)])
    assert (tmp_path / "convergence.csv").is_file() and (tmp_path / "convergence.png").is_file()
    # 10 -> 20 elements is nearly asymptotic: orders 3.8-4.0 (measured on both families).
    assert out["studies"]["uniform"].observed_order == pytest.approx([4.0] * 4, abs=0.3)


@pytest.mark.slow
def test_default_study_and_large_mesh_timing(tmp_path):
    # The default study (5-320 elements, both families) in well under a minute, clean order.
    mod = load_script("convergence")
    t0 = time.perf_counter()
    out = mod.main(["--timing", "--out", str(tmp_path)])
    assert time.perf_counter() - t0 < 60.0
    for s in out["studies"].values():
        assert s.observed_order == pytest.approx([4.0] * 4, abs=0.01)
    rows = {r["elements"]: r for r in out["timing"]}
    # Per-impact cost depends on the 80 modes, not on the mesh (measured ~22 ms at both).
    assert rows[1280]["impact_s"] < 5.0 * rows[80]["impact_s"] + 0.1  # loose: shared machine
