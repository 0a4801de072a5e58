"""The README's console examples print what the commands print.

Every ``console`` block is run, each ``$ fem-racket ...`` line in order in one scratch folder
(``meshes/`` beside it), and the lines the block shows are compared with the printed ones: a
line ``...`` stands for any lines, a line ending in ``, ...`` for the rest of a long line, and
run times (``in 0.18 s (6936 impacts/s)``, ``15.2 s in all``, refine's timing columns) are
not compared. A command
the block shows no output for must succeed. Cheap blocks run in the default suite, long ones
(reproduce, optimize, the sweeps, animate) are marked slow; a block that cannot run here (a full
disk, a Ctrl-C) is left out.
"""

import re
import shlex
from pathlib import Path

import pytest

from fem_racket.cli import main

README = Path(__file__).resolve().parent.parent / "README.md"
#: Commands that take more than a few seconds: run with ``-m slow``.
SLOW = ("reproduce", "optimize", "sensitivity", "animate", "sweep")
#: Blocks that need what a test cannot give (a full disk, a signal).
UNRUNNABLE = ("/mnt/full", "# Ctrl-C")
_TIMING = re.compile(r"\d+(\.\d+)? s (\(\d+ impacts/s\)|in all)")
#: Tables whose last columns are run times: the header's end -> how many columns.
_TIMED_COLUMNS = {"build [s] impact [ms]": 2}


def _mask(lines: list[str]) -> list[str]:
    """``lines`` with run times replaced by ``T``: sweep's rate, refine's timing columns."""
    out, drop = [], 0
    for line in lines:
        if drop and re.match(r"\s+\d", line):
            words = line.split()
            line = " ".join(words[:-drop] + ["T"] * drop)
        else:
            drop = next((n for end, n in _TIMED_COLUMNS.items() if line.endswith(end)), 0)
        out.append(_TIMING.sub("T", line))
    return out


def _blocks() -> list[list[tuple[list[str], list[str]]]]:
    """Each console block as (argv, printed lines) per command."""
    out = []
    for block in re.findall(r"```console\n(.*?)```", README.read_text(), flags=re.S):
        if any(u in block for u in UNRUNNABLE):
            continue
        steps: list[tuple[list[str], list[str]]] = []
        for line in block.splitlines():
            if line.startswith("$ "):
                steps.append((shlex.split(line[2:].replace("\\", ""), comments=True), []))
            else:
                steps[-1][1].append(line.rstrip())
        out.append(steps)
    return out


def _merge_continuations(steps):
    """A command continued on the next lines (``\\`` at the end) is one command."""
    merged = []
    for argv, printed in steps:
        while printed and printed[0].startswith("    ") and printed[0].strip().startswith("-"):
            argv = argv + shlex.split(printed.pop(0).replace("\\", ""))
        merged.append((argv, printed))
    return merged


def _same(expected: str, got: str) -> bool:
    if expected.endswith(", ..."):
        return got.startswith(expected[:-3])
    return expected == got


def matches(expected: list[str], got: list[str]) -> bool:
    """``got`` as ``expected`` shows it: segments between ``...`` lines in order, the first at
    the start and the last at the end (when the block does not end in ``...``)."""
    expected, got = _mask(expected), _mask(got)
    segments = [[]]
    for line in expected:
        if line == "...":
            segments.append([])
        else:
            segments[-1].append(line)
    at = 0
    for k, seg in enumerate(segments):
        if k == len(segments) - 1 and len(segments) > 1 and seg:
            at = max(at, len(got) - len(seg))  # the last segment ends the output
        while at + len(seg) <= len(got):
            if all(_same(e, g) for e, g in zip(seg, got[at:], strict=False)):
                break
            if k == 0:
                return False  # the first segment starts the output
            at += 1
        else:
            return False
        at += len(seg)
    return at == len(got) or expected[-1] == "..."


def _params():
    for steps in _blocks():
        steps = _merge_continuations(steps)
        slow = any(argv[1] in SLOW for argv, _ in steps)
        marks = [pytest.mark.slow] if slow else []
        name = " && ".join(" ".join(a[1:4]) for a, _ in steps)[:60]
        yield pytest.param(steps, marks=marks, id=name)


@pytest.mark.parametrize("steps", list(_params()))
def test_readme_example_output(capsys, monkeypatch, tmp_path, steps):
    monkeypatch.chdir(tmp_path)  # an example that writes a file writes it here
    (tmp_path / "meshes").symlink_to(README.parent / "meshes")
    for argv, printed in steps:
        assert argv[0] == "fem-racket"
        code = main(argv[1:])
        out, err = capsys.readouterr()
        got = [ln.rstrip() for ln in (out + err).splitlines()]
        if printed:
            assert matches(printed, got), "\n".join(got)
        assert code == (2 if "error:" in err else 0), err


def test_the_comparison_holds_the_lines_it_shows():
    got = ["a", "b 1", "c", "wrote x: 3 impacts in 0.20 s (15 impacts/s)", "d"]
    timed = [" n build [s] impact [ms]", "  5 1.5 0.002 6.71"]
    assert matches(timed, [timed[0], "  5 1.5 0.009 5.02"])
    assert not matches(timed, [timed[0], "  5 1.6 0.002 6.71"])
    assert matches(["a", "...", "d"], got)
    assert matches(["a", "b 1", "...", "wrote x: 3 impacts in 9.99 s (1 impacts/s)", "d"], got)
    assert not matches(["a", "b 2", "..."], got)  # a number printed otherwise
    assert not matches(["a", "...", "c"], got)  # the output goes on
    assert not matches(["b 1", "..."], got)  # the output starts otherwise
    assert matches(["a", "b 1, ..."], ["a", "b 1, and more"])


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
