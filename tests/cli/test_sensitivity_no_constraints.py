"""``sensitivity`` offers no constraint options: its sample spans the variables' whole box and
constrains nothing, so ``--mass-range`` & co. (listed in its help, shared with optimize) were
always refused as "constraints ['mass_kg'] ...", not naming the option. Its ``--help`` differs
from before by those four options (and the group's title) only; optimize keeps them."""

from __future__ import annotations

import pytest
from clirun import one_error, run

from fem_racket import load_config
from fem_racket.io.constants import CONSTRAINTS
from fem_racket.validation import InputError

OPTIONS = ["--" + dest.replace("_", "-") for dest in CONSTRAINTS]


def test_sensitivity_help_has_no_constraints_and_optimize_keeps_them(capsys):
    _, sens, _ = run(capsys, "sensitivity", "--help")
    _, opt, _ = run(capsys, "optimize", "--help")
    for option in OPTIONS:
        assert option not in sens and option in opt
    assert "\nobjectives:\n" in sens and "\nobjectives and constraints:\n" in opt
    for option in ("--objective", "--power-fraction", "--grip", "--shock-window"):
        assert option in sens


@pytest.mark.parametrize("option", OPTIONS)
def test_a_constraint_option_of_sensitivity_is_named(capsys, option):
    line = one_error(capsys, "sensitivity", option, "start")
    assert f"unrecognized option {option}" in line


def test_a_constraint_key_of_sensitivity_is_named(tmp_path, capsys):
    pytest.importorskip("SALib")  # the method requires it before reading the table
    path = tmp_path / "run.toml"
    path.write_text("[sensitivity]\nmass_range = [0.3, 0.4]\n")
    assert "sensitivity.mass_range is not a known key" in one_error(
        capsys, "sensitivity", "--config", path
    )
    with pytest.raises(InputError, match=r"^sensitivity\.mass_range is not a known key"):
        load_config(path).sensitivity()
