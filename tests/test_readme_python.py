"""Every Python snippet of the README runs (in a scratch folder with ``output/``; a file a
snippet reads is first made by the README command that writes it). Slow: they run sweeps, an
optimisation and an animation; the tour excerpt is checked line by line in test_readme.py."""

import re
import shlex
from pathlib import Path

import pytest

from fem_racket.cli import main

README = Path(__file__).resolve().parent.parent / "README.md"


def _snippets() -> list[str]:
    text = README.read_text()
    tour = text.index("<!-- tour:")
    return [
        m.group(1)
        for m in re.finditer(r"```python\n(.*?)```", text, flags=re.S)
        if not tour < m.start() < tour + 200
    ]


def _makers(snippet: str) -> list[list[str]]:
    """The README commands writing a file ``snippet`` names (``--out output/fig13.nc``)."""
    out = []
    for line in re.findall(r"^\$ (fem-racket .*)$", README.read_text(), flags=re.M):
        argv = shlex.split(line.replace("\\", ""), comments=True)
        if "--out" in argv and argv[argv.index("--out") + 1] in snippet:
            out.append(argv[1:])
    return out


@pytest.mark.slow
@pytest.mark.parametrize("snippet", _snippets(), ids=lambda s: s.splitlines()[0][:40])
def test_readme_python_snippet_runs(monkeypatch, tmp_path, snippet):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    (tmp_path / "output").mkdir()
    for argv in _makers(snippet):
        assert main([*argv, "--quiet"] if argv[0] == "sweep" else argv) == 0
    exec(compile(snippet, "README.md", "exec"), {})


def test_every_snippet_is_found():
    snippets = _snippets()
    assert len(snippets) >= 3 and all(s.strip() for s in snippets)
    assert any("open_dataset" in s for s in snippets)
    assert _makers('xr.open_dataset("output/fig13.nc")')[0][:1] == ["sweep"]
