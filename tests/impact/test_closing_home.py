"""The closing speed's checks live in one module, :mod:`fem_racket.impact.closing`, and are
imported from there: :mod:`fem_racket.impact.swing` re-exported them after they moved (two
homes for one check)."""

from __future__ import annotations

import ast
from pathlib import Path

import fem_racket.impact.closing as closing
import fem_racket.impact.swing as swing

ROOT = Path(__file__).resolve().parents[2]
CHECKS = set(closing.__all__)  # check_kcb_closing, closing_speed
#: Not yet moved by their owner this session (studies/racket_map.py takes closing_speed from
#: swing, which uses it itself); the list may only shrink.
NOT_YET = {"fem_racket/studies/racket_map.py"}


def test_swing_does_not_reexport_the_closing_checks():
    assert CHECKS == {"check_kcb_closing", "closing_speed"}
    assert not CHECKS & set(swing.__all__)
    assert not hasattr(swing, "check_kcb_closing")  # closing_speed: swing_setup uses it


def test_the_closing_checks_are_imported_from_their_home():
    wrong = []
    for path in sorted([*ROOT.glob("fem_racket/**/*.py"), *ROOT.glob("scripts/*.py"),
                        *ROOT.glob("tests/**/*.py")]):  # fmt: skip
        rel = path.relative_to(ROOT).as_posix()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom) and node.module == "fem_racket.impact.swing":
                if CHECKS & {a.name for a in node.names} and rel not in NOT_YET:
                    wrong.append(f"{rel}:{node.lineno}")
    assert not wrong
