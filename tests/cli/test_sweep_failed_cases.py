"""A sweep with failed cases says so once, and its COR range says which cases it covers: it
printed "N cases failed" per chunk and again for the sweep, and "COR from a to b" as if every
case had succeeded (a NaN case left out silently)."""

from __future__ import annotations

import logging

from clirun import run

from fem_racket.cli.commands.sweep import _cor_range


def test_failed_cases_are_noted_once(tmp_path, capsys, caplog, monkeypatch):
    # every case refused by the modes' accuracy check, made impossible (as
    # tests/studies/test_sweep_limits.py): a legitimate failure of each case
    from fem_racket.frame import curvature
    from fem_racket.studies.cases import clear_caches

    clear_caches()
    monkeypatch.setattr(curvature, "RESIDUAL_TOL", 0.0)
    out = tmp_path / "s.csv"
    try:
        with caplog.at_level(logging.WARNING):
            code, printed, _ = run(
                capsys, "sweep", "--ei1", "100,200", "--serial", "--quiet", "--out", out
            )
    finally:
        clear_caches()
    assert code == 0
    counted = [r.getMessage() for r in caplog.records if "of 2 cases failed" in r.getMessage()]
    assert counted == ["2 of 2 cases failed: NaN in the dataset, first: case 0"]
    assert not [r for r in caplog.records if r.name == "fem_racket.studies.cases"]
    assert "failed its accuracy check" in caplog.text  # the cause, from the solver
    assert printed.splitlines()[-1] == "COR: every case failed (2 of 2)"


def test_the_cor_range_says_how_many_cases_failed():
    summary = {"impacts": 2, "cor_min": 0.36859, "cor_max": 0.36859}
    assert _cor_range(summary, 1) == "COR from 0.368590 to 0.368590 (1 of 2 cases failed)"
    assert _cor_range(summary, 0) == "COR from 0.368590 to 0.368590"
