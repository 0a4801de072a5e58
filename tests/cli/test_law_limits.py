"""Issue 22 (deliverable 2) through the command line: each case that gave a traceback, a
silently wrong answer or a silently ignored option now gives exit 2 and one line naming it.

Every case: exit code 2, one line on stderr naming the parameter (or the case) and what is
allowed, no traceback, no file written (``simulate`` cases ask for ``--out``).
"""

from __future__ import annotations

import pytest

from fem_racket import FrameMesh, FrameModel, write_mesh
from fem_racket.cli import main

SERIES = ("--law", "series")
#: (id, argv, words every one of which the error line names)
CASES = [
    # tracebacks before ("Newton iteration did not converge", NaN to int)
    ("k2-huge", ["simulate", "--law", "hysteretic", "--k2", "1e300"], ("k2 = 1e+300", "[100")),
    ("ball-stiff-huge", ["simulate", *SERIES, "--ball-stiffness", "1e300"], ("ball_stiffness",)),
    ("ball-stiff-tiny", ["simulate", *SERIES, "--ball-stiffness", "1e-300"], ("ball_stiffness",)),
    ("ball-damp-tiny", ["simulate", *SERIES, "--ball-damping", "1e-300"], ("ball_damping",)),
    ("bed-huge", ["simulate", *SERIES, "--string-stiffness", "1e300"], ("string_stiffness",)),
    ("bed-tiny", ["simulate", *SERIES, "--string-stiffness", "1e-300"], ("string_stiffness",)),
    (
        "rigid-ball-linear-bed",
        ["simulate", *SERIES, "--ball-stiffness", "1e12", "--ball-damping", "1"]
        + ["--string-stiffness", "27400", "--string-cubic", "0"],
        ("ball_stiffness", "1e+08]"),
    ),
    # energy created before (COR -1.857)
    ("ball-soft", ["simulate", *SERIES, "--ball-stiffness", "1e-3"], ("ball_stiffness",)),
    # within every bound, the general integrator's Newton iteration fails: the case named
    (
        "steel-ball",
        ["simulate", *SERIES, "--ball-stiffness", "1e8", "--ball-damping", "0.01"],
        ("law 'series'", "ball_stiffness = 1e+08", "20 m/s", "cvode"),
    ),
    # the k2 < k1 combination of a sweep grid, refused before any work
    (
        "sweep-k2-below-k1",
        ["sweep", "--law", "hysteretic", "--k1", "1e15,5e15", "--k2", "4e15"],
        ("k2 >= k1", "k1 = 5e+15", "k2 = 4e+15"),
    ),
    # options accepted and ignored before
    ("simulate-kcb", ["simulate", "--law", "hysteretic", "--kcb", "3e4"], ("kcb", "'hysteretic'")),
    ("simulate-zeta", ["simulate", "--law", "itf-ball", "--zeta", "0.1"], ("zeta", "'itf-ball'")),
    ("sweep-kcb-axis", ["sweep", *SERIES, "--kcb", "3e4,4e4"], ("kcb", "'series'")),
    ("sweep-zeta-axis", ["sweep", "--law", "hunt-crossley", "--zeta", "0.1"], ("zeta",)),
    ("vtk-zeta", ["export-vtk", "--law", "hysteretic", "--zeta", "0.1"], ("zeta",)),
    ("vtk-kcb", ["export-vtk", "--law", "series", "--kcb", "3e4"], ("kcb",)),
    ("map-zeta", ["map", "--law", "hysteretic", "--zeta", "0.1"], ("zeta",)),
    (
        "run-file-kcb",
        ["simulate", "--config", "run.toml"],
        ("kcb", "'hysteretic'"),
    ),
    # implausible balls and implements
    ("ball-grams", ["simulate", "--ball-mass", "57"], ("ball mass = 57", "57.0 g = 0.057 kg")),
    ("sweep-ball-grams", ["sweep", "--ball-mass", "0.057,57"], ("ball_mass = 57", "grams")),
    ("mesh-mm", ["simulate", "--mesh", "mm.vtu"], ("length = 680 m", "millimetres")),
    ("mesh-g-per-m", ["simulate", "--mesh", "g.vtu"], ("mass = 360 kg", "rhoA in g/m")),
    ("mesh-n-mm2", ["simulate", "--mesh", "nmm.vtu"], ("first free-free frequency", "N mm^2")),
    (
        "segments-mm",
        ["simulate", "--config", "mm.toml"],
        ("frame.segments length = 680 m", "millimetres"),
    ),
    (
        "compare-segments-mm",
        ["compare", "standard", "mm.toml"],
        ("mm.toml: frame.segments length = 680 m", "millimetres"),
    ),
]

RUN_FILES = {
    "run.toml": '[contact]\nlaw = "hysteretic"\nkcb_n_m = 3e4\n',
    "mm.toml": "[[frame.segments]]\nlength_m = 204\nei_n_m2 = 146\nrhoa_kg_m = 0.696\n"
    "[[frame.segments]]\nlength_m = 476\nei_n_m2 = 128.5\nrhoa_kg_m = 0.458\n",
}


def _write_inputs(folder):
    for name, text in RUN_FILES.items():
        (folder / name).write_text(text)
    m = FrameModel.build(None, 20).mesh
    write_mesh(FrameMesh(m.points * 1e3, m.EI, m.rhoA), folder / "mm.vtu")
    write_mesh(FrameMesh(m.points, m.EI, m.rhoA * 1e3), folder / "g.vtu")
    write_mesh(FrameMesh(m.points, m.EI * 1e6, m.rhoA), folder / "nmm.vtu")


@pytest.mark.parametrize(("argv", "words"), [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_law_and_implement_limits_give_one_line(capsys, tmp_path, monkeypatch, argv, words):
    monkeypatch.chdir(tmp_path)
    _write_inputs(tmp_path)
    before = sorted(tmp_path.rglob("*"))
    if argv[0] == "simulate":
        argv = [*argv, "--out", "result.json"]
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 2, (out, err)
    assert "Traceback" not in err and len(err.splitlines()) == 1, err
    for word in words:
        assert word in err, (word, err)
    assert sorted(tmp_path.rglob("*")) == before, "a file was written"


def test_plausible_implements_and_balls_still_run(capsys, tmp_path, monkeypatch):
    # The ranges admit bats and paddles: a 1 m, 0.9 kg bat-like beam and a 2.7 g ball run.
    monkeypatch.chdir(tmp_path)
    (tmp_path / "bat.toml").write_text(
        "[[frame.segments]]\nlength_m = 1.0\nei_n_m2 = 2000\nrhoa_kg_m = 0.9\n"
        "[ball]\nmass_kg = 0.145\n"
    )
    code, err = main(["simulate", "--config", "bat.toml"]), capsys.readouterr().err
    assert code == 0, err
    code, err = main(["simulate", "--ball-mass", "0.0027", "--speed", "10"]), capsys.readouterr()
    assert code == 0, err
