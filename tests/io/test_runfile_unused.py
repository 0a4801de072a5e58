"""Run-file keys a command would ignore (issue 21.3): a command computing impacts refuses, in
one line (exit 2), a key of the impact's tables it has no option for, as its Python method
does; a key at its neutral value, a command's own axis, and other commands skip them."""

import pytest

from fem_racket import load_config
from fem_racket.cli import main
from fem_racket.validation import InputError

SWING = "[impact]\nracket_speed_m_s = 12.0\n"


@pytest.mark.parametrize("command", ["export-vtk", "animate"])
def test_drawings_refuse_a_swing(capsys, tmp_path, command):
    path = tmp_path / "run.toml"
    path.write_text(SWING)
    assert main([command, "--config", str(path), "--out", str(tmp_path / "x")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "impact.racket_speed_m_s = 12.0 is not allowed" in err
    assert f"fem-racket {command}" in err and "would be ignored" in err
    method = load_config(path).export_vtk if command == "export-vtk" else load_config(path).animate
    with pytest.raises(InputError, match="racket_speed_m_s"):
        method(tmp_path / "y")
    for key in ("reference_x_over_l = 0.7", "pivot_m = 0.1"):  # the swing's point, with a swing
        path.write_text(SWING + key + "\n")
        assert main([command, "--config", str(path)]) == 2
        assert "racket_speed_m_s" in capsys.readouterr().err


CASES = {
    # command: (file text, the key named)
    "sweep": ('[[frame.lead]]\nplace = "12"\nmass_g = 3\n', "frame.lead"),
    "map": ("[frame]\nei1_n_m2 = 500.0\n", "frame.ei1_n_m2"),
    "refine": ('[contact]\nlaw = "hysteretic"\n', "contact.law"),
    "optimize": ('[hand]\ngrip = "firm"\n', "hand.grip"),
    "sensitivity": ("[oblique]\nangle_deg = 20.0\n", "oblique.angle_deg"),
}


@pytest.mark.parametrize("command", list(CASES))
def test_studies_refuse_keys_they_would_ignore(capsys, tmp_path, command):
    text, key = CASES[command]
    path = tmp_path / "run.toml"
    path.write_text(text)
    assert main([command, "--config", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{key} = " in err and "would be ignored" in err, err
    if command in ("sweep", "map", "refine"):  # their Python methods refuse it too
        with pytest.raises(InputError, match=key.replace(".", r"\.")):
            getattr(load_config(path), command)()


def test_neutral_values_axes_and_other_commands_pass(capsys, tmp_path):
    # a swing of 0 m/s, its default reference point, offset 0 and the standard preset change
    # nothing; map spans the positions itself; modes (no impact) skips the impact's keys of a
    # shared file; the example file checks for every command (a pivot without a swing is
    # refused: test_a_swing_point_without_a_swing_is_refused)
    path = tmp_path / "run.toml"
    path.write_text(
        "[impact]\nracket_speed_m_s = 0.0\nreference_x_over_l = 0.75\noffset_m = 0.0\n"
        'position_x_over_l = 0.7\n[frame]\npreset = "standard"\n'
    )
    assert main(["config", "--check", str(path)]) == 0, capsys.readouterr().err
    assert "not for this command" not in capsys.readouterr().out  # every command runs it
    path.write_text('[hand]\ngrip = "firm"\n[oblique]\nangle_deg = 10.0\n')
    assert main(["modes", "--config", str(path), "--count", "2"]) == 0
    assert "frequenc" in capsys.readouterr().out.lower()
    assert main(["config", "--check", str(path)]) == 0  # a note for the studies, not an error
    assert "[sweep] not for this command: " in capsys.readouterr().out


@pytest.mark.parametrize("key", ["pivot_m = 0.1", "reference_x_over_l = 0.6"])
@pytest.mark.parametrize("command", ["simulate", "sweep", "export-vtk"])
def test_a_swing_point_without_a_swing_is_refused(capsys, tmp_path, command, key):
    # the swing's point or pivot without a swing would be dropped (before: passed on purpose);
    # the commands with the option refuse it as on their command line, the others as a key
    # they have no option for
    path = tmp_path / "run.toml"
    path.write_text(f"[impact]\n{key}\n")
    out = {"simulate": "x.json", "sweep": "x.nc", "export-vtk": "x"}[command]
    assert main([command, "--config", str(path), "--out", str(tmp_path / out)]) == 2
    err = capsys.readouterr().err
    name = key.split("_")[0]
    assert err.count("\n") == 1 and f"{name}" in err and "is not allowed" in err, err
    if command == "export-vtk":
        assert "would be ignored" in err
    else:
        assert "without a swing" in err
