"""Design variables beyond one value per segment: smooth EI(x), rhoA(x) by control points, added
masses at free positions, the string bed's stiffness."""

import numpy as np
import pytest

import fem_racket
from fem_racket.contact.linear import kcb_from_speed
from fem_racket.contact.presets import get_law
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.masses import MIN_GAP, AddedMass, add_masses
from fem_racket.frame.mesh import frame_mesh
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import standard_frame
from fem_racket.impact.exact.engine import impacts
from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.objectives import evaluate_rows, output_names
from fem_racket.studies.design.options import VariableOptions
from fem_racket.studies.design.paper_problem import paper_problem
from fem_racket.studies.design.report import design_maps
from fem_racket.studies.design.solvers import optimize
from fem_racket.studies.design.swing import mass_quantities
from fem_racket.studies.design.variables import Constraint
from fem_racket.validation import InputError

STATIONS = (0.0, 0.25, 0.5, 0.75, 1.0)


def outputs(problem, x):
    return dict(zip(output_names(problem), evaluate_rows(problem, x[None])[0], strict=True))


def test_linear_profile_mass_is_the_trapezoid_rule():
    """rhoA linear between stations: its integral is exactly L x the trapezoid rule of the
    values over the stations (cell means keep it on any mesh)."""
    p = design_problem(rhoa_points=STATIONS, interpolation="linear", vary=("rhoa",))
    x = np.array([0.9, 0.4, 0.7, 0.3, 0.5])
    expected = 0.68 * np.sum(0.5 * (x[1:] + x[:-1]) * np.diff(STATIONS))
    mesh = p.mesh(x)
    assert mass_quantities(mesh)["mass"] == pytest.approx(expected, rel=1e-13)


def test_pchip_profile_passes_through_its_control_values_without_overshoot():
    p = design_problem(ei_points=STATIONS, elements=400, vary=("ei",))
    x = np.array([100.0, 300.0, 250.0, 1200.0, 800.0])
    mesh = p.mesh(x)
    mid = 0.5 * (mesh.points[1:] + mesh.points[:-1]) / mesh.length
    for s, v in zip(STATIONS, x, strict=True):
        nearest = mesh.EI[np.argmin(np.abs(mid - s))]
        assert nearest == pytest.approx(v, rel=0.02)  # cell means of 1.7 mm cells
    assert mesh.EI.min() >= x.min() and mesh.EI.max() <= x.max()  # monotone: no overshoot


def test_control_point_objective_converges_with_the_mesh():
    """Piecewise-constant cells of a smooth profile: the mean e_A changes by O(h^2) as the
    cells shrink (measured 2.3e-5, 7.6e-6, 1.8e-6 from 20 to 160 cells)."""
    values = []
    for cells in (20, 40, 80, 160):
        p = design_problem(
            ei_points=STATIONS, rhoa_points=(0.0, 0.5, 1.0), elements=cells, speeds=(30.0,)
        )
        values.append(outputs(p, p.x_start)["cor"])
    d = np.abs(np.diff(values))
    assert d[1] < d[0] / 2.5 and d[2] < d[1] / 2.5
    assert d[2] < 3e-6


def profile_misfit(target):
    """Synthetic outputs from each design's real mesh: cor = -mean over cells of
    (log EI - log EI*)^2 - (rhoA - rhoA*)^2 / (0.1 kg/m)^2; quantities as evaluated."""

    def function(problem, designs):
        ref = problem.mesh(target)
        names = output_names(problem)
        out = np.zeros((len(designs), len(names)))
        for i, x in enumerate(designs):
            mesh = problem.mesh(x)
            e = np.mean(np.log(mesh.EI / ref.EI) ** 2 + ((mesh.rhoA - ref.rhoA) / 0.1) ** 2)
            out[i, names.index("cor")] = -e
            out[i, names.index("mass_kg")] = mass_quantities(mesh)["mass"]
        return out

    return function


def test_planted_control_point_profile_recovered_to_1_percent():
    """A planted EI(x), rhoA(x) (5 + 3 control values) is the unique best fit of itself; with
    the total mass fixed at the planted racket's, SLSQP recovers every control value to 1 %
    and the mass constraint holds."""
    target = np.array([180.0, 400.0, 900.0, 600.0, 300.0, 0.8, 0.5, 0.55])
    base = design_problem(ei_points=STATIONS, rhoa_points=(0.0, 0.5, 1.0))
    mass = mass_quantities(base.mesh(target))["mass"]
    p = paper_problem(
        None,
        VariableOptions(ei_points=STATIONS, rhoa_points=(0.0, 0.5, 1.0)),
        constraints=(Constraint("mass_kg", mass, mass),),
    )
    r = optimize(
        p, evaluator=Evaluator(p, function=profile_misfit(target)), maxiter=200, progress=False
    )
    assert np.allclose(r.x, target, rtol=0.01)
    assert all(c["holds"] for c in r.constraints())


def balance_target(b_star):
    """cor = -((balance - b*) / 1 cm)^2 from each design's real mesh."""

    def function(problem, designs):
        names = output_names(problem)
        out = np.zeros((len(designs), len(names)))
        for i, x in enumerate(designs):
            cg = mass_quantities(problem.mesh(x))["cg"]
            out[i, names.index("balance_m")] = cg
            out[i, names.index("cor")] = -(((cg - b_star) / 0.01) ** 2)
        return out

    return function


def test_free_mass_position_planted_optimum_recovered():
    """30 g of tape whose position is the only variable: the balance point moves monotonically
    with it, so a planted balance (that of the tape at 0.85 L) gives back 0.85 L to 1 %."""
    kwargs = {"vary": ("position",), "mass_positions": (0.6,), "mass_start": 0.03}
    p = design_problem(position_bounds=(0.4, 1.0), **kwargs)
    b_star = mass_quantities(p.mesh(np.array([0.85])))["cg"]
    r = optimize(p, evaluator=Evaluator(p, function=balance_target(b_star)), progress=False)
    assert r.x[0] == pytest.approx(0.85, rel=0.01)
    # differential evolution (global) too
    r = optimize(
        p,
        method="differential-evolution",
        evaluator=Evaluator(p, function=balance_target(b_star)),
        progress=False,
    )
    assert r.x[0] == pytest.approx(0.85, rel=0.01)


def test_free_mass_is_exact_and_continuous_in_its_position():
    """The strip adds exactly its mass and first moment m x_c wherever it sits, also with an end
    a hair from a node (snapped within MIN_GAP L) and across nodes."""
    base = frame_mesh(standard_frame(), 20)
    q0 = mass_quantities(base)
    node = base.points[15] / base.length
    for d in (1e-3, 2e-6, 5e-7, 1e-9, 0.0, -1e-9, -5e-7):
        pos = node + 0.01 / base.length + d
        mesh = add_masses(base, [AddedMass(pos, 0.03)])
        q = mass_quantities(mesh)
        assert q["mass"] == pytest.approx(q0["mass"] + 0.03, rel=1e-13)
        moment = q["mass"] * q["cg"] - q0["mass"] * q0["cg"]
        assert moment / 0.03 == pytest.approx(pos * base.length, abs=MIN_GAP * base.length)
        assert np.diff(mesh.points).min() > 0.5 * MIN_GAP * base.length
        FrameModel(assemble_closed_form(mesh)).modes(3)  # a well-posed eigenproblem


def test_kcb_factor_scales_the_papers_kcb():
    """The linear law's string-bed variable multiplies K_CB(v): the design's e_A is the engine's
    at K_CB = factor x K_CB(v)."""
    p = design_problem(
        boundaries=(0.3,), vary=("string",), speeds=(30.0,), zone_range=(0.7, 0.8), zone_points=2
    )
    assert p.names == ["kcb_factor"]
    got = outputs(p, np.array([1.5]))["cor"]
    model = FrameModel(assemble_closed_form(p.mesh(np.array([1.5]))))
    e = impacts(model, position=[0.7, 0.8], speed=30.0, kcb=1.5 * kcb_from_speed(30.0)).cor
    assert got == pytest.approx(np.mean(e), abs=1e-9)
    # The reported map (fem-racket map's) sees the same string bed as the objective.
    (m,) = design_maps(p, np.array([1.5]), positions=np.array([0.6, 0.7, 0.8]))
    np.testing.assert_allclose(m.apparent_cor[1:], e, atol=1e-9)


def test_series_string_stiffness_matches_simulate():
    """With the series law, e_A of a design (k_s, k_3 variables) is simulate()'s COR for that
    law on that racket (the same general integrator; simulate keeps every mode)."""
    law = get_law("series")
    p = design_problem(
        boundaries=(0.3,),
        vary=("string", "string_cubic"),
        law=law,
        speeds=(30.0,),
        zone_range=(0.7, 0.8),
        zone_points=2,
    )
    assert p.names == ["k_s", "k_3"]
    x = np.array([2500.0, 4e8])
    got = outputs(p, x)["cor"]
    ref = fem_racket.get_law("series", string_stiffness=2500.0, string_cubic=4e8)
    cor = [fem_racket.simulate(p.mesh(x), position=s, speed=30.0, law=ref).cor for s in (0.7, 0.8)]
    assert got == pytest.approx(np.mean(cor), abs=2e-5)  # beta = 50 against every mode
    (m,) = design_maps(p, x, positions=np.array([0.6, 0.7, 0.8]))
    assert m.law.describe() == ref.describe()
    np.testing.assert_allclose(m.apparent_cor[1:], cor, atol=2e-5)


@pytest.mark.parametrize(
    ("kwargs", "needle"),
    [
        ({"ei_points": (0.1, 1.0)}, "ei_points"),
        ({"rhoa_points": (0.0,)}, "rhoa_points"),
        ({"interpolation": "cubic"}, "interpolation"),
        ({"vary": ("position",), "mass_positions": (0.8,), "position_bounds": (-0.1, 1)}, "pos_1"),
        ({"vary": ("string_cubic",)}, "string_cubic"),
        ({"vary": ("string",), "law": get_law("hysteretic")}, "string"),
        (
            {"zone_point": 3},
            "'zone_point' is not known to design_problem; did you mean 'zone_points'",
        ),
    ],
)
def test_bad_new_variables(kwargs, needle):
    with pytest.raises(InputError, match=needle):
        design_problem(**kwargs)


RUN_FILES = {
    "control-points": (
        "[design]\nei_points = [0, 0.3, 0.6, 1]\nrhoa_points = [0, 0.5, 1]\n"
        "interpolation = 'linear'\n",
        ["ei_1", "ei_2", "ei_3", "ei_4", "rhoa_1", "rhoa_2", "rhoa_3"],
        {"ei_stations_x_over_l": [0, 0.3, 0.6, 1], "interpolation": "linear"},
    ),
    "free-mass": (
        "[design]\nvary = ['mass', 'position']\nmass_positions = [0.85]\nmass_start = 0.01\n"
        "position_bounds = [0.6, 1]\n",
        ["mass_1", "pos_1"],
        {"mass_positions_x_over_l": [0.85]},
    ),
    "kcb-factor": (
        "[design]\nvary = ['ei', 'string']\nlink_ei = true\nstring_bounds = [0.5, 2]\n",
        ["ei", "kcb_factor"],
        {},
    ),
    "series-string": (
        "[contact]\nlaw = 'series'\n[design]\nvary = ['string', 'string_cubic']\n"
        "string_bounds = [1000, 4000]\n",
        ["k_s", "k_3"],
        {"law": {"law": "series"}},
    ),
}


@pytest.mark.parametrize("case", sorted(RUN_FILES))
def test_new_variables_round_trip_through_a_run_file(case, tmp_path, capsys):
    """Each new kind of variable from a run file's [design] (and [contact]) table: the problem
    written to result.json describes it, and the optimum loads back with --mesh."""
    import json

    from tests.clirun import run_json

    table, names, described = RUN_FILES[case]
    out = tmp_path / "o"
    run = tmp_path / "run.toml"
    run.write_text(
        table + "boundaries = [0.3]\nspeeds = [30]\nzone_points = 2\nmaxiter = 1\n"
        f"backend = 'serial'\nout = '{out}'\n"
    )
    data = run_json(capsys, "optimize", "--config", run)
    assert list(data["variables"]) == names
    result = json.loads((out / "result.json").read_text())
    problem = result["problem"]
    assert [v["name"] for v in problem["variables"]] == names
    for key, value in described.items():
        if isinstance(value, dict):
            assert value.items() <= problem[key].items()
        else:
            assert problem[key] == value
    modes = run_json(capsys, "modes", "--mesh", out / "optimum.vtu")
    assert modes["mass_kg"] == pytest.approx(result["outputs"]["mass_kg"], rel=1e-12)


def test_modal_impacts_with_one_structure_per_case():
    """Cases on two frames in one call (a row of omega per case) give each frame's own call."""
    fm = [FrameModel.build(standard_frame(), 20), FrameModel.build(None, 24)]
    x = np.array([0.7, 0.85])
    omega, values, rigid = [], [], []
    for model in fm:
        modes = model.modes(None)
        g = model.fe.field_matrix(x * model.mesh.length, 0)
        omega.append(modes.omega[:40])
        values.append((g @ modes.shapes)[:, :40])
        rigid.append(((g @ modes.rigid) ** 2).sum(axis=1))
    both = fem_racket.modal_impacts(
        np.stack(omega)[:, None, :], np.stack(values), np.stack(rigid), speed=30.0
    )
    for k in range(2):
        one = fem_racket.modal_impacts(omega[k], values[k], rigid[k], speed=30.0)
        assert np.array_equal(both.cor[k], one.cor)
