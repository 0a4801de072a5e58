"""``fem-racket customise``: the written racket has the reported specs; planted lead recovered."""

from __future__ import annotations

import json

import numpy as np
import pytest
from clirun import run, run_json

from fem_racket import frame_mesh, standard_frame
from fem_racket.frame.catalogue import catalogue
from fem_racket.frame.head import DEFAULT_HEAD
from fem_racket.frame.lead import Lead, add_lead, lead_moments
from fem_racket.frame.specs import KG_CM2
from fem_racket.io.mesh_files import read_mesh


def test_customise_recovers_planted_lead_and_the_mesh_has_the_reported_specs(capsys, tmp_path):
    planted = {"12": 0.006, "handle": 0.004}
    mesh = frame_mesh(standard_frame(), 20)
    want = catalogue(add_lead(mesh, [Lead(p, m) for p, m in planted.items()], DEFAULT_HEAD))
    out, maps = tmp_path / "c.vtu", tmp_path / "c.nc"
    code, text, err = run(
        capsys, "customise", "--swing-weight", repr(want.swing_weight / KG_CM2),
        "--balance", repr(want.balance), "--places", "12,handle", "--out", out, "--maps", maps,
        "--json",
    )  # fmt: skip
    assert code == 0, err
    data = json.loads(text)
    assert data["placement_g"] == pytest.approx({p: m * 1e3 for p, m in planted.items()}, rel=1e-8)
    assert data["added_mass_g"] == pytest.approx(10.0, rel=1e-8)
    # every spec recomputed from the written mesh equals the reported one (issue 28: 1e-9)
    again = catalogue(read_mesh(out)).as_dict()
    for key, value in data["after"].items():
        assert again[key] == (None if value is None else pytest.approx(value, rel=1e-9)), key
    assert data["after"]["swing_weight_kg_cm2"] == pytest.approx(
        want.swing_weight / KG_CM2, rel=1e-12
    )
    assert set(data["maps"]) == {"before", "customised"}
    assert maps.is_file() and (tmp_path / "c.vtu.json").is_file()


def test_customise_range_target_and_table(capsys, tmp_path):
    code, text, err = run(
        capsys, "customise", "--swing-weight", "305:320", "--mass", "0.3:0.4", "--places", "3/9",
        "--out", tmp_path / "c.vtu", "--maps", tmp_path / "c.png",
    )  # fmt: skip
    assert code == 0, err
    assert "at 3/9" in text and "swing_weight_kg_cm2" in text


def test_keep_holds_the_racket_value(capsys, tmp_path):
    data = run_json(
        capsys, "customise", "--swing-weight", "320", "--balance", "keep",
        "--places", "12,3/9,handle", "--out", tmp_path / "c.vtu", "--maps", tmp_path / "c.nc",
    )  # fmt: skip
    assert data["after"]["balance_m"] == pytest.approx(data["before"]["balance_m"], rel=1e-12)
    assert data["targets"]["balance_m"] == [data["before"]["balance_m"]] * 2
    # the tip and the handle: cheaper than 3/9 for swing weight at a fixed balance
    assert data["placement_g"]["3/9"] == 0.0
    # independent path: the 2 x 2 system of the two places used (swing weight up, balance kept)
    head, b = DEFAULT_HEAD, data["before"]["balance_m"]
    k12, kh = lead_moments("12", head), lead_moments("handle", head)
    a = [[k12[2], kh[2]], [k12[1] - b, kh[1] - b]]
    dsw = (320.0 - data["before"]["swing_weight_kg_cm2"]) * KG_CM2
    m12, mh = np.linalg.solve(a, [dsw, 0.0])
    assert data["placement_g"]["12"] == pytest.approx(m12 * 1e3, rel=1e-8)
    assert data["placement_g"]["handle"] == pytest.approx(mh * 1e3, rel=1e-8)


def test_customise_twist_weight_at_3_9_and_the_mesh_file_carries_it(capsys, tmp_path):
    out = tmp_path / "c.vtu"
    base = catalogue(frame_mesh(standard_frame(), 20), f1=False).twist_weight / KG_CM2
    data = run_json(
        capsys, "customise", "--twist-weight", repr(base + 1.0), "--places", "3/9",
        "--out", out, "--maps", tmp_path / "m.nc",
    )  # fmt: skip
    r = DEFAULT_HEAD.width_m / 2
    # 1 kg cm^2 = m r^2: m = 1e-4 / r^2 kg
    assert data["placement_g"]["3/9"] == pytest.approx(1e-4 / r**2 * 1e3, rel=1e-9)
    again = catalogue(read_mesh(out))
    assert again.twist_weight / KG_CM2 == pytest.approx(base + 1.0, rel=1e-9)
    assert data["after"]["torsion_f1_hz"] == pytest.approx(again.torsion_f1, rel=1e-9)
