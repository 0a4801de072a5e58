"""An option given at its default value is refused where any other value of it is (issue 21.3):
the commands pass what was given (``args.explicit_options``), not the values that differ from
the defaults, so ``sweep --law hunt-crossley --separation displacement`` is refused as
``simulate`` refuses it (it ran), in one line and in simulate's words."""

import pytest

from tests.clirun import one_error

SWEEP = ("sweep", "--speeds", "20", "--positions", "0.7", "--serial", "--quiet")
DESIGN = ("--out", "design_out")

#: (options on top of sweep and simulate alike, at their defaults; words of the refusal).
AS_SIMULATE = {
    "law-separation": (
        ("--law", "hunt-crossley", "--separation", "displacement"),
        "separation = 'displacement' is not allowed with contact law 'hunt-crossley'",
    ),
    "cvode-law-basis": (
        ("--law", "hunt-crossley", "--solver", "cvode", "--basis", "modal"),
        "basis = 'modal' is not allowed with solver 'cvode' under a contact law",
    ),
    "cvode-law-modes": (
        ("--law", "hunt-crossley", "--solver", "cvode", "--modes", "80"),
        "modes = 80 is not allowed with solver 'cvode' under a contact law",
    ),
    "cvode-physical-modes": (
        ("--solver", "cvode", "--basis", "physical", "--modes", "80"),
        "modes = 80 is not allowed with solver 'cvode' with basis 'physical'",
    ),
    "bed-modes": (
        ("--string-tension", "246", "--modes", "80"),
        "modes = 80 is not allowed with a string bed and solver 'exact'",
    ),
    "bed-tolerance": (
        ("--string-tension", "246", "--tolerance", "1e-6"),
        "tolerance = 1e-06 is not allowed with a string bed and solver 'exact'",
    ),
}

#: Commands refusing an option given at its default (argv, the start of the refusal).
OTHERS = {
    "sweep-reference": (
        (*SWEEP, "--reference", "0.75", "--out", "s.nc"),
        "reference = 0.75 x/L is not allowed without a swing",
    ),
    "refine-grading": (
        ("refine", "--family", "uniform", "--grading", "4", "--no-files"),
        "grading = 4.0 is not allowed with family 'uniform'",
    ),
    "optimize-popsize": (
        ("optimize", "--popsize", "10", *DESIGN),
        "popsize = 10 is not allowed with method 'SLSQP'",
    ),
    "optimize-zone-sigma": (
        ("optimize", "--zone-sigma", "0.05", *DESIGN),
        "zone_sigma = 0.05 is not allowed with zone 'uniform'",
    ),
    "sensitivity-reference": (
        ("sensitivity", "--reference", "0.75", "--out", "s.png"),
        "reference = 0.75 x/L is not allowed without a swing",
    ),
}


def _said(line: str) -> str:
    return line.split(": error: ", 1)[1]


@pytest.mark.parametrize("name", list(AS_SIMULATE))
def test_sweep_refuses_a_default_given_as_simulate_does(capsys, cwd, name):
    extra, words = AS_SIMULATE[name]
    sweep = one_error(capsys, *SWEEP, "--out", "s.nc", *extra)
    simulate = one_error(capsys, "simulate", "--speed", "20", "--position", "0.7", *extra)
    assert _said(sweep).startswith(words), sweep
    assert _said(sweep) == _said(simulate)
    assert not (cwd / "s.nc").exists() and not (cwd / "s.nc.checkpoint").exists()


@pytest.mark.parametrize("name", list(OTHERS))
def test_a_default_given_is_refused_in_one_line(capsys, cwd, name):
    argv, words = OTHERS[name]
    assert _said(one_error(capsys, *argv)).startswith(words)


@pytest.mark.parametrize("name", ["law-separation", "bed-tolerance"])
def test_a_non_default_value_is_refused_alike(capsys, cwd, name):
    # the same refusal at another value (it was refused before too): the option, not its value
    extra, words = AS_SIMULATE[name]
    other = {"displacement": "force", "1e-6": "1e-4"}
    extra = tuple(other.get(a, a) for a in extra)
    line = _said(one_error(capsys, *SWEEP, "--out", "s.nc", *extra))
    assert line.startswith(words.split(" = ")[0] + " = ")


def test_sensitivity_refuses_a_power_fraction_given_at_its_default(capsys, cwd):
    pytest.importorskip("SALib")
    line = one_error(capsys, "sensitivity", "--power-fraction", "0.9", "--out", "s.png")
    assert _said(line).startswith("power_fraction = 0.9 is not allowed with output 'cor'")
    assert not (cwd / "s.png").exists()
