"""A library of an optional extra that is missing: one line naming the pip install that adds
it, exit 2, before any work (the extras are declared in pyproject.toml; fem_racket.extras)."""

import sys

import pytest

from fem_racket.extras import EXTRAS, MissingExtra, require
from tests.clirun import run


@pytest.mark.parametrize(
    ("module", "argv", "extra"),
    [
        ("imageio", ["animate", "--out", "{tmp}/a.gif"], "animate"),
        ("SALib", ["sensitivity", "--designs", "8"], "design"),
        ("pymoo", ["optimize", "--method", "nsga2", "--objective", "cor,ball_speed"], "design"),
        (
            "distributed",
            ["sweep", "--scheduler", "tcp://127.0.0.1:1", "--out", "{tmp}/s.nc"],
            "dask",
        ),
    ],
)
def test_a_missing_extra_is_one_line_naming_its_install(
    capsys, monkeypatch, tmp_path, module, argv, extra
):
    monkeypatch.chdir(tmp_path)  # default outputs would go here
    monkeypatch.setitem(sys.modules, module, None)  # import fails as if not installed
    code, out, err = run(capsys, *[a.format(tmp=tmp_path) for a in argv])
    assert (code, out) == (2, "")
    assert err.count("\n") == 1 and f"needs {module}, which is not installed" in err
    assert f"pip install 'fem_racket[{extra}]'" in err
    assert list(tmp_path.iterdir()) == []  # refused before any work


def test_require_names_the_extra_and_passes_other_import_errors_on(monkeypatch):
    assert require("json", "x").dumps(1) == "1"  # an installed module is returned
    for name in ("pymoo", "pymoo.optimize"):  # a submodule another test imported is cached
        monkeypatch.setitem(sys.modules, name, None)
    with pytest.raises(MissingExtra, match=r"needs pymoo.*fem_racket\[design\]"):
        require("pymoo.optimize", "nsga2")
    assert set(EXTRAS.values()) == {"animate", "design", "dask"}


def test_pyvista_is_core_a_missing_one_is_a_broken_install(monkeypatch):
    # the project's brief lists pyvista among the core dependencies: no extra names it, and
    # its absence is the import's own error, not an "install the extra" line
    import tomllib
    from pathlib import Path

    project = tomllib.loads((Path(__file__).resolve().parents[2] / "pyproject.toml").read_text())
    core = {d.split(">")[0].split("[")[0] for d in project["project"]["dependencies"]}
    assert {"pyvista", "scikit-fem", "numpy", "scipy", "meshio", "scikit-sundae"} <= core
    assert "pyvista" not in EXTRAS and require("pyvista", "x").__name__ == "pyvista"
    monkeypatch.setitem(sys.modules, "pyvista", None)
    with pytest.raises(ModuleNotFoundError):
        require("pyvista", "export-vtk")
