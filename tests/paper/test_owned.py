"""Which files ``reproduce`` recognises as its own (so it may replace them): by provenance."""

import json

import numpy as np
import pytest

from fem_racket.io.figure_files import save_figure
from fem_racket.outputs import provenance
from fem_racket.outputs.owned import written_by_fem_racket


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


@pytest.mark.parametrize("suffix", ["png", "svg", "pdf"])
def test_commands_and_run_files_judge_a_figure_alike(figure, tmp_path, suffix):
    # one judgement (outputs.owned.own_output) for a command's default output and a run file's
    # method: a run file's method read an SVG or PDF by a sidecar it never has, the command by
    # the provenance the figure keeps
    import argparse

    from fem_racket.cli.options.rerun import replace_own
    from fem_racket.io.config_rerun import rerun_overwrite

    ours = save_figure(figure, tmp_path / f"ours.{suffix}", provenance())
    plain = tmp_path / f"plain.{suffix}"
    figure.savefig(plain)
    args = argparse.Namespace(overwrite=False)
    for path, own in ((ours, True), (plain, False)):
        assert rerun_overwrite(False, True, [path]) is own
        assert replace_own(args, True, [path]) is own
        assert rerun_overwrite(False, False, [path]) is False  # named with --out: never


def test_other_outputs_by_their_netcdf_sidecar_or_folder_marker(tmp_path):
    from fem_racket.outputs.netcdf import write_netcdf
    from fem_racket.outputs.owned import own_output

    meta = provenance()
    nc = tmp_path / "s.nc"
    write_netcdf(nc, {"cor": (("x",), np.array([0.4, 0.5]), {})}, {"software": "fem_racket"})
    (tmp_path / "t.csv").write_text("x [m]\n1\n")
    (tmp_path / "t.csv.json").write_text(json.dumps({"provenance": meta}))
    (tmp_path / "u.csv").write_text("x [m]\n1\n")
    (tmp_path / "series").mkdir()
    (tmp_path / "series" / "provenance.json").write_text(json.dumps(meta))
    (tmp_path / "mine").mkdir()
    assert own_output(nc) and own_output(tmp_path / "t.csv") and own_output(tmp_path / "series")
    assert not own_output(tmp_path / "u.csv") and not own_output(tmp_path / "mine")
