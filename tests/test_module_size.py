"""Small parts: no module of the package is longer than 300 lines and no function takes more than
10 parameters (the house rules; issue 21: options travel as small objects, not keyword chains)."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "fem_racket"
MODULES = sorted(PACKAGE.rglob("*.py"))
#: The most lines a module may have.
MAX_LINES = 300
#: The most parameters a function may take (``self``/``cls`` not counted; ``*args`` and
#: ``**kwargs`` count one each).
MAX_PARAMETERS = 10


def parameter_count(node: ast.FunctionDef | ast.AsyncFunctionDef) -> int:
    """The parameters of a function definition, ``self``/``cls`` of a method not counted."""
    a = node.args
    names = [p.arg for p in (*a.posonlyargs, *a.args)]
    n = len(names) + len(a.kwonlyargs) + (a.vararg is not None) + (a.kwarg is not None)
    return n - (bool(names) and names[0] in ("self", "cls"))


def test_no_module_exceeds_300_lines():
    assert len(MODULES) > 100  # the package's modules were found
    long = {
        str(p.relative_to(PACKAGE.parent)): n
        for p in MODULES
        if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAX_LINES
    }
    assert long == {}, f"modules longer than {MAX_LINES} lines: {long}"


def test_no_function_takes_more_than_10_parameters():
    wide = {}
    for p in MODULES:
        for node in ast.walk(ast.parse(p.read_text(encoding="utf-8"))):
            if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
                if (n := parameter_count(node)) > MAX_PARAMETERS:
                    wide[f"{p.relative_to(PACKAGE.parent)}:{node.lineno} {node.name}"] = n
    assert wide == {}, f"functions taking more than {MAX_PARAMETERS} parameters: {wide}"


@pytest.mark.parametrize(
    ("source", "count"),
    [
        ("def f(a, b=1, *c, d, e=2, **f): pass", 6),
        ("class K:\n    def m(self, a, /, b): pass", 2),
        ("class K:\n    @classmethod\n    def m(cls, *, a): pass", 1),
        ("def f(" + ", ".join(f"p{i}" for i in range(11)) + "): pass", 11),
    ],
)
def test_parameters_are_counted_as_the_rule_says(source, count):
    node = next(n for n in ast.walk(ast.parse(source)) if isinstance(n, ast.FunctionDef))
    assert parameter_count(node) == count
