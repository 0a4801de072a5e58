"""Off the long axis ``--modes`` counts bending and torsion modes each (audit F1): the note
said "using all 20" where JSON ``modes`` (the flexible modes kept, both families) said 40."""

import json

from tests.clirun import run


def test_off_axis_modes_note_counts_both_families_as_json_does(capsys):
    argv = ["simulate", "--elements", "10", "--offset", "0.05", "--modes", "50", "--json"]
    code, out, err = run(capsys, *argv)
    assert code == 0
    assert err.strip() == (
        "fem-racket simulate: note: modes = 50: the 10-element mesh has 20 flexible modes of "
        "bending and 20 of torsion (--modes counts each family); using all, 40 flexible modes "
        "in all"
    )
    assert json.loads(out)["modes"] == 40
    # below the mesh's count: N of each family, 2 N in all
    code, out, err = run(capsys, *argv[:-2], "5", "--json")
    assert (code, err, json.loads(out)["modes"]) == (0, "", 10)


def test_help_states_the_count_per_family(capsys):
    code, out, _ = run(capsys, "simulate", "--help")
    assert code == 0
    assert "off the long axis N of bending and N of torsion" in " ".join(out.split())
