"""``fem-racket fit``: the mesh it writes has the asked specification and loads with --mesh."""

from __future__ import annotations

import json

import pytest
from clirun import run, run_json

from fem_racket.frame.specs import KG_CM2, racket_spec
from fem_racket.io.mesh_files import read_mesh

SPEC = ("--length", "0.685", "--mass", "0.318", "--balance", "0.32", "--swing-weight", "316")


def test_fit_writes_a_mesh_with_the_specification(capsys, tmp_path):
    out = tmp_path / "r.vtu"
    data = run_json(capsys, "fit", *SPEC, "--f1", "150", "--out", out)
    got = racket_spec(read_mesh(out))
    # Issue 14: mass, balance, swing weight to 0.1 %, f1 to 0.5 % (fitted exactly here).
    assert got.mass == pytest.approx(0.318, rel=1e-9)
    assert got.balance == pytest.approx(0.32, rel=1e-9)
    assert got.swing_weight == pytest.approx(316 * KG_CM2, rel=1e-9)
    assert got.f1 == pytest.approx(150.0, rel=1e-6)
    assert data["fitted"]["swing_weight_kg_cm2"] == pytest.approx(316.0, rel=1e-9)
    side = json.loads((tmp_path / "r.vtu.json").read_text())
    assert side["target"]["f1_hz"] == 150.0 and "version" in side
    code, text, err = run(capsys, "simulate", "--mesh", str(out), "--json")
    assert code == 0, err


def test_inconsistent_specification_is_one_line_and_no_file(capsys, tmp_path):
    out = tmp_path / "r.vtu"
    code, _, err = run(capsys, "fit", *SPEC[:-1], "600", "--out", str(out))
    assert code == 2
    assert "swing weight = 600 kg cm^2 is not allowed" in err and len(err.splitlines()) == 1
    assert not out.exists()
