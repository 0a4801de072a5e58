"""A sweep strikes the strung racket off its long axis as ``simulate`` does: it refused any
offset with a string bed ("the strung racket is struck on its long axis") though
``simulate --string-tension 246 --offset 0.05`` runs off-axis; the problem checks the point."""

from __future__ import annotations

import csv

import pytest
from clirun import run, run_json


def test_the_sweep_strikes_the_bed_off_axis_as_simulate(tmp_path, capsys):
    out = tmp_path / "s.csv"
    argv = ["sweep", "--string-tension", "246", "--offset", "0.05", "--position", "0.6,0.75"]
    code, _, err = run(capsys, *argv, "--serial", "--quiet", "--out", out)
    assert code == 0, err
    with out.open() as f:
        rows = list(csv.DictReader(f))
    for row in rows:
        x = float(row["position [x/L]"])
        alone = run_json(capsys, "simulate", "--string-tension", 246, "--offset", 0.05,
                         "--position", x)  # fmt: skip
        assert float(row["cor [-]"]) == pytest.approx(alone["cor"], rel=1e-12)
    on_axis = run_json(capsys, "simulate", "--string-tension", 246, "--position", 0.75)
    assert abs(float(rows[1]["cor [-]"]) - on_axis["cor"]) > 1e-3  # the offset is used
