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


def test_f1_every_reader_refuses_is_refused_at_fit(capsys, tmp_path):
    # The readers bound the uniform beam's f1 from the mean EI to [1, 50000] Hz
    # (frame/plausible.py); on this racket that estimate is 0.9166 of the FE f1, so fit refuses
    # f1 below 1/0.9166 = 1.091 Hz, with that bound (rounded up), and writes nothing.
    out = tmp_path / "r.vtu"
    code, _, err = run(capsys, "fit", *SPEC, "--f1", "1", "--out", str(out))
    assert code == 2 and len(err.splitlines()) == 1 and not out.exists()
    assert err.strip() == (
        "fem-racket fit: error: f1 = 1.0 Hz is not allowed: must be at least 1.091 Hz for this "
        "racket (its mean EI then gives the uniform beam's first free-free frequency, 0.9166 Hz "
        "here, within [1, 50000] Hz, the bound every reader of a mesh applies)"
    )
    # the bound printed is allowed, and the mesh it writes is read by modes and simulate
    run_json(capsys, "fit", *SPEC, "--f1", "1.091", "--out", out)
    assert run(capsys, "modes", "--mesh", str(out), "--json")[0] == 0
    assert run(capsys, "simulate", "--mesh", str(out), "--json")[0] == 0
