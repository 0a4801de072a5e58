"""A key only the core tables set, written in a command's own table, is refused alike by the
command (``--config``) and by its Python method, naming the core key that sets it
(:func:`fem_racket.io.config_unused.refuse_core_only`); before, ``load_config(f).map()`` took
``[map] speed`` and ``[map] angle`` while ``fem-racket map --config f`` refused them."""

import pytest
from clirun import file_refused_alike

from fem_racket.io.config import load_config
from fem_racket.validation import InputError

CASES = [
    ("map", "speed = 25", "map.speed is not allowed here: set impact.speed_m_s instead"),
    ("map", "angle = 20", "map.angle is not allowed here: set oblique.angle_deg instead"),
    ("map", "elements = 10", "map.elements is not allowed here: set frame.elements instead"),
    ("refine", "speed = 25", "refine.speed is not allowed here: set impact.speed_m_s instead"),
    (
        "refine",
        "hc_exponent = 1.5",
        "refine.hc_exponent is not allowed here: set contact.hc_exponent instead",
    ),
]


@pytest.mark.parametrize(("command", "line", "message"), CASES)
def test_command_and_method_refuse_a_core_key_alike(cwd, capsys, command, line, message):
    argv = (command, "--config", "run.toml")
    file_refused_alike(
        capsys, f"[{command}]\n{line}\n", argv, lambda c: getattr(c, command)(), message
    )


def test_a_command_own_core_key_stays_allowed(tmp_path):
    """refine spans its element counts itself: ``[refine] elements`` is its own (a list)."""
    path = tmp_path / "run.toml"
    path.write_text("[refine]\nelements = 10\n")
    with pytest.raises(InputError, match="must be a list of integers"):
        load_config(path).refine()
