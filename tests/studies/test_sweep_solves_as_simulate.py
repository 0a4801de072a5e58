"""A sweep takes, refuses and picks solvers as simulate does, and its case is simulate's impact
(audit A4, A6; issue 21, D2 "one registry of solvers, auto picks" and D4 "studies ask the
solver").

For every contact law (the paper's, the linear ``kawazoe-1997-ball`` preset, a nonlinear one)
on every structure (a free racket at rest, a string bed, an oblique ball, a swing) and every
solver name, a one-case sweep on a coarse mesh refuses with simulate's line where simulate
refuses, and otherwise runs the solver simulate runs (``auto`` included: the registry's pick)
to simulate's numbers. Before, the sweep kept its own solver lists: ``general`` was refused
under the paper's law, ``exact`` on a strung racket under the ball's law, ``cvode`` on an
oblique ball under a nonlinear law, and ``auto`` ran ``general`` where simulate's ran
``exact``.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import fem_racket as fr
from fem_racket.frame.segments import standard_frame
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.swing import Swing
from fem_racket.strings.bed import StringBed
from fem_racket.studies.sweep import sweep_result
from fem_racket.validation import InputError

#: One impact, on a coarse mesh (fast): simulate's keywords and the sweep's.
CASE = {"position": 0.7, "speed": 20.0, "elements": 6}
LAWS = {
    "paper": {},
    "linear preset": {"law": "kawazoe-1997-ball"},
    "nonlinear": {"law": "hunt-crossley"},
}
#: Each structure as simulate states it and as the sweep's axes state it.
STRUCTURES = {
    "free": ({}, {}),
    "strung": ({"strings": StringBed(tension_n=250.0)}, {"string_tension": 250.0}),
    "oblique": (
        {"incidence": Incidence(angle=30.0, spin=100.0)},
        {"angle": 30.0, "spin": 100.0},
    ),
    "swing": ({"swing": Swing.from_speed(10.0, standard_frame().length)}, {"racket_speed": 10.0}),
}
SOLVERS = ("auto", "exact", "general", "cvode", "bdf")
#: The variables compared, where both give them.
COMPARED = ("cor", "contact_time_s", "rebound_speed_m_s", "peak_force_n", "spin_out_rpm")


def _simulate_options(solver: str, law: dict, structure: str) -> dict:
    """simulate's output times as the sweep's solver has them (:func:`fem_racket.studies.cases.
    sweep_solver`): the ODE solvers' 1 us histories under the paper's law or for an oblique
    ball, none under another law; a batch (free racket, swing) has none; a string bed and an
    oblique ball are solved case by case at the solver's default output times."""
    if structure == "strung":
        return {}
    if solver in ("cvode", "bdf"):
        return {"output_step": 1e-6 if not law or structure == "oblique" else None}
    if structure == "oblique" or (solver == "general" and not law):
        return {}  # each case as its own problem (general under the paper's law: no batch)
    return {"output_step": None}


@pytest.mark.parametrize(
    ("law", "structure", "solver"),
    list(itertools.product(LAWS, STRUCTURES, SOLVERS)),
    ids=lambda v: v.replace(" ", "-"),
)
def test_a_sweep_solves_as_simulate(law, structure, solver):
    alone, swept = STRUCTURES[structure]
    try:
        ds = sweep_result(
            **CASE, **LAWS[law], **swept, solver=solver, peak_force=True, backend="serial"
        )
    except InputError as err:
        refused = str(err)
    else:
        refused = None
    if refused is not None:  # simulate refuses it in the same line
        with pytest.raises(InputError) as err:
            fr.simulate(**CASE, **LAWS[law], **alone, solver=solver)
        assert refused == str(err.value)
        return
    # the picked solver
    ran = ds.attrs["solver"]
    if solver != "auto":
        assert ran == solver
    options = _simulate_options(ran, LAWS[law], structure)
    r = fr.simulate(**CASE, **LAWS[law], **alone, solver=solver, **options)
    summary = r.summary()
    assert summary["solver"] == ran
    # the numbers: bit for bit where the same path runs; the batched engine at the closing
    # speed against simulate's single impact differs by rounding only (measured <= 1e-14
    # relative; 1e-12 allowed)
    x = ds.to_xarray()
    compared = [v for v in COMPARED if v in x and v in summary]
    assert {"cor", "contact_time_s"} <= set(compared)
    for name in compared:
        np.testing.assert_allclose(
            x[name].values.ravel()[0], summary[name], rtol=1e-12, err_msg=name
        )


def test_the_audit_lines_now_run():
    """The findings' sweeps: general under the paper's law (also on a string bed), which
    simulate ran; bdf on a string bed refused in the solver's own line, not a list that
    contradicted another."""
    plain = sweep_result(**CASE, solver="general", backend="serial")
    assert plain.attrs["solver"] == "general"
    strung = sweep_result(**CASE, string_tension=250.0, solver="general", backend="serial")
    assert np.isfinite(strung.to_xarray().cor.values).all()
    with pytest.raises(InputError) as err:
        sweep_result(**CASE, string_tension=250.0, solver="bdf", backend="serial")
    assert str(err.value) == (
        "solver = 'bdf' is not allowed with a string bed: must be one of exact, general, cvode"
    )


def test_auto_on_a_string_bed_under_the_balls_law_is_exact():
    """A6: a strung sweep with the kawazoe-1997-ball given picks ``exact`` as simulate's auto
    does (it ran the general integrator, 13x slower) and gives the numbers of the same sweep
    without the law (the bed's default ball law is that preset)."""
    grid = {**CASE, "string_tension": 250.0, "speed": [20.0, 30.0], "backend": "serial"}
    named = sweep_result(**grid, law="kawazoe-1997-ball")
    assert named.attrs["solver"] == "exact"
    np.testing.assert_array_equal(named.values, sweep_result(**grid).values)
