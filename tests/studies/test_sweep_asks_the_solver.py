"""A sweep asks the solver (issue 21, D4; audit items 3, 8 and 14): the options its cases are
solved with are taken and refused by the same rules as simulate's (``make_solver``'s
``Solver.takes``, then ``Solver.check`` on its first case), so the refusal is simulate's line;
the run options that would do nothing are refused in one line too; and the options used are
used (a tolerance on an oblique sweep changes its COR as simulate's)."""

from __future__ import annotations

import numpy as np
import pytest

import fem_racket as fr
from fem_racket.studies.sweep import sweep_result
from fem_racket.validation import InputError

RUN = {"backend": "serial", "progress": False}


@pytest.mark.parametrize(
    "options",
    [
        {"solver": "exact", "rtol": 1e-3},
        {"solver": "cvode", "tolerance": 0.1},
        {"solver": "bdf", "tolerance": 0.1},
        {"law": "hunt-crossley", "separation": "force"},
        {"law": "hunt-crossley", "solver": "cvode", "modes": 10},
        {"solver": "bdf", "basis": "physical", "modes": 10},
        {"solver": "exact", "basis": "physical"},
    ],
    ids=lambda o: " ".join(f"{k}={v}" for k, v in o.items()),
)
def test_a_sweep_refuses_with_simulates_line(options):
    with pytest.raises(InputError) as alone:
        fr.simulate(position=0.6, **options)
    with pytest.raises(InputError) as swept:
        sweep_result(position=[0.6, 0.7], **options, **RUN)
    assert str(swept.value) == str(alone.value)


def test_defaults_ask_for_nothing_and_the_options_given_are_used():
    """Options left out ask for nothing; the numbers stay main's. The exact solver's own
    options given at their defaults change nothing; those it does not take are refused at any
    value (before, rtol, atol and basis at their defaults passed as "neutral": issue 21.3)."""
    plain = sweep_result(position=[0.6, 0.7], **RUN).values
    named = sweep_result(position=[0.6, 0.7], modes=80, tolerance=1e-6, **RUN)
    np.testing.assert_array_equal(named.values, plain)
    for name, value in (("rtol", 1e-10), ("atol", 1e-12), ("basis", "modal")):
        with pytest.raises(InputError, match=f"^{name} = .* is not allowed with solver 'exact'"):
            sweep_result(position=[0.6, 0.7], **{name: value}, **RUN)
    # main's sweep before this change printed these (batched engine, tolerance 1e-6)
    cor = [0.4002005330304712, 0.4081116956738373]
    np.testing.assert_array_equal(sweep_result(position=[0.6, 0.7], **RUN).to_xarray().cor, cor)


def test_an_oblique_sweep_uses_its_tolerance():
    oblique = {"angle": 30.0, "position": 0.7, **RUN}
    loose = sweep_result(tolerance=0.1, **oblique).to_xarray().cor.item()
    every = sweep_result(**oblique).to_xarray().cor.item()
    from fem_racket.impact.incidence import Incidence

    alone = fr.simulate(position=0.7, incidence=Incidence(angle=30.0), tolerance=0.1)
    assert loose != every
    assert loose == pytest.approx(alone.summary()["cor"], abs=1e-12)


@pytest.mark.parametrize(
    ("run", "says"),
    [
        ({"overwrite": True}, "overwrite = True is not allowed without output"),
        ({"restart": True}, "restart = True is not allowed without output"),
        ({"output": "s.txt"}, "output = 's.txt' is not allowed: must end in .nc"),
        ({"backend": "serial", "workers": 3}, "workers = 3 is not allowed with backend 'serial'"),
        (
            {"backend": "serial", "scheduler": "tcp://127.0.0.1:8786"},
            "scheduler = 'tcp://127.0.0.1:8786' is not allowed with backend 'serial'",
        ),
        (
            {"backend": "processes", "scheduler": "tcp://127.0.0.1:8786"},
            "scheduler = 'tcp://127.0.0.1:8786' is not allowed with backend 'processes'",
        ),
        (
            {"workers": 2, "scheduler": "tcp://127.0.0.1:8786"},
            "workers = 2 is not allowed with backend 'dask'",
        ),
    ],
)
def test_run_options_that_would_do_nothing_are_refused(tmp_path, monkeypatch, run, says):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(InputError, match=says.replace("(", r"\(").replace(".", r"\.")):
        sweep_result(position=[0.6, 0.7], progress=False, **run)
    assert not any(tmp_path.iterdir())


def test_workers_alone_ask_for_a_local_pool():
    r = sweep_result(position=[0.6, 0.7], workers=2, progress=False)
    assert r.backend == "processes"


def test_a_range_of_one_value_between_two_ends_is_refused():
    with pytest.raises(InputError, match="position = '0.5:0.9:1' is not allowed: num 1 needs"):
        sweep_result(position="0.5:0.9:1", **RUN)
    assert sweep_result(position="0.5:0.5:1", **RUN).values.shape[0] == 1
