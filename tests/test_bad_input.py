"""A catalogue of bad inputs through the CLI, in-process.

Every case must give: exit code 2, exactly one line on stderr that names the parameter and says
what is allowed, no traceback, and no file left behind (each ``simulate`` case also asks for
``--out result.json``, so a case that wrongly ran to the end, or failed half-way through writing,
would leave a file).

Extend the lists below; bad mesh files have their own list, ``BAD_MESHES`` (issue 5).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest

from fem_racket.cli import main


@dataclass
class Case:
    """argv for ``main``; ``files`` are created in the working folder first (name -> text)."""

    id: str
    argv: list[str]
    names: tuple[str, ...]  # every one must appear in the error line (parameter, allowed form)
    files: dict[str, str] = field(default_factory=dict)


def sim(*argv: str) -> list[str]:
    return ["simulate", *argv]


def toml(text: str, *argv: str, command: str = "simulate") -> tuple[list[str], dict[str, str]]:
    """argv running ``command`` on run.toml holding ``text``, and the files to create."""
    return [command, "--config", "run.toml", *argv], {"run.toml": text}


def T(case_id: str, argv_files: tuple[list[str], dict[str, str]], names: tuple[str, ...]) -> Case:
    """A case running a run file (see :func:`toml`)."""
    return Case(case_id, argv_files[0], names, argv_files[1])


CLI_CASES = [
    Case("speed-zero", sim("--speed", "0"), ("speed = 0", "> 0")),
    Case("speed-negative", sim("--speed", "-3"), ("speed = -3", "> 0")),
    Case("speed-nan", sim("--speed", "nan"), ("speed = nan", "finite")),
    Case("speed-inf", sim("--speed", "inf"), ("speed = inf", "finite")),
    Case("speed-not-a-number", sim("--speed", "fast"), ("--speed", "float")),
    Case("position-off-tip", sim("--position", "1.5"), ("position = 1.5", "[0, 1]")),
    Case("position-off-grip", sim("--position", "-0.1"), ("position = -0.1", "[0, 1]")),
    Case("position-nan", sim("--position", "nan"), ("position", "finite")),
    Case("ei1-negative", sim("--ei1", "-146"), ("ei1 = -146", "> 0")),
    Case("ei1-zero", sim("--ei1", "0"), ("ei1 = 0", "> 0")),
    Case("ei1-inf", sim("--ei1", "inf"), ("ei1 = inf", "finite")),
    Case("ei2-nan", sim("--ei2", "nan"), ("ei2 = nan", "finite")),
    Case("ball-mass-zero", sim("--ball-mass", "0"), ("ball mass = 0", "> 0")),
    Case("ball-mass-negative", sim("--ball-mass", "-0.057"), ("ball mass", "> 0")),
    Case("kcb-zero", sim("--kcb", "0"), ("kcb = 0", "> 0")),
    Case("kcb-negative", sim("--kcb", "-1"), ("kcb = -1", "> 0")),
    Case("zeta-one", sim("--zeta", "1"), ("zeta = 1", "[0, 1)")),
    Case("zeta-negative", sim("--zeta", "-0.2"), ("zeta = -0.2", "[0, 1)")),
    Case("zeta-nan", sim("--zeta", "nan"), ("zeta", "finite")),
    Case("elements-one", sim("--elements", "1"), ("elements = 1", ">= 2")),
    Case("elements-zero", sim("--elements", "0"), ("elements = 0", ">=")),
    Case("modes-zero", sim("--modes", "0"), ("modes = 0", ">= 1")),
    Case("unknown-solver", sim("--solver", "euler"), ("--solver", "choose from", "exact")),
    Case("unknown-separation", sim("--separation", "x"), ("--separation", "choose from")),
    Case("exact-physical", sim("--basis", "physical"), ("basis = 'physical'", "'modal'")),
    Case("t-max-zero", sim("--t-max", "0"), ("t_max = 0", "> 0")),
    Case("t-max-negative", sim("--t-max", "-1"), ("t_max = -1", "> 0")),
    Case("rtol-zero", sim("--solver", "cvode", "--rtol", "0"), ("rtol = 0", "> 0")),
    Case("atol-nan", sim("--atol", "nan"), ("atol = nan", "finite")),
    # The standard impact lasts 4.04 ms: 0.1 ms is far too short to separate (exact and CVODE).
    Case("no-separation-exact", sim("--t-max", "1e-4"), ("t_max = 0.0001 s", "raise t_max")),
    Case(
        "no-separation-cvode",
        sim("--t-max", "1e-4", "--solver", "cvode"),
        ("t_max = 0.0001 s", "raise t_max"),
    ),
    Case("modes-count-zero", ["modes", "--count", "0"], ("count = 0", ">= 1")),
    Case("modes-ei1-nan", ["modes", "--ei1", "nan"], ("ei1 = nan", "finite")),
    Case("unknown-command", ["nonsense"], ("COMMAND", "choose from")),
    Case("config-needs-a-mode", ["config"], ("--example", "--check", "required")),
]

OUTPUT_CASES = [
    Case(
        "out-under-a-regular-file",
        sim("--out", "afile/result.json"),
        ("output folder = 'afile'", "must be a folder you can write to"),
        {"afile": "not a folder"},
    ),
    Case(
        "out-exists",
        sim("--out", "old.json"),
        ("output = 'old.json' already exists", "--overwrite"),
        {"old.json": "{}"},
    ),
    Case("out-is-a-folder", sim("--out", ".", "--overwrite"), ("output = '.'", "must be a file")),
    Case(
        "config-example-out-exists",
        ["config", "--example", "--out", "run.toml"],
        ("already exists", "--overwrite"),
        {"run.toml": "# mine\n"},
    ),
]

TOML_CASES = [
    T(
        "toml-malformed",
        toml("[impact]\nspeed_m_s = = 30\n"),
        ("run.toml", "not valid TOML", "line 2"),
    ),
    T("toml-unclosed-table", toml("[impact\nspeed_m_s = 3\n"), ("not valid TOML", "line 1")),
    Case("toml-missing-file", ["simulate", "--config", "nope.toml"], ("config = 'nope.toml'",)),
    Case("toml-folder", ["simulate", "--config", "."], ("config = '.'", "must be a TOML file")),
    T(
        "toml-unknown-key",
        toml("[impact]\nspeed = 30\n"),
        ("impact.speed is not a known key", "did you mean 'speed_m_s'"),
    ),
    T(
        "toml-key-in-wrong-table",
        toml("[ball]\nspeed_m_s = 30\n"),
        ("ball.speed_m_s", "did you mean 'impact.speed_m_s'"),
    ),
    T(
        "toml-unknown-table",
        toml("[impakt]\nspeed_m_s = 30\n"),
        ("impakt is not a known key", "did you mean 'impact'"),
    ),
    T("toml-top-level-key", toml("speed_m_s = 30\n"), ("speed_m_s", "impact.speed_m_s")),
    T(
        "toml-string-for-number",
        toml("[impact]\nspeed_m_s = '30'\n"),
        ("impact.speed_m_s = '30'", "must be a number"),
    ),
    T(
        "toml-bool-for-number",
        toml("[contact]\nkcb_n_m = true\n"),
        ("contact.kcb_n_m = True", "must be a number"),
    ),
    T(
        "toml-speed-negative",
        toml("[impact]\nspeed_m_s = -3\n"),
        ("impact.speed_m_s = -3 m/s", "> 0"),
    ),
    T("toml-speed-zero", toml("[impact]\nspeed_m_s = 0.0\n"), ("impact.speed_m_s = 0.0",)),
    T("toml-speed-nan", toml("[impact]\nspeed_m_s = nan\n"), ("impact.speed_m_s", "finite")),
    T("toml-speed-inf", toml("[impact]\nspeed_m_s = inf\n"), ("impact.speed_m_s", "finite")),
    T(
        "toml-position-off-frame",
        toml("[impact]\nposition_x_over_l = 1.2\n"),
        ("impact.position_x_over_l = 1.2", "[0, 1]"),
    ),
    T(
        "toml-unknown-solver",
        toml("[solver]\nname = 'euler'\n"),
        ("solver.name = 'euler'", "must be one of", "exact"),
    ),
    T(
        "toml-modes-float",
        toml("[solver]\nmodes = 1.5\n"),
        ("solver.modes = 1.5", "integer >= 1"),
    ),
    T(
        "toml-elements-zero",
        toml("[frame]\nelements = 0\n"),
        ("frame.elements = 0", "integer >= 1"),
    ),
    T(
        "toml-segment-negative-length",
        toml("[[frame.segments]]\nlength_m = -0.2\nei_n_m2 = 146\nrhoa_kg_m = 0.7\n"),
        ("frame.segments[0].length_m = -0.2 m", "> 0"),
    ),
    T(
        "toml-segment-missing-key",
        toml("[[frame.segments]]\nlength_m = 0.2\nei_n_m2 = 146\n"),
        ("frame.segments[0]", "rhoa_kg_m"),
    ),
    T("toml-segments-empty", toml("[frame]\nsegments = []\n"), ("frame.segments", "non-empty")),
    T(
        "toml-segments-and-preset",
        toml("[frame]\npreset = 'rigid'\nsegments = [{length_m=1, ei_n_m2=1, rhoa_kg_m=1}]\n"),
        ("frame.segments, frame.preset cannot be combined", "one of"),
    ),
    T(
        "toml-unknown-preset",
        toml("[frame]\npreset = 'wooden'\n"),
        ("frame.preset = 'wooden'", "standard, rigid"),
    ),
    T(
        "toml-zeta-and-clamped-cor",
        toml("[contact]\nzeta = 0.05\nclamped_cor = 0.8\n"),
        ("contact.zeta and contact.clamped_cor cannot be combined",),
    ),
    T(
        "toml-clamped-cor-zero",
        toml("[contact]\nclamped_cor = 0\n"),
        ("contact.clamped_cor = 0", "(0, 1]"),
    ),
    T(
        "toml-ball-mass-zero",
        toml("[ball]\nmass_kg = 0\n"),
        ("ball.mass_kg = 0 kg", "> 0"),
    ),
    T(
        "toml-overwrite-not-bool",
        toml("[output]\noverwrite = 'yes'\n"),
        ("output.overwrite = 'yes'", "true or false"),
    ),
    T(
        "toml-no-separation",
        toml("[solver]\nt_max_s = 1e-4\n"),
        ("t_max = 0.0001 s", "raise t_max"),
    ),
    T(
        "toml-command-table-unknown-key",
        toml("[simulate]\njsn = true\n"),
        ("simulate.jsn is not a known key", "did you mean 'json'"),
    ),
    T(
        "toml-command-table-core-key",
        toml("[simulate]\nspeed = 30\n"),
        ("simulate.speed", "set impact.speed_m_s instead"),
    ),
    T(
        "toml-command-table-wrong-type",
        toml("[modes]\ncount = 1.5\n", command="modes"),
        ("modes.count = 1.5", "must be an integer"),
    ),
    T(
        "toml-command-table-bad-value",
        toml("[modes]\ncount = 0\n", command="modes"),
        ("count = 0", ">= 1"),
    ),
    T(
        "toml-segments-with-cli-ei1",
        toml("[frame]\nsegments = [{length_m=0.7, ei_n_m2=150, rhoa_kg_m=0.5}]\n", "--ei1", "9"),
        ("--ei1 cannot be combined with frame.segments",),
    ),
    T(
        "toml-missing-mesh",
        toml("[frame]\nmesh = 'meshes/none.vtu'\n"),
        ("frame.mesh = 'meshes/none.vtu'", "no such file", "relative to the run file"),
    ),
    Case(
        "toml-check-bad-file",
        ["config", "--check", "run.toml"],
        ("impact.speed_m_s = -1", "> 0"),
        {"run.toml": "[impact]\nspeed_m_s = -1\n"},
    ),
]


# -- bad mesh files (issue 5 extends this list) ------------------------------------------------
def _write_line_mesh(path: Path, x: np.ndarray, cells: np.ndarray, **cell_data: list) -> None:
    import meshio

    pts = np.zeros((x.size, 3))
    pts[:, 0] = x
    meshio.write(path, meshio.Mesh(pts, [("line", cells)], cell_data=cell_data))


def _mesh_without_rhoa(path: Path) -> None:
    _write_line_mesh(path, np.linspace(0, 0.68, 5), np.c_[0:4, 1:5], EI=[np.full(4, 146.0)])


def _mesh_with_gap(path: Path) -> None:
    x = np.array([0.0, 0.3, 0.35, 0.68])
    ei, ra = [np.full(2, 146.0)], [np.full(2, 0.5)]
    _write_line_mesh(path, x, np.array([[0, 1], [2, 3]]), EI=ei, rhoA=ra)


#: (id, function writing the bad mesh to the path it is given, words the error must contain).
#: Each is read through a run file's ``frame.mesh``; issue 5 adds gaps, overlaps, unsorted nodes,
#: zero-length cells ... here (and may run them through ``--mesh`` too).
BAD_MESHES = [
    ("mesh-missing-rhoA", _mesh_without_rhoa, ("mesh = ", "'rhoA' is missing")),
    ("mesh-gap", _mesh_with_gap, ("mesh = ", "gap between x = 0.3 m and x = 0.35 m")),
]


def _mesh_case(mesh_id: str, names: tuple[str, ...]) -> Case:
    return T(mesh_id, toml("[frame]\nmesh = 'bad.vtu'\n"), names)


ALL_CASES = CLI_CASES + OUTPUT_CASES + TOML_CASES
MESH_CASES = {c[0]: c[1] for c in BAD_MESHES}


def test_catalogue_size():
    assert len(ALL_CASES) + len(BAD_MESHES) >= 30
    assert len({c.id for c in ALL_CASES} | set(MESH_CASES)) == len(ALL_CASES) + len(BAD_MESHES)


def _check_one_error(capsys, tmp_path, case: Case) -> None:
    for name, text in case.files.items():
        (tmp_path / name).write_text(text)
    before = {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*")}
    argv = list(case.argv)
    if argv[0] == "simulate" and "--out" not in argv:
        argv += ["--out", "result.json"]
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 2, (out, err)
    assert "Traceback" not in err
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith("fem-racket") and ": error: " in lines[0]
    for needle in case.names:
        assert needle in lines[0], f"{needle!r} not in {lines[0]!r}"
    after = {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*")}
    assert after == before, "a file was written or changed"


@pytest.mark.parametrize("case", ALL_CASES, ids=[c.id for c in ALL_CASES])
def test_bad_input_gives_one_line_exit_2_and_no_file(capsys, tmp_path, monkeypatch, case):
    monkeypatch.chdir(tmp_path)
    _check_one_error(capsys, tmp_path, case)


@pytest.mark.parametrize(("mesh_id", "write", "names"), BAD_MESHES, ids=list(MESH_CASES))
def test_bad_mesh_gives_one_line_exit_2_and_no_file(
    capsys, tmp_path, monkeypatch, mesh_id, write, names
):
    monkeypatch.chdir(tmp_path)
    write(tmp_path / "bad.vtu")
    _check_one_error(capsys, tmp_path, _mesh_case(mesh_id, names))
