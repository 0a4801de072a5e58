"""customise: least lead meeting targets; planted solutions recovered; unreachable refused."""

import numpy as np
import pytest

from fem_racket import frame_mesh, standard_frame
from fem_racket.frame.catalogue import catalogue
from fem_racket.frame.head import DEFAULT_HEAD
from fem_racket.frame.lead import Lead, add_lead
from fem_racket.frame.mesh import FrameMesh
from fem_racket.io.mesh_files import read_mesh, write_mesh
from fem_racket.studies.customise import Target, customise
from fem_racket.validation import InputError


@pytest.fixture(scope="module")
def mesh():
    return frame_mesh(standard_frame(), 20)


def exact(value):
    return Target(value, value)


@pytest.mark.parametrize(
    "planted",
    [
        {"12": 0.006, "handle": 0.004},
        {"3/9": 0.010, "butt": 0.008},
        {"2/10": 0.003, "throat": 0.012},
    ],
)
def test_recovers_a_planted_solution(mesh, planted):
    head = DEFAULT_HEAD.on_frame(mesh.length)
    target = catalogue(add_lead(mesh, [Lead(p, m) for p, m in planted.items()], head), f1=False)
    # two places, two value targets: the planted masses are the only solution
    out = customise(
        mesh,
        {"swing_weight": exact(target.swing_weight), "balance": exact(target.balance)},
        list(planted),
    )
    assert out.added == pytest.approx(planted, rel=1e-8)
    assert out.after.swing_weight == pytest.approx(target.swing_weight, rel=1e-12)
    assert out.after.balance == pytest.approx(target.balance, rel=1e-12)


def test_recovers_planted_lead_from_swing_weight_and_twistweight(mesh):
    planted = {"12": 0.004, "3/9": 0.008}
    head = DEFAULT_HEAD.on_frame(mesh.length)
    target = catalogue(add_lead(mesh, [Lead(p, m) for p, m in planted.items()], head), f1=False)
    out = customise(
        mesh,
        {"swing_weight": exact(target.swing_weight), "twist_weight": exact(target.twist_weight)},
        ["12", "3/9"],
    )
    assert out.added == pytest.approx(planted, rel=1e-8)
    assert out.after.twist_weight == pytest.approx(target.twist_weight, rel=1e-12)


def test_least_mass_goes_where_it_counts(mesh):
    # a swing-weight floor alone: the cheapest lead is at 12 (largest (x - 0.1)^2 per gram)
    before = catalogue(mesh, f1=False)
    out = customise(mesh, {"swing_weight": Target(before.swing_weight + 1e-3, 1.0)}, ["3/9", "12"])
    assert out.added["3/9"] == 0.0 and out.added["12"] > 0.0
    assert out.after.swing_weight == pytest.approx(before.swing_weight + 1e-3, rel=1e-12)


def test_written_mesh_reproduces_every_reported_spec(mesh, tmp_path):
    before = catalogue(mesh, f1=False)
    out = customise(
        mesh,
        {
            "swing_weight": exact(before.swing_weight + 8e-4),
            "balance": exact(before.balance),
            "mass": Target(0.3, 0.4),
        },
        ["12", "3/9", "handle"],
    )
    path = write_mesh(out.mesh, tmp_path / "custom.vtu")
    again = catalogue(read_mesh(path))
    for key, value in out.after.as_dict().items():
        if value is None:
            assert again.as_dict()[key] is None
        else:
            assert again.as_dict()[key] == pytest.approx(value, rel=1e-9)


def test_unreachable_targets_name_the_reachable_range(mesh):
    before = catalogue(mesh, f1=False)
    with pytest.raises(InputError, match=r"swing-weight = 290\.\.290 kg cm\^2 is not reachable"):
        customise(mesh, {"swing_weight": exact(0.029)}, ["12"])
    with pytest.raises(InputError, match=r"balance = .* can reach \[0\.30790"):
        customise(mesh, {"balance": exact(0.2)}, ["12", "3/9"])
    # each reachable alone but not together: balance kept, swing weight up with lead at 12 only
    with pytest.raises(InputError, match="with the other targets"):
        customise(
            mesh,
            {"swing_weight": exact(before.swing_weight + 1e-3), "balance": exact(before.balance)},
            ["12"],
        )


def test_bad_targets(mesh):
    with pytest.raises(InputError, match="target"):
        customise(mesh, {"stiffness": exact(1.0)}, ["12"])
    with pytest.raises(InputError, match="places"):
        customise(mesh, {"mass": exact(0.37)}, [])
    bare = FrameMesh(mesh.points, mesh.EI, mesh.rhoA)  # no torsion data: no twistweight
    with pytest.raises(InputError, match="twist-weight"):
        customise(bare, {"twist_weight": exact(0.002)}, ["3/9"])
    with pytest.raises(InputError, match="target"):
        Target(0.3, 0.2)
    assert np.isfinite(catalogue(mesh).f1)
