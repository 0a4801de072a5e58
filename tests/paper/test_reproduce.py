"""``fem-racket reproduce``: every figure, values.json and the report, called in-process."""

import json
import re
import time
from pathlib import Path

import pytest

from fem_racket.cli import main
from fem_racket.paper.claims import AGREES, DIFFERS, NOT_CHECKABLE
from fem_racket.paper.figures import FIGURES, expected_files

ROOT = Path(__file__).resolve().parents[2]
CELL = re.compile(r"(?<!\\)\|")  # a table-cell border (escaped pipes are cell text)


def verdicts(text: str) -> list[str]:
    """The verdict column of every claim row of the report's tables."""
    rows = [r for r in text.splitlines() if r.startswith("| ") and not r.startswith("| § |")]
    return [CELL.split(r)[4].strip(" *") for r in rows]


@pytest.fixture(scope="module")
def quick_run(tmp_path_factory):
    base = tmp_path_factory.mktemp("reproduce")
    out, report = base / "figs", base / "docs" / "REPORT.md"
    code = main(["reproduce", "--out", str(out), "--report", str(report), "--quick"])
    return code, out, report


def test_reproduce_writes_every_figure_values_and_report(quick_run, capsys):
    code, out, report = quick_run
    assert code == 0
    for spec in FIGURES.values():
        for p in expected_files(spec, out):
            assert p.is_file() and p.stat().st_size > 0, p
    data = json.loads((out / "values.json").read_text())
    assert set(data["values"]) == set(FIGURES)
    assert data["provenance"]["parameters"]["quick"] is True
    assert report.is_file()


def test_every_output_carries_the_provenance(quick_run):
    # values.json holds it for the folder (and so for its CSVs); each PNG in its text chunks;
    # the report in a closing HTML comment.
    from PIL import Image

    _, out, report = quick_run
    meta = json.loads((out / "values.json").read_text())["provenance"]
    params = meta["parameters"]
    assert meta["version"] and meta["created_utc"] and params["quick"] is True
    assert params["out"] == str(out) and params["report"] == str(report)
    assert params["solver"].startswith("exact") and params["separation"] == "displacement"
    for spec in FIGURES.values():
        with Image.open(out / f"{spec.name}.png") as im:
            im.load()
            assert json.loads(im.text["provenance"]) == meta, spec.name
    last = report.read_text().rstrip().splitlines()[-1]
    prefix = "<!-- provenance: "
    assert last.startswith(prefix) and last.endswith(" -->")
    assert json.loads(last[len(prefix) : -len(" -->")]) == meta


def test_report_embeds_every_figure_by_a_relative_link(quick_run):
    _, out, report = quick_run
    text = report.read_text()
    links = re.findall(r"!\[[^\]]*\]\(([^)]+\.png)\)", text)
    assert len(links) == len(FIGURES)
    for link in links:
        assert link.startswith("../figs/")  # relative to the report's folder
        assert (report.parent / link).resolve().is_file()
    assert "Quick run" in text


def test_report_has_a_verdict_row_per_claim(quick_run):
    _, _, report = quick_run
    text = report.read_text()
    claims = [r for r in text.splitlines() if r.startswith("| ") and not r.startswith("| § |")]
    assert len(claims) >= 30
    assert set(verdicts(text)) <= {AGREES, DIFFERS, NOT_CHECKABLE}
    for section in ("2.2", "3.1", "3.2", "3.3", "4.1", "4.2", "5", "Concl. (1)", "Concl. (4)"):
        assert any(r.startswith(f"| {section}") for r in claims), section


def test_reproduce_refuses_existing_outputs_before_computing(quick_run, capsys):
    _, out, report = quick_run
    t0 = time.perf_counter()
    code = main(["reproduce", "--out", str(out), "--report", str(report), "--quick"])
    assert code == 2
    assert time.perf_counter() - t0 < 2.0  # refused up front, not after the work
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "already exists" in err and "--overwrite" in err


def test_committed_report_covers_every_figure():
    """REPRODUCTION.md at the root is the command's output (regenerated, committed)."""
    text = (ROOT / "REPRODUCTION.md").read_text()
    assert "fem-racket reproduce" in text
    for spec in FIGURES.values():
        assert f"output/paper/{spec.name}.png" in text
    assert "Quick run" not in text


@pytest.mark.slow
def test_full_reproduction_matches_the_committed_verdicts(tmp_path):
    """Full resolution (~30 s): the verdicts equal those of the committed REPRODUCTION.md."""
    report = tmp_path / "REPRODUCTION.md"
    assert main(["reproduce", "--out", str(tmp_path / "paper"), "--report", str(report)]) == 0
    assert verdicts(report.read_text()) == verdicts((ROOT / "REPRODUCTION.md").read_text())
