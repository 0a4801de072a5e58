"""A library of an optional extra that is missing: one line naming the pip install that adds
it, exit 2, before any work (the extras are declared in pyproject.toml; fem_racket.extras)."""

import sys

import pytest

from fem_racket.extras import EXTRAS, MissingExtra, require
from tests.clirun import run


@pytest.mark.parametrize(
    ("module", "argv", "extra"),
    [
        ("pyvista", ["export-vtk", "--out", "{tmp}/v"], "vtk"),
        ("imageio", ["animate", "--out", "{tmp}/a.gif"], "vtk"),
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
    assert set(EXTRAS.values()) == {"vtk", "design", "dask"}
