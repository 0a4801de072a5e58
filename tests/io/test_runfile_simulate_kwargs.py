"""``load_config(f).simulate_kwargs()`` gives ``fem_racket.simulate`` the file's impact or
refuses: it silently dropped ``[frame]``, ``[impact] offset_m``, ``[oblique]``, ``[strings]``,
``[hand]``, ``[solver] tolerance`` and ``[simulate] output_step`` (with EI1 = 500,
``fr.simulate(**kw)`` gave COR 0.376570 where ``.simulate()`` and the CLI gave 0.372475)."""

from __future__ import annotations

import pytest
from clirun import run_json

import fem_racket as fr
from fem_racket.io.config_example import example_config
from fem_racket.validation import InputError


def test_the_keywords_carry_offset_and_tolerance(tmp_path, capsys):
    path = tmp_path / "run.toml"
    path.write_text(
        '[impact]\nspeed_m_s = 30.0\noffset_m = 0.03\n[solver]\nname = "exact"\ntolerance = 1e-4\n'
    )
    kw = fr.load_config(path).simulate_kwargs()
    assert kw == {"offset": 0.03, "speed": 30.0, "solver": "exact", "tolerance": 1e-4}
    ours = fr.simulate(**kw, output_step=None)  # .simulate() computes no histories here
    assert ours.cor == fr.load_config(path).simulate().cor
    assert ours.cor == pytest.approx(run_json(capsys, "simulate", "--config", path)["cor"])


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("[frame]\nei1_n_m2 = 500.0\n", "frame.ei1_n_m2 = 500.0"),
        ("[oblique]\nangle_deg = 20.0\n", "oblique.angle_deg = 20.0"),
        ("[strings]\ntension_n = 200.0\n", "strings.tension_n = 200.0"),
        ("[hand]\ngrip = 'firm'\n", "hand.grip = 'firm'"),
        ("[impact]\nracket_speed_m_s = 10.0\n", "impact.racket_speed_m_s = 10.0"),
        ('[frame]\nlead = [{ place = "12", mass_g = 5 }]\n', "frame.lead = "),
        ("[simulate]\noutput_step = 2e-5\n", "simulate.output_step = 2e-05"),
    ],
)
def test_what_the_keywords_cannot_carry_is_refused(tmp_path, text, words):
    path = tmp_path / "run.toml"
    path.write_text("[ball]\nmass_kg = 0.058\n" + text)
    with pytest.raises(InputError) as err:
        fr.load_config(path).simulate_kwargs()
    line = str(err.value)
    assert line.startswith(words) and "\n" not in line, line
    assert f"({path}) is not allowed in simulate_kwargs()" in line
    assert "load_config(path).simulate()" in line


def test_keys_at_their_defaults_change_nothing():
    kw = fr.parse_config(example_config()).simulate_kwargs()
    assert kw["position"] == 0.75 and kw["speed"] == 20.0 and "ei1" not in kw
