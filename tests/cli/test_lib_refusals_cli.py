"""A folder given for a file is named as a folder (library and command line), and the README's
word on a string bed with an incidence holds (issue 21, deliverable 3)."""

from __future__ import annotations

import pytest

from fem_racket.io.mesh_files import read_mesh
from fem_racket.io.racket_table import read_rackets
from fem_racket.validation import InputError
from tests.clirun import one_error, run


@pytest.mark.parametrize(
    ("read", "words"),
    [
        (read_mesh, "it is a folder, not a mesh file"),
        (read_rackets, "it is a folder, not a racket"),
    ],
)
def test_a_folder_is_not_a_file_in_the_library(tmp_path, read, words):
    with pytest.raises(InputError, match=words) as err:
        read(tmp_path)
    assert "no such file" not in str(err.value) and str(tmp_path) in str(err.value)
    with pytest.raises(InputError, match="no such file"):  # a missing file still says so
        read(tmp_path / "none")


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["simulate", "--mesh", "{dir}"], "mesh = '{dir}' is not allowed: it is a folder, not a"),
        (["compare", "standard", "{dir}"], "mesh = '{dir}' is not allowed: it is a folder"),
        (["closest", "{dir}", "--mass", "0.3"], "rackets = '{dir}' is not allowed: it is a folder"),
    ],
)
def test_a_folder_is_not_a_file_on_the_command_line(capsys, tmp_path, argv, words):
    line = one_error(capsys, *[a.format(dir=tmp_path) for a in argv])
    assert words.format(dir=tmp_path) in line, line


def test_a_string_bed_takes_an_incidence_without_a_hand(capsys):
    # README, "The hand-held racket": a hand with a bed is refused, the bed alone takes one
    code, out, err = run(capsys, "simulate", "--string-tension", "246", "--angle", "30")
    assert code == 0, err
    assert "spin out" in out and "angle in" in out
    line = one_error(
        capsys, "simulate", "--string-tension", "246", "--angle", "30", "--grip", "firm"
    )
    assert "a hand is not allowed with a string bed" in line
