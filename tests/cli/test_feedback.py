"""Feedback on long work: progress bars on a terminal only, --quiet, -v after the command."""

import pytest

from fem_racket.cli import main
from fem_racket.progress import progress_bar


def test_progress_bar_shows_when_enabled_and_hides_off_a_terminal(capsys):
    assert list(progress_bar(range(3), desc="work", unit="step", enabled=True)) == [0, 1, 2]
    err = capsys.readouterr().err
    assert "work:" in err and "0/3" in err  # the bar is cleared when done (leave=False)
    # None: only on a terminal; pytest's captured stderr is not one.
    assert list(progress_bar(range(3), desc="work", enabled=None)) == [0, 1, 2]
    assert capsys.readouterr().err == ""


@pytest.mark.parametrize(
    "argv",
    [
        ["modes", "-v", "--quiet"],
        ["simulate", "--json", "-v"],
        ["refine", "--elements", "5,10", "--no-files", "--quiet", "--verbose"],
    ],
)
def test_verbose_after_the_command_and_quiet(argv, capsys):
    assert main(argv) == 0
    assert "%" not in capsys.readouterr().err  # no bar with --quiet or off a terminal


def test_figure_script_and_reproduce_write_svg_and_pdf(tmp_path):
    from fem_racket.paper.figures import make_figure
    from fem_racket.paper.reproduce import render_report, reproduce

    _, files = make_figure("fig04", tmp_path / "s", quick=True, fmt="svg", dpi=300)
    assert files[-1].suffix == ".svg" and files[-1].read_text().lstrip().startswith("<?xml")
    done = reproduce(tmp_path / "p", quick=True, figures=["fig04"], fmt="pdf")
    pdf = [p for p in done.files if p.suffix == ".pdf"]
    assert pdf and pdf[0].read_bytes().startswith(b"%PDF")
    text = render_report(done.figures, [], "figs", fmt="pdf")
    assert "[Fig. 4" in text and "(figs/fig04_frame_modes.pdf)" in text and "![" not in text


def test_reproduce_bar_names_each_phase_and_ends_with_the_work(tmp_path, capsys):
    # One bar over the whole work: it reached 10/10 at ~9 s of a 54 s run when it counted only
    # the computing; drawing the figures took the rest.
    from fem_racket.paper.reproduce import reproduce

    reproduce(tmp_path, quick=True, figures=["fig04"], progress=True)
    err = capsys.readouterr().err
    assert "reproduce: computing fig04" in err and "reproduce: drawing fig04" in err
    assert "1/2" in err and "2/2" in err
    assert err.index("computing fig04") < err.index("drawing fig04")
