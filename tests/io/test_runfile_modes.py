"""``load_config(f).modes()`` = ``fem-racket modes --config f`` (issue 21.7): the bending modes,
their nodes, the mass properties and catalogue numbers, and the torsion modes where the frame has
torsion data, to the command's printed digits (its JSON, 15 significant digits: 1e-12); none
where it has none."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from clirun import run_json
from runfile_helpers import py_json, same

from fem_racket import load_config
from fem_racket.frame.modal import FreeModes

MESHES = Path(__file__).resolve().parents[2] / "meshes"


def _both(capsys, text: str):
    Path("run.toml").write_text(text)
    return load_config("run.toml").modes(), run_json(capsys, "modes", "--config", "run.toml")


def test_a_frame_with_torsion_gives_its_torsion_modes(cwd, capsys):
    # the standard preset carries the torsion profile (GJ, rhoIp); lead at 12 o'clock on it
    text = '[frame]\nelements = 12\n[[frame.lead]]\nplace = "12"\nmass_g = 3\n[modes]\ncount = 3\n'
    modes, cli = _both(capsys, text)
    same(py_json(modes.summary()), cli)  # every key, bending and torsion, to 1e-12
    assert len(cli["frequencies_hz"]) == len(cli["torsion_frequencies_hz"]) == 3
    same(py_json(modes.torsion_frequencies.tolist()), cli["torsion_frequencies_hz"])
    same(py_json(modes.frequencies.tolist()), cli["frequencies_hz"])
    assert modes.props is modes.bending.props and isinstance(modes.bending, FreeModes)
    assert modes.torsion.polar_moment == pytest.approx(cli["polar_moment_kg_m2"], rel=1e-12)
    assert repr(modes).startswith("RacketModes(bending=[") and "torsion=[" in repr(modes)


def test_a_fitted_mesh_with_a_twistweight_gives_its_torsion_modes(cwd, capsys):
    # fit --twist-weight writes GJ and rhoIp: the frame written takes torsion
    run_json(capsys, "fit", "--length", "0.685", "--mass", "0.318", "--balance", "0.32",
             "--swing-weight", "316", "--twist-weight", "15", "--out", "fit.vtu")  # fmt: skip
    modes, cli = _both(capsys, '[frame]\nmesh = "fit.vtu"\n')
    same(py_json(modes.summary()), cli)
    assert len(cli["torsion_frequencies_hz"]) == 4  # the default count
    assert cli["twist_weight_kg_cm2"] == pytest.approx(15.0, rel=1e-9)  # the fitted target


def test_a_mesh_without_torsion_gives_none(cwd, capsys):
    mesh = MESHES / "tapered_racket.vtu"
    modes, cli = _both(capsys, f"[frame]\nmesh = {str(mesh)!r}\n[modes]\ncount = 2\n")
    same(py_json(modes.summary()), cli)
    assert modes.torsion is None and modes.torsion_frequencies is None
    assert "torsion=None" in repr(modes)
    assert "torsion_frequencies_hz" not in cli and cli["twist_weight_kg_cm2"] is None
    assert len(modes.nodes) == 2 and all(np.all((n > 0) & (n < 1)) for n in modes.nodes)


def test_more_modes_than_the_mesh_has_are_noted(cwd, capsys, caplog):
    import logging

    caplog.set_level(logging.INFO, logger="fem_racket.io.config_modes")
    modes, cli = _both(capsys, "[frame]\nelements = 3\n[modes]\ncount = 9\n")
    same(py_json(modes.summary()), cli)
    assert len(cli["frequencies_hz"]) == modes.bending.omega.size < 9
    assert "count = 9: the 3-element mesh has" in caplog.text
