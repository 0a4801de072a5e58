"""Which files ``reproduce`` recognises as its own (so it may replace them): by provenance."""

import json

import pytest

from fem_racket.io.figure_files import save_figure
from fem_racket.outputs import provenance
from fem_racket.paper.owned import written_by_fem_racket


@pytest.fixture
def figure():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(2, 2))
    ax.plot([0, 1])
    yield fig
    plt.close(fig)


@pytest.mark.parametrize("suffix", ["png", "svg", "pdf"])
def test_figures_ours_by_provenance_a_plain_one_not(figure, tmp_path, suffix):
    ours = save_figure(figure, tmp_path / f"ours.{suffix}", provenance())
    plain = tmp_path / f"plain.{suffix}"
    figure.savefig(plain)
    assert written_by_fem_racket(ours)
    assert not written_by_fem_racket(plain)


def test_values_report_and_listed_tables(tmp_path):
    meta = provenance()
    (tmp_path / "values.json").write_text(json.dumps({"provenance": meta, "files": ["a.csv"]}))
    (tmp_path / "a.csv").write_text("x [m]\n1\n")
    (tmp_path / "b.csv").write_text("x [m]\n1\n")
    report = tmp_path / "R.md"
    report.write_text(f"# text\n\n<!-- provenance: {json.dumps(meta)} -->\n")
    notes = tmp_path / "notes.md"
    notes.write_text("# my notes\n")
    assert written_by_fem_racket(tmp_path / "values.json")
    assert written_by_fem_racket(tmp_path / "a.csv")
    assert not written_by_fem_racket(tmp_path / "b.csv")  # not listed: a user's table
    assert written_by_fem_racket(report) and not written_by_fem_racket(notes)
    assert not written_by_fem_racket(tmp_path / "missing.png")
    (tmp_path / "values.json").write_text("{}")  # no provenance: nothing listed is ours
    assert not written_by_fem_racket(tmp_path / "a.csv")
