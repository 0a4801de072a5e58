"""The mesh formats written (``fit``/``customise --out``, ``write_mesh``): those that keep line
cells and their cell data, each read back by ``modes --mesh`` as the frame written; any other
suffix refused before the fit, naming the value given (``r.stl`` once gave an empty file and
meshio's warning; ``r.txt`` named a temporary of a temporary)."""

from __future__ import annotations

import numpy as np
import pytest
from clirun import file_refused_alike, refused_before_any_file, run, run_json

from fem_racket import frame_mesh, standard_frame
from fem_racket.frame.mesh import FrameMesh
from fem_racket.io.mesh_files import MESH_SUFFIXES, read_mesh, write_mesh
from fem_racket.validation import InputError

SPEC = ("--length", "0.685", "--mass", "0.3", "--balance", "0.32", "--swing-weight", "290",
        "--twist-weight", "15")  # fmt: skip
ALLOWED = "a mesh file must end in one of .vtu, .vtk, .xdmf, .xmf, .msh, .med, .dat, .tec, .avs"


@pytest.mark.parametrize("suffix", MESH_SUFFIXES)
def test_every_format_written_reads_back_as_the_frame(capsys, cwd, suffix):
    data = run_json(capsys, "fit", *SPEC, "--out", f"r{suffix}")
    assert sorted(p.name for p in cwd.iterdir()) == [f"r{suffix}", f"r{suffix}.json"]  # no .h5
    back = run_json(capsys, "modes", "--mesh", f"r{suffix}")
    run_json(capsys, "fit", *SPEC, "--out", "ref/r.vtu")  # .vtu: exact (test_mesh_io.py)
    same = run_json(capsys, "modes", "--mesh", "ref/r.vtu")
    assert back["mass_kg"] == pytest.approx(data["fitted"]["mass_kg"], rel=1e-12)
    assert back["twist_weight_kg_cm2"] == pytest.approx(15.0, rel=1e-12)
    # every format exact but .avs (ASCII, 15 significant digits: measured 3e-15)
    rel = 1e-13 if suffix == ".avs" else 0.0
    assert back["frequencies_hz"] == pytest.approx(same["frequencies_hz"], rel=rel, abs=0.0)


def test_write_mesh_keeps_every_number_and_the_torsion_data(tmp_path):
    mesh = frame_mesh(standard_frame(), 9)
    n = mesh.n_elements
    mesh = FrameMesh(mesh.points, mesh.EI, mesh.rhoA, np.linspace(40.0, 60.0, n), np.full(n, 1e-4))
    for suffix in MESH_SUFFIXES:
        back = read_mesh(write_mesh(mesh, tmp_path / f"m{suffix}"))
        for k in ("points", "EI", "rhoA", "GJ", "rhoIp"):
            want = getattr(mesh, k)
            assert getattr(back, k) == pytest.approx(want, rel=1e-14, abs=0.0), (suffix, k)
    assert len(list(tmp_path.iterdir())) == len(MESH_SUFFIXES)  # no .h5 beside an .xdmf/.xmf


@pytest.mark.parametrize("out", ["r.stl", "r.txt", "noext", "r.obj", "r.inp", "r.hmf"])
def test_another_suffix_is_refused_before_the_fit(capsys, cwd, out):
    line = refused_before_any_file(capsys, "fit", *SPEC, "--out", out)
    assert f"out = '{out}' is not allowed: {ALLOWED}" in line, line
    assert ".part" not in line  # the user's value, not a temporary's name
    line = refused_before_any_file(capsys, "customise", "--swing-weight", "330", "--out", out)
    assert f"out = '{out}' is not allowed: {ALLOWED}" in line, line
    with pytest.raises(InputError, match=f"path = '.*{out}' is not allowed: {ALLOWED}"):
        write_mesh(frame_mesh(standard_frame(), 4), cwd / out)
    assert not any(cwd.iterdir())


def test_a_run_files_out_is_refused_alike(capsys, cwd):
    text = "[fit]\nlength = 0.685\nmass = 0.3\nbalance = 0.32\nswing_weight = 290\nout = 'r.stl'\n"
    file_refused_alike(
        capsys, text, ["fit", "--config", "run.toml"], lambda c: c.fit(), "out = 'r.stl'"
    )


def test_an_upper_case_suffix_is_its_format(capsys, cwd):
    code, _, err = run(capsys, "fit", *SPEC, "--out", "R.VTU")
    assert code == 0, err
    assert read_mesh("R.VTU").n_elements > 0
