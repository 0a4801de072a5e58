"""``fem-racket reproduce --law NAME``: its own folder and report, the law in the provenance, bad
values refused with one line (called in-process)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from fem_racket.cli import build_parser, main
from fem_racket.cli.commands.reproduce import _destinations
from fem_racket.paper.claims.conclusions import CONCLUSIONS
from fem_racket.paper.figures import FIGURES, expected_files
from tests.clirun import refused_before_any_file

ROOT = Path(__file__).resolve().parents[2]
LAW = "kawazoe-1997-nonlinear"


def _args(*argv: str):
    return build_parser().parse_args(["reproduce", *argv])


@pytest.mark.parametrize(
    ("argv", "out", "report"),
    [
        ((), "output/paper", "REPRODUCTION.md"),  # today's behaviour
        (("--law", "linear"), "output/paper", "REPRODUCTION.md"),
        (("--law", LAW), f"output/paper/{LAW}", f"output/paper/{LAW}/REPRODUCTION.md"),
        (("--law", "series", "--out", "x"), "x", "x/REPRODUCTION.md"),
        (("--law", "hunt-crossley", "--report", "r.md"), "output/paper/hunt-crossley", "r.md"),
    ],
)
def test_a_law_writes_into_its_own_folder(argv, out, report):
    assert _destinations(_args(*argv)) == (out, report)


@pytest.mark.parametrize(
    ("argv", "names"),
    [
        (("--law", "rubber"), ("--law", "invalid choice", "kawazoe-1997-nonlinear")),
        (("--law", "series", "--k1", "3"), ("k1", "series")),
        (("--law", LAW, "--hc-alpha", "0.1"), ("preset",)),
        (("--law", "linear", "--k2", "1e16"), ("linear", "kcb")),
        (("--law", "hysteretic", "--k1", "-1"), ("k1 = -1", "> 0")),
        (("--law", "hysteretic", "--k1", "2e16", "--k2", "1e16"), ("k2", "k1")),
    ],
)
def test_bad_law_gives_one_line_exit_2_and_no_file(capsys, cwd, argv, names):
    line = refused_before_any_file(capsys, "reproduce", "--quick", *argv)
    for name in names:
        assert name in line, (name, line)


@pytest.mark.slow  # ~15 s: every figure under the law on the quick grids
def test_reproduce_with_a_law_writes_its_figures_report_and_provenance(tmp_path, capsys):
    from PIL import Image

    out = tmp_path / "law"
    code = main(["reproduce", "--law", LAW, "--quick", "--out", str(out)])
    assert code == 0
    printed = capsys.readouterr().out
    assert f"of the paper's 4 conclusions hold under {LAW}" in printed
    drawn = [k for k, s in FIGURES.items() if not s.law_skip]
    assert set(drawn) < set(FIGURES)  # Figs 11-12 are linear only
    for key in drawn:
        for p in expected_files(FIGURES[key], out):
            assert p.is_file(), p
    for key in set(FIGURES) - set(drawn):
        assert not (out / f"{FIGURES[key].name}.png").exists()
    data = json.loads((out / "values.json").read_text())
    meta = data["provenance"]
    assert meta["law"]["name"] == LAW and meta["law"]["law"] == "hysteretic"
    assert meta["parameters"]["law"] == LAW
    assert meta["parameters"]["report"] == str(out / "REPRODUCTION.md")
    with Image.open(out / "fig13_cor_rigidity.png") as im:
        im.load()
        assert json.loads(im.text["provenance"]) == meta
    text = (out / "REPRODUCTION.md").read_text()
    # the four conclusions, verbatim, each with a verdict
    for n, statement in CONCLUSIONS.items():
        row = next(r for r in text.splitlines() if r.startswith(f"| Concl. {n}"))
        assert statement in row
        assert "**holds**" in row or "**does not hold**" in row
    # the contact-time table shows the computed values (20, 30, 40 m/s; ms)
    values = data["values"]["fig02_03"]
    for s in ("20", "30", "40"):
        row = next(r for r in text.splitlines() if r.startswith(f"| {s} |"))
        assert f"{values[f'tc_clamped_{s}_s'] * 1e3:.2f}" in row
        assert f"{values[f'tc_free_75_{s}_s'] * 1e3:.2f}" in row
    for key in set(FIGURES) - set(drawn):
        assert f"{FIGURES[key].name}: not drawn" in text
    for link in re.findall(r"!\[[^\]]*\]\(([^)]+\.png)\)", text):
        assert (out / link).resolve().is_file()
