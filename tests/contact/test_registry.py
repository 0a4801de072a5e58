"""A new contact law is one class plus one registry call (issue 21, deliverable 5).

The toy law below (a plain linear spring without damping) is declared here, in the test module,
and registered with one call; nothing else in the package is touched. It then works through
``simulate(law=...)``, a sweep axis, a run file's ``[contact]`` table, the command line's
options and the calibration. Its answers are checked against an independent path: the paper's
linear law with zeta = 0 is the same spring, solved by the exact eigen-solution.
"""

import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np
import pytest
from clirun import run, run_json

from fem_racket import simulate
from fem_racket.contact.law import ContactLaw
from fem_racket.contact.parameters import LawFit, LawParameter
from fem_racket.contact.presets import FILE_KEYS, LAW_NAMES, get_law
from fem_racket.contact.registry import FAMILIES, register, unregister
from fem_racket.io.config import parse_config
from fem_racket.studies.calibrate import FAMILIES as FITTED
from fem_racket.studies.calibrate import calibrate, clamped_impacts
from fem_racket.studies.sweep import sweep_result
from fem_racket.validation import InputError


@dataclass(frozen=True, eq=False)
class ToySpring(ContactLaw):
    """F = k delta: a linear spring without damping."""

    name: ClassVar[str] = "toy-spring"
    declared: ClassVar[tuple[LawParameter, ...]] = (
        LawParameter(
            name="toy_stiffness",
            field="stiffness",
            unit="N/m",
            default=5e4,
            low=1e3,
            high=1e7,
            help="toy spring stiffness k",
            why="a tennis ball on strings: 2.7e4-8.3e4 N/m (the paper)",
        ),
    )
    fit = LawFit(
        names=("k [N/m]",),
        build=lambda p: ToySpring(p[0]),
        low=(1e3,),
        high=(1e7,),
        starts={"kawazoe-1997": (4e4,), "itf": (2e4,)},
    )
    stiffness: Any

    def force(self, d: Any, v: Any, z: Any) -> Any:
        return self.stiffness * d

    def partials(self, d: Any, v: Any, z: Any) -> tuple[Any, Any, Any]:
        zero = 0.0 * np.asarray(d)
        return self.stiffness + zero, zero, zero

    def contact_time_estimate(self, mass: Any, speed: Any) -> Any:
        return math.pi * np.sqrt(np.asarray(mass) / self.stiffness) + 0.0 * np.asarray(speed)


@pytest.fixture
def toy():
    register(ToySpring)  # the one registry call a new law needs
    yield ToySpring
    unregister(ToySpring.name)
    assert ToySpring.name not in LAW_NAMES


def _exact(k, position=0.75, speed=20.0):
    """The same spring as the paper's law with zeta = 0, by the exact eigen-solution."""
    return simulate(position=position, speed=speed, kcb=k, zeta=0.0, output_step=None)


def test_registered_law_appears_in_every_derived_table(toy):
    assert FAMILIES["toy-spring"] is ToySpring and "toy-spring" in LAW_NAMES
    assert FILE_KEYS["toy_stiffness"] == "toy_stiffness_n_m"
    assert "toy-spring" in FITTED
    assert get_law("toy-spring").stiffness == 5e4
    with pytest.raises(InputError, match=r"toy_stiffness = 10.0 N/m .*\[1000, 1e\+07\]"):
        get_law("toy-spring", toy_stiffness=10.0)


def test_simulate_takes_the_registered_law(toy):
    # The general integrator on the toy spring equals the exact solution of the paper's law
    # with zeta = 0 to its COR tolerance (1e-6, the README's promise for the general path).
    r = simulate(speed=20.0, law="toy-spring", output_step=None)
    assert r.cor == pytest.approx(_exact(5e4).cor, abs=2e-6)
    assert r.contact_time == pytest.approx(_exact(5e4).contact_time, rel=1e-5)


def test_sweep_takes_the_registered_law_as_an_axis(toy):
    res = sweep_result(law="toy-spring", toy_stiffness="3e4,6e4", speed=20.0, backend="serial")
    ds = res.to_xarray()
    assert list(ds.toy_stiffness.values) == [3e4, 6e4]
    for k in (3e4, 6e4):
        cor = float(ds.cor.sel(toy_stiffness=k))
        assert cor == pytest.approx(_exact(k).cor, abs=2e-6)
    with pytest.raises(InputError, match="toy_stiffness = 100000000.0 N/m"):
        sweep_result(law="toy-spring", toy_stiffness="1e8,2e8")


def test_run_file_contact_table_takes_the_registered_law(toy, tmp_path):
    text = '[contact]\nlaw = "toy-spring"\ntoy_stiffness_n_m = 4e4\n'
    kwargs = parse_config(text).simulate_kwargs()
    assert kwargs["law"].stiffness == 4e4
    r = simulate(speed=20.0, output_step=None, **kwargs)
    assert r.cor == pytest.approx(_exact(4e4).cor, abs=2e-6)
    with pytest.raises(InputError, match="contact.toy_stiffness_n_m = 1"):
        parse_config('[contact]\nlaw = "toy-spring"\ntoy_stiffness_n_m = 1.0\n')


def test_command_line_options_take_the_registered_law(toy, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, "simulate", "--law", "toy-spring", "--toy-stiffness", "4e4")
    assert code == 0, err
    data = run_json(capsys, "simulate", "--law", "toy-spring", "--toy-stiffness", "4e4")
    assert data["law"] == "toy-spring" and data["toy_stiffness_n_m"] == 4e4
    ref = simulate(law=get_law("toy-spring", toy_stiffness=4e4), output_step=None)
    assert data["cor"] == ref.cor
    code, out, err = run(capsys, "sweep", "--law", "toy-spring", "--toy-stiffness", "3e4,5e4")
    assert code == 0, err
    code, _, err = run(capsys, "simulate", "--law", "toy-spring", "--toy-stiffness", "1")
    assert code == 2 and err.count("\n") == 1 and "toy_stiffness = 1" in err


def test_calibration_fits_the_registered_law(toy):
    # One stiffness cannot give the paper's falling contact time and a COR of 0.83 (the toy
    # spring returns every joule): the fit's COR is 1 on a rigid support, its contact times
    # pi sqrt(m/k) (the closed form, eq 11).
    cal = calibrate("toy-spring", "kawazoe-1997")
    k = cal.law.stiffness
    cor, tc = clamped_impacts(cal.law, [20.0, 40.0])
    assert cor == pytest.approx(1.0, abs=1e-6)
    assert tc == pytest.approx(math.pi * math.sqrt(0.057 / k), rel=1e-6)
    assert not cal.meets_targets
