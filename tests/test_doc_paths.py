"""Maps that stay true: every path and module the documentation names exists.

Read: README.md, REPRODUCTION.md, meshes/README.md, docs/ (when there is one), and the docstrings
of every module, class and function of the package, the scripts and the tests. Checked:

- paths under ``fem_racket/``, ``tests/``, ``scripts/``, ``meshes/`` and ``docs/`` (a ``*`` in
  one must match at least one file), and the targets of the Markdown files' relative links;
- dotted names starting with ``fem_racket``: a module, or a name of one (``fem_racket.simulate``);
- in docstrings, the relative Sphinx references ``:mod:`.x```, ``:func:`.x.f``` ...: a sibling of
  the module (or a name in the module itself).
"""

from __future__ import annotations

import ast
import importlib
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PATH = re.compile(r"(?<![\w/.-])((?:fem_racket|tests|scripts|meshes|docs)/[\w*./-]*[\w*/])")
DOTTED = re.compile(r"(?<![\w.])(fem_racket(?:\.\w+)+)")
RELATIVE = re.compile(r":(?:mod|func|class|data|attr|meth|exc):`~?(\.[\w.]+)`")
LINK = re.compile(r"\]\(((?!https?:|#|mailto:)[^)\s#]+)")
MARKDOWN = ["README.md", "REPRODUCTION.md", "meshes/README.md"]
#: Names left to their owners, skipped here, each as (file, name): a name that lands or is
#: corrected must leave this list (the docstring test fails on an entry no longer stale, so the
#: list cannot go dead).
PENDING: set[tuple[str, str]] = set()


def _markdown() -> list[Path]:
    return [ROOT / f for f in MARKDOWN if (ROOT / f).exists()] + sorted(ROOT.glob("docs/**/*.md"))


def _sources() -> list[Path]:
    return sorted(
        [*ROOT.glob("fem_racket/**/*.py"), *ROOT.glob("scripts/*.py"), *ROOT.glob("tests/**/*.py")]
    )


def _docstrings(path: Path) -> str:
    kinds = (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)
    tree = ast.parse(path.read_text())
    docs = [ast.get_docstring(n, clean=False) for n in ast.walk(tree) if isinstance(n, kinds)]
    return "\n".join(d for d in docs if d)


def path_exists(text: str) -> bool:
    name = text.rstrip("/.")
    return any(ROOT.glob(name)) if "*" in name else (ROOT / name).exists()


def name_exists(dotted: str) -> bool:
    """A module, or a name reachable from the longest importable prefix."""
    parts = dotted.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        for attr in parts[i:]:
            if not hasattr(obj, attr):
                return False
            obj = getattr(obj, attr)
        return True
    return False


def _module(path: Path) -> tuple[str, str]:
    """(the module's dotted name, its package)."""
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        name = ".".join(parts[:-1])
        return name, name
    name = ".".join(parts)
    return name, name.rsplit(".", 1)[0]


def stale(where: Path, text: str, *, relative_to: tuple[str, str] | None = None) -> list[str]:
    """The paths and names of ``text`` (found in ``where``) that do not exist."""
    out = [p for p in PATH.findall(text) if not path_exists(p)]
    out += [d for d in DOTTED.findall(text) if not name_exists(d)]
    if where.suffix == ".md":
        out += [u for u in LINK.findall(text) if not (where.parent / u).exists()]
    if relative_to is not None:
        module, package = relative_to
        for ref in RELATIVE.findall(text):
            if not (name_exists(package + ref) or name_exists(module + ref)):
                out.append(ref)
    return out


@pytest.mark.parametrize("path", _markdown(), ids=lambda p: str(p.relative_to(ROOT)))
def test_paths_and_modules_named_in_the_docs_exist(path):
    assert stale(path, path.read_text()) == []


def test_paths_and_modules_named_in_docstrings_exist():
    found = []
    for path in _sources():
        rel = str(path.relative_to(ROOT))
        package = _module(path) if rel.startswith("fem_racket/") else None
        found += [(rel, s) for s in stale(path, _docstrings(path), relative_to=package)]
    assert sorted(set(found) - PENDING) == []
    assert sorted(PENDING - set(found)) == [], "no longer stale: remove them from PENDING"


def test_the_check_finds_a_stale_name(tmp_path):
    text = "see `fem_racket/vtk.py`, fem_racket.figures.FIGURES and :mod:`.nowhere`"
    found = stale(tmp_path / "x.py", text, relative_to=("fem_racket.io.plotting", "fem_racket.io"))
    assert found == ["fem_racket/vtk.py", "fem_racket.figures.FIGURES", ".nowhere"]
    assert stale(tmp_path / "x.py", "`fem_racket/io/vtk.py`, fem_racket.simulate") == []
