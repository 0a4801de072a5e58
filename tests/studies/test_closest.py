"""closest: ranking by scaled distance; the least lead of each; the example CSV and its errors."""

from __future__ import annotations

from pathlib import Path

import pytest
from clirun import run, run_json

from fem_racket import frame_mesh, standard_frame
from fem_racket.frame.catalogue import Catalogue, catalogue
from fem_racket.frame.head import DEFAULT_HEAD
from fem_racket.frame.lead import Lead, add_lead
from fem_racket.frame.specs import KG_CM2
from fem_racket.io.racket_table import read_rackets
from fem_racket.studies.closest import Listed, closest, distance, predicted
from fem_racket.studies.customise import Target
from fem_racket.validation import InputError

EXAMPLE = Path(__file__).resolve().parents[2] / "meshes" / "rackets.csv"


def listed(name, mass, balance, sw, tw=None):
    return Listed(name, Catalogue(0.685, mass, balance, sw * KG_CM2, tw and tw * KG_CM2))


def test_distance_is_zero_inside_the_ranges_and_scaled_outside():
    r = listed("a", 0.320, 0.320, 320)
    assert distance(r, {"mass": Target(0.3, 0.33)}) == (0.0, [])
    # 10 g ~ 1 unit, 10 kg cm^2 ~ 1 unit: sqrt(2^2 + 1^2)
    d, missing = distance(r, {"mass": Target(0.34, 0.34), "swing_weight": Target(0.031, 0.031)})
    assert d == pytest.approx(5**0.5, rel=1e-12) and missing == []
    assert distance(r, {"twist_weight": Target(0.0014, 0.0014)}) == (0.0, ["twist_weight"])


def test_predicted_numbers_are_the_mesh_numbers():
    mesh = frame_mesh(standard_frame(), 20)
    head = DEFAULT_HEAD.on_frame(mesh.length)
    added = {"12": 0.004, "3/9": 0.006, "0.2": 0.003}
    want = catalogue(add_lead(mesh, [Lead(p, m) for p, m in added.items()], head), f1=False)
    got = predicted(catalogue(mesh, f1=False), added, head)
    assert got.mass == pytest.approx(want.mass, rel=1e-13)
    assert got.balance == pytest.approx(want.balance, rel=1e-12)
    assert got.swing_weight == pytest.approx(want.swing_weight, rel=1e-12)


def test_nearest_first_each_with_its_least_lead():
    rackets = [listed("far", 0.30, 0.30, 300), listed("near", 0.318, 0.32, 318)]
    target = {"swing_weight": Target(0.0325, 0.0325), "balance": Target(0.32, 0.32)}
    out = closest(rackets, target, ["12", "handle"], count=2)
    assert [m.listed.name for m in out] == ["near", "far"]
    near = out[0]
    assert near.after.swing_weight == pytest.approx(0.0325, rel=1e-9)
    assert near.after.balance == pytest.approx(0.32, rel=1e-9)
    # lighter than the racket: lead cannot, and says why
    heavy = closest(rackets, {"mass": Target(0.25, 0.26)}, ["12"], count=1)[0]
    assert heavy.added is None and "can reach [0.3" in heavy.reason


def test_example_csv_reads_and_ranks(capsys):
    rackets = read_rackets(EXAMPLE)
    assert len(rackets) == 7 and rackets[0].specs.f1 == pytest.approx(122.1)
    data = run_json(capsys, "closest", EXAMPLE, "--swing-weight", "330", "--balance", "0.32")
    assert len(data["rackets"]) == 3
    assert [r["distance"] for r in data["rackets"]] == sorted(
        r["distance"] for r in data["rackets"]
    )
    ok = [r for r in data["rackets"] if r["reachable"]]
    assert ok and all(r["after"]["swing_weight_kg_cm2"] == pytest.approx(330) for r in ok)


@pytest.mark.parametrize(
    ("text", "says"),
    [
        ("name,length_m,mass_kg,balance_m\nx,0.68,0.3,0.3\n", "column swing_weight_kg_cm2"),
        ("name,length_m,mass_kg,balance_m,swing_weight_kg_cm2,ra\n", "unknown column ra"),
        ("name,length_m,mass_kg,balance_m,swing_weight_kg_cm2\nx,0.68,heavy,0.3,300\n", "row 2"),
        ("name,length_m,mass_kg,balance_m,swing_weight_kg_cm2\nx,0.68,0.3,0.9,300\n", "within"),
        ("name,length_m,mass_kg,balance_m,swing_weight_kg_cm2\n", "lists no racket"),
    ],
)
def test_bad_csv_is_one_line(tmp_path, text, says):
    path = tmp_path / "r.csv"
    path.write_text(text)
    with pytest.raises(InputError, match=says):
        read_rackets(path)


def test_bad_closest_options(capsys):
    code, _, err = run(capsys, "closest", EXAMPLE)
    assert code == 2 and "give at least one of --swing-weight" in err
    code, _, err = run(capsys, "closest", EXAMPLE, "--mass", "0.3", "--places", "tip")
    assert code == 2 and "place = 'tip'" in err
