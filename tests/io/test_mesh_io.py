"""Mesh files: round trip, validation of bad meshes, graded meshes, --mesh on the CLI."""

from pathlib import Path

import meshio
import numpy as np
import pytest
from clirun import run_json
from script_loader import load_script

from fem_racket import FrameMesh, FrameModel, frame_mesh, read_mesh, standard_frame, write_mesh
from fem_racket.cli import main
from fem_racket.frame.continuous import free_free_frequencies
from fem_racket.frame.mesh import frame_from_mesh, graded_mesh, insert_nodes
from fem_racket.validation import InputError

ROOT = Path(__file__).resolve().parents[2]
MESHES = ROOT / "meshes"


def _write_raw(path, x, cells, cell_data=None, y=None):
    pts = np.zeros((len(x), 3))
    pts[:, 0] = x
    if y is not None:
        pts[:, 1] = y
    n = len(cells)
    data = (
        {"EI": [np.full(n, 146.0)], "rhoA": [np.full(n, 0.5)]} if cell_data is None else cell_data
    )
    meshio.write(path, meshio.Mesh(pts, [("line", np.array(cells))], cell_data=data))
    return path


@pytest.mark.parametrize("suffix", [".vtu", ".vtk", ".msh", ".xdmf"])  # .xdmf needs h5py
def test_round_trip(tmp_path, suffix):
    mesh = graded_mesh(standard_frame(), 17, 3.0, extra_points=(0.769,))
    path = write_mesh(mesh, tmp_path / f"frame{suffix}")
    back = read_mesh(path)
    for k in ("points", "EI", "rhoA"):
        assert np.array_equal(getattr(back, k), getattr(mesh, k)), k
    f0 = FrameModel.build(mesh).modes(4).frequencies
    f1 = FrameModel.build(back).modes(4).frequencies
    assert np.array_equal(f0, f1)


def test_write_refuses_existing_file_when_asked(tmp_path):
    mesh = frame_mesh(standard_frame(), 4)
    path = write_mesh(mesh, tmp_path / "a.vtu")
    write_mesh(mesh, path, overwrite=True)
    with pytest.raises(InputError, match="already exists"):
        write_mesh(mesh, path)  # the default refuses to replace a file
    with pytest.raises(
        InputError, match="a.unknownformat. is not allowed: a mesh file must end in"
    ):
        write_mesh(mesh, tmp_path / "a.unknownformat")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.vtu"]  # no temporary left


def test_cells_in_any_order_and_direction(tmp_path):
    # Nodes numbered backwards and cells listed out of order still make the same frame.
    x = np.array([0.68, 0.3, 0.1, 0.0, 0.5])
    cells = [[4, 0], [2, 3], [1, 4], [1, 2]]
    ei = {"EI": [np.array([4.0, 1.0, 3.0, 2.0])], "rhoA": [np.array([0.4, 0.1, 0.3, 0.2])]}
    m = read_mesh(_write_raw(tmp_path / "m.vtu", x, cells, ei))
    assert m.points.tolist() == [0.0, 0.1, 0.3, 0.5, 0.68]
    assert m.EI.tolist() == [1.0, 2.0, 3.0, 4.0]
    assert m.rhoA.tolist() == [0.1, 0.2, 0.3, 0.4]


def test_offset_mesh_starts_at_grip(tmp_path):
    m = read_mesh(_write_raw(tmp_path / "m.vtu", [1.0, 1.3, 1.68], [[0, 1], [1, 2]]))
    assert m.points == pytest.approx([0.0, 0.3, 0.68])


BAD = {
    "gap": ([0.0, 0.3, 0.31, 0.68], [[0, 1], [2, 3]], None, "gap between x = 0.3 m and x = 0.31"),
    "overlap": ([0.0, 0.4, 0.3, 0.68], [[0, 1], [2, 3]], None, "overlap between x = 0.4 m"),
    "unsorted nodes": ([0.0, 0.5, 0.3, 0.68], [[0, 1], [1, 2], [2, 3]], None, "overlap"),
    "zero-length": ([0.0, 0.3, 0.3, 0.68], [[0, 1], [1, 2], [2, 3]], None, "zero-length cell"),
    "missing EI": ([0.0, 0.68], [[0, 1]], {"rhoA": [np.array([0.5])]}, "'EI' is missing"),
    "missing rhoA": ([0.0, 0.68], [[0, 1]], {"EI": [np.array([1.0])]}, "'rhoA' is missing"),
    "negative EI": (
        [0.0, 0.3, 0.68],
        [[0, 1], [1, 2]],
        {"EI": [np.array([146.0, -1.0])], "rhoA": [np.array([0.5, 0.5])]},
        "EI = -1.0 N m^2 in cell 1 (x = 0.3..0.68 m)",
    ),
    "zero rhoA": (
        [0.0, 0.68],
        [[0, 1]],
        {"EI": [np.array([146.0])], "rhoA": [np.array([0.0])]},
        "rhoA = 0.0 kg/m",
    ),
    "nan rhoA": (
        [0.0, 0.68],
        [[0, 1]],
        {"EI": [np.array([146.0])], "rhoA": [np.array([np.nan])]},
        "rhoA = nan",
    ),
    "vector EI": (
        [0.0, 0.68],
        [[0, 1]],
        {"EI": [np.array([[1.0, 2.0]])], "rhoA": [np.array([0.5])]},
        "one number per cell",
    ),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_mesh_is_one_clear_line(tmp_path, case, capsys):
    x, cells, data, needle = BAD[case]
    path = _write_raw(tmp_path / "bad.vtu", x, cells, data)
    with pytest.raises(InputError) as err:
        read_mesh(path)
    msg = str(err.value)
    assert needle in msg and "bad.vtu" in msg and "\n" not in msg
    # The CLI turns it into one line on stderr and exit code 2.
    code = main(["modes", "--mesh", str(path)])
    out, errout = capsys.readouterr()
    assert code == 2 and needle in errout and "Traceback" not in errout
    assert len(errout.strip().splitlines()) == 1


def test_not_along_x(tmp_path):
    path = _write_raw(tmp_path / "m.vtu", [0.0, 0.3, 0.68], [[0, 1], [1, 2]], y=[0, 0.1, 0])
    with pytest.raises(InputError, match="not on one line along x"):
        read_mesh(path)


def test_no_line_cells(tmp_path):
    pts = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]])
    meshio.write(tmp_path / "t.vtu", meshio.Mesh(pts, [("triangle", np.array([[0, 1, 2]]))]))
    with pytest.raises(InputError, match="no 'line' cells .*triangle"):
        read_mesh(tmp_path / "t.vtu")


@pytest.mark.parametrize(
    ("content", "needle"),
    [(None, "no such file"), (b"not a mesh at all\x00\x01", "could not be read")],
)
def test_unreadable_file(tmp_path, content, needle):
    path = tmp_path / "broken.vtu"
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(InputError, match=needle) as err:
        read_mesh(path)
    assert "\n" not in str(err.value)


def test_frame_mesh_object_validation():
    with pytest.raises(InputError, match="unsorted nodes between x = 0.5 m and x = 0.3 m"):
        FrameMesh([0.0, 0.5, 0.3], [1.0, 1.0], [1.0, 1.0])
    with pytest.raises(InputError, match="zero-length cell"):
        FrameMesh([0.0, 0.3, 0.3], [1.0, 1.0], [1.0, 1.0])
    with pytest.raises(InputError, match="3 values for 2 cells"):
        FrameMesh([0.0, 0.3, 0.6], [1.0, 1.0, 1.0], [1.0, 1.0])


@pytest.mark.parametrize("n", [2, 3, 7, 20, 33, 101])
@pytest.mark.parametrize("grading", [1.0, 4.0])
def test_refinement_keeps_steps_and_impact_point_on_nodes(n, grading):
    # A 4-segment frame; every step, and the impact point on request, must be a node.
    mesh_in = frame_mesh(standard_frame(), 10)
    frame = frame_from_mesh(insert_nodes(mesh_in, ()))
    from fem_racket.frame.segments import Frame, Segment

    frame = Frame((*frame.segments, Segment(0.05, 90.0, 0.6), Segment(0.011, 80.0, 0.3)))
    mesh = graded_mesh(frame, max(n, 4), grading, extra_points=(0.7691,))
    for x in frame.steps:
        assert np.min(np.abs(mesh.points - x)) == 0.0
    assert np.min(np.abs(mesh.points - 0.7691 * frame.length)) < 1e-15
    back = frame_from_mesh(mesh).segments  # the same segments back
    assert [(s.EI, s.rhoA) for s in back] == [(s.EI, s.rhoA) for s in frame.segments]
    assert [s.length for s in back] == pytest.approx([s.length for s in frame.segments], abs=1e-15)
    assert np.all(np.diff(mesh.points) > 0)


def test_graded_mesh_ratio_and_bad_grading():
    mesh = graded_mesh(standard_frame(), 40, 4.0)
    h = np.diff(mesh.points)
    assert 3.0 < h.max() / h.min() <= 4.0  # grading is the continuous ratio of the map
    with pytest.raises(InputError, match="grading"):
        graded_mesh(standard_frame(), 20, 0.5)


def test_committed_meshes_equal_the_script_output():
    mod = load_script("make_meshes")
    built = mod.build_meshes()
    assert sorted(built) == sorted(p.name for p in MESHES.glob("*.vtu"))
    for name, mesh in built.items():
        assert mod.same_mesh(read_mesh(MESHES / name), mesh), name
    assert mod.main(["--check"]) == 0


def test_example_meshes_are_plausible_rackets():
    for name in ("tapered_racket.vtu", "head_heavy_racket.vtu"):
        mesh = read_mesh(MESHES / name)
        props = FrameModel.build(mesh).props
        assert 0.30 <= props.mass <= 0.36  # kg, strung rackets (issue 5 brief)
        assert props.length == pytest.approx(0.685)
        assert len(frame_from_mesh(mesh).segments) >= 3


def test_standard_mesh_file_is_the_default_racket(capsys):
    # The same 20 cells as the default run: same COR to round-off of the point coordinates.
    a = run_json(capsys, "simulate", "--mesh", MESHES / "standard_racket.vtu")
    b = run_json(capsys, "simulate")
    assert a["cor"] == pytest.approx(b["cor"], rel=1e-12)
    assert a["elements"] == 20
    m = run_json(capsys, "modes", "--mesh", MESHES / "tapered_racket.vtu")
    exact = free_free_frequencies(read_mesh(MESHES / "tapered_racket.vtu"), 2)
    assert m["frequencies_hz"][:2] == pytest.approx(exact, rel=1e-4)  # 24 cells: FE err < 1e-4


@pytest.mark.parametrize("opt", [["--elements", "40"], ["--ei1", "200"], ["--ei2", "100"]])
def test_mesh_excludes_frame_options(capsys, opt):
    code = main(["simulate", "--mesh", str(MESHES / "standard_racket.vtu"), *opt])
    err = capsys.readouterr()[1]
    assert code == 2
    assert f"{opt[0]} is not allowed with --mesh" in err
