"""The README's console examples print what the commands print."""

import re
from pathlib import Path

import pytest

from fem_racket.cli import main

README = Path(__file__).resolve().parent.parent / "README.md"


def _examples() -> list[tuple[str, list[str]]]:
    """(command line, printed lines) of README console blocks that show one whole output
    (a block with "..." abbreviates it, or holds run-dependent text such as timings)."""
    out = []
    for block in re.findall(r"```console\n(.*?)```", README.read_text(), flags=re.S):
        lines = block.splitlines()
        if sum(ln.startswith("$ ") for ln in lines) == 1 and "..." not in block:
            out.append((lines[0][2:], lines[1:]))
    return out


@pytest.mark.parametrize(("command", "printed"), _examples(), ids=lambda v: str(v)[:40])
def test_readme_example_output(capsys, monkeypatch, tmp_path, command, printed):
    monkeypatch.chdir(tmp_path)  # an example that writes a file writes it here
    (tmp_path / "examples").symlink_to(README.parent / "examples")  # the files examples read
    argv = command.split()
    assert argv[0] == "fem-racket"
    code = main(argv[1:])
    out, err = capsys.readouterr()
    assert [ln.rstrip() for ln in (out + err).splitlines()] == [ln.rstrip() for ln in printed]
    assert code == (2 if "error:" in err else 0)


def test_readme_library_section_shows_the_tours_first_cells_and_their_output(capsys):
    """The README's tour excerpt is the code of scripts/tour.py's first impact cells, and the
    text block after it is what that code prints."""
    text = README.read_text()
    marker = text.index("<!-- tour:")
    code, printed = re.findall(r"```(?:python|text)\n(.*?)```", text[marker:], flags=re.S)[:2]
    tour = (README.parent / "scripts" / "tour.py").read_text()
    parts = re.split(r"^# %%(.*)$", tour, flags=re.M)
    cells = [body.strip() for head, body in zip(parts[1::2], parts[2::2], strict=True)]
    code_cells = [c for c, head in zip(cells, parts[1::2], strict=True) if not head.strip()]
    assert code == "import fem_racket as fr\n\n" + "\n\n".join(code_cells[1:3]) + "\n"
    exec(compile(code, "README.md", "exec"), {})
    assert capsys.readouterr().out == printed
