"""Run-file keys that had no table entry (issue 21.3/21.7): ``[strings] stretch`` =
``--string-stretch``; ``[oblique] side_angle_deg``/``side_spin_rpm`` = ``--side-angle``/
``--side-spin``, in Python (``load_config(f).simulate()``) as on the command line."""

import json

import pytest

from fem_racket import load_config
from fem_racket.cli import main
from fem_racket.validation import InputError


def _json(capsys, *argv):
    code = main([str(a) for a in argv] + ["--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    return json.loads(out)


def test_strings_stretch_key_is_the_option(capsys, tmp_path):
    # stretch = true gives the printed outcome of --string-stretch, bit for bit (both cvode,
    # which the library's "auto" picks for a stretching bed); stretch = false is the linear bed.
    path = tmp_path / "run.toml"
    path.write_text("[strings]\nstretch = true\n[impact]\nspeed_m_s = 40.0\n")
    file = _json(capsys, "simulate", "--config", path, "--elements", 8)
    cli = _json(capsys, "simulate", "--string-stretch", "--speed", 40, "--elements", 8)
    assert file == cli
    assert file["string_stretch"] is True and file["solver"] == "cvode"
    path.write_text("[strings]\nstretch = false\n[impact]\nspeed_m_s = 40.0\n")
    linear = _json(capsys, "simulate", "--config", path, "--elements", 8)
    plain = _json(capsys, "simulate", "--string-tension", 246, "--speed", 40, "--elements", 8)
    assert linear == plain and linear["string_stretch"] is False
    assert linear["solver"] == "exact" and linear["contact_time_s"] > file["contact_time_s"]
    path.write_text('[strings]\nstretch = "yes"\n')
    code = main(["simulate", "--config", str(path)])
    assert code == 2 and "strings.stretch = 'yes'" in capsys.readouterr().err


def test_auto_picks_cvode_for_a_stretching_bed():
    from fem_racket import FrameModel, standard_frame
    from fem_racket.impact.problem import ImpactProblem
    from fem_racket.impact.solvers import make_solver
    from fem_racket.strings.bed import StringBed

    model = FrameModel.build(standard_frame(), 8)
    stretch = ImpactProblem.build(model, strings=StringBed(stretch=True), speed=30.0)
    assert make_solver("auto").pick(stretch).name == "cvode"
    assert make_solver("auto").pick(ImpactProblem.build(model, strings=StringBed())).name == (
        "exact"
    )
    a, c = make_solver("auto").solve(stretch), make_solver("cvode").solve(stretch)
    assert (a.cor, a.contact_time) == (c.cor, c.contact_time)
    with pytest.raises(InputError, match="modes = 10 is not allowed .* solver 'cvode'"):
        make_solver("auto", modes=10).solve(stretch)  # cvode's own refusal, named
