"""Small modules: no module of the package is longer than 300 lines (the house rule)."""

from __future__ import annotations

from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "fem_racket"
#: The most lines a module may have.
MAX_LINES = 300


def test_no_module_exceeds_300_lines():
    modules = sorted(PACKAGE.rglob("*.py"))
    assert len(modules) > 100  # the package's modules were found
    long = {
        str(p.relative_to(PACKAGE.parent)): n
        for p in modules
        if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAX_LINES
    }
    assert long == {}, f"modules longer than {MAX_LINES} lines: {long}"
