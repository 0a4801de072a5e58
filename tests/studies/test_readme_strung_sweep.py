"""README's sweep section says what a string bed does not take: each thing it names is refused by
``fem-racket sweep --string-tension``, and what the sweep runs (an offset, as ``simulate``) is
not named there (audit A5: the sentence named the offset, which the sweep runs)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from clirun import run

README = Path(__file__).resolve().parents[2] / "README.md"
#: Each thing the sentence may name -> the sweep options that ask for it on a string bed.
ITEMS = {
    "swing": ("--racket-speed", "10"),
    "offset": ("--offset", "0.03", "--position", "0.7"),
    "`--kcb`": ("--kcb", "1e5"),
    "`--zeta`": ("--zeta", "0.05"),
    "`bdf`": ("--solver", "bdf"),
    "`--tolerance`": ("--tolerance", "1e-3"),
    "`--modes`": ("--modes", "10"),
    "side angle": ("--angle", "20", "--side-angle", "0,10"),
    "side spin": ("--side-spin", "0,1000"),
}


def _refused_sentence() -> str:
    text = " ".join(README.read_text(encoding="utf-8").split())
    m = re.search(r"A string bed takes no (.*?)\(as `simulate`", text)
    assert m, "README: the sweep's string-bed sentence is gone"
    return m.group(1)


@pytest.mark.parametrize("item", sorted(ITEMS))
def test_what_readme_says_a_strung_sweep_refuses_it_refuses(cwd, capsys, item):
    named = re.search(rf"(?<![-\w]){re.escape(item)}(?![-\w])", _refused_sentence()) is not None
    argv = ("sweep", "--string-tension", "250", *ITEMS[item], "--out", "s.nc", "--quiet")
    code, _, err = run(capsys, *argv)
    assert code == (2 if named else 0), (item, named, err)
    if named:  # refused before any work, naming it
        assert err.count("\n") == 1 and "string" in err and not Path("s.nc").exists(), err
