"""A run file's oblique keys are refused stating the range the model checks (one home: the
bounds of :mod:`fem_racket.impact.incidence`), and a clamped head from a run file on a string
bed names the file's keys, not an option the user never gave."""

from __future__ import annotations

from pathlib import Path

import pytest
from clirun import one_error

from fem_racket.impact.incidence import MAX_COMPLIANCE_RATIO, MAX_FRICTION, Incidence
from fem_racket.validation import InputError


@pytest.mark.parametrize(
    ("key", "value", "allowed"),
    [
        ("friction", "-1", "[0, 5]"),
        ("friction", "10", "[0, 5]"),
        ("compliance_ratio", "-1", "[0, 15]"),
        ("compliance_ratio", "16", "[0, 15]"),
    ],
)
def test_run_file_states_the_range_the_model_checks(capsys, cwd, key, value, allowed):
    Path("run.toml").write_text(f"[oblique]\nangle_deg = 30.0\n{key} = {value}\n")
    line = one_error(capsys, "simulate", "--config", "run.toml")
    assert line == (
        f"fem-racket simulate: error: run.toml: oblique.{key} = {value} is not allowed: must lie "
        f"in {allowed}"
    )
    option = "--" + key.replace("_", "-")
    line = one_error(capsys, "simulate", "--angle", "30", option, value)
    assert line.endswith(f"{key} = {float(value)} is not allowed: must lie in {allowed}")


def test_the_bounds_stated_are_the_bounds_checked(capsys, cwd):
    Incidence(friction=MAX_FRICTION, compliance_ratio=MAX_COMPLIANCE_RATIO)
    with pytest.raises(InputError, match=r"must lie in \[0, 5\]$"):
        Incidence(friction=-1e-300)
    Path("run.toml").write_text(f"[oblique]\nangle_deg = 30.0\nfriction = {MAX_FRICTION}\n")
    line = one_error(capsys, "simulate", "--config", "run.toml", "--speed", "1e9")
    assert "friction" not in line  # the file's bound itself passes; the speed is refused


def test_clamped_and_strings_from_a_run_file_name_its_keys(capsys, cwd):
    free = "the strung racket is free and at rest"
    Path("run.toml").write_text("[strings]\ntension_n = 250.0\n[oblique]\nclamped = true\n")
    line = one_error(capsys, "simulate", "--config", "run.toml")
    assert line == (
        "fem-racket simulate: error: oblique.clamped (run.toml) is not allowed with the string "
        f"bed of strings.tension_n (run.toml): {free}"
    )
    Path("run.toml").write_text("[strings]\ntension_n = 250.0\n")
    line = one_error(capsys, "simulate", "--config", "run.toml", "--angle", "20", "--clamped")
    assert line.endswith(f"--clamped is not allowed with the string bed of strings.tension_n "
                         f"(run.toml): {free}")  # fmt: skip
    line = one_error(capsys, "simulate", "--string-tension", "250", "--angle", "20", "--clamped")
    assert line.endswith(f"error: --clamped is not allowed with a string bed: {free}")
