"""``refine --impact-modes N`` and ``[refine] impact_modes`` are used: the impacts keep at most
N flexible modes, as ``simulate --modes N`` on the same mesh (they only sized the eigen-solve
and the impacts kept every mode: ``--impact-modes 1`` gave the default's COR)."""

from __future__ import annotations

import pytest
from clirun import run_json

from fem_racket import load_config

REFINE = ["refine", "--elements", "10,20", "--count", "2", "--positions", "0.75"]
QUIET = ["--quiet", "--no-files"]


def test_impact_modes_sets_the_impacts_modes(capsys):
    default = run_json(capsys, *REFINE, *QUIET)
    one = run_json(capsys, *REFINE, *QUIET, "--impact-modes", "1")
    assert default["impact_modes_used"] == [20, 40]  # every mode of the mesh (80 at most)
    assert one["impact_modes_used"] == [1, 1]
    assert abs(one["cor"][0][0] - default["cor"][0][0]) > 1e-3
    for row, n in zip(one["cor"], (10, 20), strict=True):
        alone = run_json(capsys, "simulate", "--elements", n, "--position", 0.75, "--modes", 1)
        assert row[0] == pytest.approx(alone["cor"], rel=1e-12)


def test_the_run_files_impact_modes_is_used(tmp_path, capsys):
    path = tmp_path / "run.toml"
    path.write_text(
        "[refine]\nelements = [10]\ncount = 1\npositions = [0.75]\nimpact_modes = 1\n"
        'family = "uniform"\n'
    )
    study = load_config(path).refine()["uniform"]
    assert study.impact_modes_used.tolist() == [1]
    cli = run_json(capsys, "refine", "--config", path, *QUIET)
    assert cli["impact_modes_used"] == [1]
    assert study.cor[0, 0] == pytest.approx(cli["cor"][0][0], rel=1e-12)
