"""A run file's ``[strings]`` bed drawn in Python (issue 21.7, issue 25's bed):
``load_config(f).export_vtk()`` writes the strung series ``fem-racket export-vtk --config f``
writes, file for file and byte for byte, and ``.animate()`` the same GIF; what the strung series
does not draw is refused alike, from the file as from the command line."""

from __future__ import annotations

import pytest
from runfile_helpers import BED as STRUNG

from fem_racket import load_config
from fem_racket.cli import main
from fem_racket.validation import InputError

BED = STRUNG + "offset_m = 0.02\n"  # off the axis


def test_export_vtk_draws_the_bed_as_the_command(cwd, capsys):
    pytest.importorskip("pyvista")
    (cwd / "run.toml").write_text(BED + '[vtk]\nframes = 4\nscale = 3.0\nout = "a"\n')
    assert main(["export-vtk", "--config", "run.toml", "--quiet"]) == 0, capsys.readouterr().err
    pvd = load_config(cwd / "run.toml").export_vtk(out=cwd / "b")
    ours = sorted(p.name for p in pvd.parent.iterdir() if p.suffix in (".vtu", ".pvd"))
    theirs = sorted(p.name for p in (cwd / "a").iterdir() if p.suffix in (".vtu", ".pvd"))
    assert ours == theirs
    assert sum(n.startswith("strings_") for n in ours) == 4  # the bed, at the 4 steps asked
    for name in theirs:  # the same impact drawn the same way: every file bit for bit
        assert (cwd / "b" / name).read_bytes() == (cwd / "a" / name).read_bytes(), name


def test_animate_draws_the_bed_as_the_command(cwd, capsys):
    pytest.importorskip("pyvista")
    pytest.importorskip("imageio")
    text = BED + '[animate]\nframes = 2\nsize = "160x160"\nout = "a.gif"\n'
    (cwd / "run.toml").write_text(text)
    assert main(["animate", "--config", "run.toml", "--quiet"]) == 0, capsys.readouterr().err
    path = load_config(cwd / "run.toml").animate(out=cwd / "b.gif")
    assert path.read_bytes() == (cwd / "a.gif").read_bytes()


@pytest.mark.parametrize(
    ("table", "words"),
    [
        ("[vtk]\nsubdivide = 2\n", "vtk.subdivide = 2 (run.toml) is not allowed with a string bed"),
        ('[vtk]\nfield = "slope"\n', "vtk.field = 'slope' (run.toml) is not allowed with a string"),
        # the bed's histories have their own samples: a step is refused by its solver, from the
        # file (it was dropped) as from the command line
        ("[vtk]\noutput_step = 2e-5\n", "output_step = 2e-05 is not allowed with a string bed"),
    ],
    ids=["subdivide", "field", "output_step"],
)
def test_what_the_strung_series_does_not_draw_is_refused_alike(cwd, capsys, table, words):
    pytest.importorskip("pyvista")
    (cwd / "run.toml").write_text(BED + table)
    assert main(["export-vtk", "--config", "run.toml", "--out", "a"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and words in err, err
    with pytest.raises(InputError, match=words.split(" (")[0].replace(".", r"\.")):
        load_config(cwd / "run.toml").export_vtk(out=cwd / "b")
    assert not (cwd / "a").exists() and not (cwd / "b").exists()


def test_a_step_at_the_default_changes_nothing(cwd, capsys):
    # [simulate] output_step = 1e-5 (the default) with a bed: run by both, as a default key
    (cwd / "run.toml").write_text(BED + "[simulate]\noutput_step = 1e-5\n")
    assert main(["simulate", "--config", "run.toml", "--json"]) == 0, capsys.readouterr().err
    load_config(cwd / "run.toml").simulate()
    (cwd / "run.toml").write_text(BED + "[simulate]\noutput_step = 2e-5\n")
    assert main(["simulate", "--config", "run.toml"]) == 2  # was run, the step dropped
    assert "output_step = 2e-05 is not allowed with a string bed" in capsys.readouterr().err
    with pytest.raises(InputError, match="output_step = 2e-05 is not allowed with a string bed"):
        load_config(cwd / "run.toml").simulate()
