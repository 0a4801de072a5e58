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
    # What the figures used, not what was asked (80 modes asked, a 20-element mesh has 40).
    used = meta["used"]
    assert used["solver"] == "exact" and used["separation"] == "displacement"
    assert used["modes"] == 40 and used["elements"] == 20 and used["rtol"] is None
    assert used["zeta"] == pytest.approx(0.0592, abs=5e-5)  # clamped COR 0.83, eq 4
    assert used["kcb_n_m_at_20_30_40_m_s"] == pytest.approx([2.74e4, 5.0e4, 8.33e4])  # §2.1.1
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


def test_reproduce_refuses_a_file_it_did_not_write_before_computing(quick_run, capsys):
    _, out, report = quick_run
    text = report.read_text()
    user = report.with_name("USER.md")
    user.write_text("# my notes\n")
    t0 = time.process_time()  # CPU seconds: other processes on the machine do not count
    code = main(["reproduce", "--out", str(out), "--report", str(user), "--quick"])
    assert code == 2
    assert time.process_time() - t0 < 2.0  # refused up front, not after the work
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "not a file fem-racket reproduce wrote" in err
    assert "--overwrite" in err and user.read_text() == "# my notes\n"
    assert report.read_text() == text


def test_reproduce_replaces_its_own_files_but_never_a_users(tmp_path):
    # A fresh clone holds the committed figures: a rerun replaces them without --overwrite
    # (recognised by their provenance), but a file it did not write needs --overwrite.
    from PIL import Image

    from fem_racket.paper.reproduce import reproduce
    from fem_racket.validation import InputError

    out = tmp_path / "figs"
    first = reproduce(out, quick=True, figures=["fig04"])
    png = out / "fig04_frame_modes.png"
    committed = png.read_bytes()
    again = reproduce(out, quick=True, figures=["fig04"])
    assert [p.name for p in again.files] == [p.name for p in first.files]
    # An unchanged image is left as it is (no difference for version control).
    assert png.read_bytes() == committed
    Image.new("RGB", (8, 8)).save(png)  # a user's image, without our provenance
    before = png.read_bytes()
    with pytest.raises(InputError, match="not a file fem-racket reproduce wrote"):
        reproduce(out, quick=True, figures=["fig04"])
    assert png.read_bytes() == before
    reproduce(out, quick=True, figures=["fig04"], overwrite=True)
    assert png.read_bytes() != before


def test_committed_report_covers_every_figure():
    """REPRODUCTION.md at the root is the command's output (regenerated, committed)."""
    text = (ROOT / "REPRODUCTION.md").read_text()
    assert "fem-racket reproduce" in text
    for spec in FIGURES.values():
        assert f"output/paper/{spec.name}.png" in text
        # committed beside it, so the report shows its figures right after git clone
        assert (ROOT / "output" / "paper" / f"{spec.name}.png").is_file()
    assert "Quick run" not in text


@pytest.mark.slow
def test_full_reproduction_matches_the_committed_verdicts(tmp_path):
    """Full resolution (~30 s): the verdicts equal those of the committed REPRODUCTION.md."""
    report = tmp_path / "REPRODUCTION.md"
    assert main(["reproduce", "--out", str(tmp_path / "paper"), "--report", str(report)]) == 0
    assert verdicts(report.read_text()) == verdicts((ROOT / "REPRODUCTION.md").read_text())


def test_rerun_leaves_an_unchanged_report_as_it_is(quick_run):
    """The committed report is not rewritten when only its provenance would change."""
    _, out, report = quick_run
    before = report.read_text()
    assert main(["reproduce", "--out", str(out), "--report", str(report), "--quick"]) == 0
    assert report.read_text() == before
