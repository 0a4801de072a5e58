"""Run files = CLI, walked (issue 21.7): for every command that takes ``--config`` (its Python
method, or for ``reproduce`` :func:`fem_racket.paper.config_reproduce.reproduce_file`), every key
of the core tables alone, every pair of them (``-m slow``) and the combinations that meet in one
run (a hand with an oblique ball, a bed off the axis, a clamped head with a frame ...), the
method ``load_config(f).<command>()`` refuses exactly the files ``fem-racket <command> --config
f`` refuses, and runs the others (with the command's own table :data:`BASE` where it needs one
to run, and the operands a run file cannot name, :data:`OPERANDS`). Both are run to the end of
their checks only (:func:`fem_racket.validation.checks_only`, as ``config --check`` runs the
command), so the walk is fast; the numbers of the runs are compared in ``test_config_run.py``,
``test_config_commands.py``, ``test_runfile_*.py``."""

from __future__ import annotations

import itertools
import shutil
from pathlib import Path

import pytest

from fem_racket import load_config
from fem_racket.cli.commands.config import _dry_run
from fem_racket.paper.config_reproduce import reproduce_file
from fem_racket.validation import ChecksPassed, InputError, checks_only

ROOT = Path(__file__).resolve().parents[2]

#: One non-neutral value of every kind of core key (name -> TOML), and command-table keys that
#: meet the core tables (a step or a drawing option with a bed, a power area with a spin map).
KEYS = {
    "frame.preset": '[frame]\npreset = "rigid"\n',
    "frame.ei1": "[frame]\nei1_n_m2 = 300.0\n",
    "frame.ei2": "[frame]\nei2_n_m2 = 100.0\n",
    "frame.elements": "[frame]\nelements = 12\n",
    "frame.segments": "[frame]\nsegments = [{ length_m = 0.2, ei_n_m2 = 150.0, rhoa_kg_m = 0.7 }, "
    "{ length_m = 0.48, ei_n_m2 = 120.0, rhoa_kg_m = 0.46 }]\n",
    "frame.mesh": '[frame]\nmesh = "standard_racket.vtu"\n',
    "frame.lead": '[[frame.lead]]\nplace = "12"\nmass_g = 3\n',
    "ball.mass": "[ball]\nmass_kg = 0.056\n",
    "contact.kcb": "[contact]\nkcb_n_m = 30000.0\n",
    "contact.zeta": "[contact]\nzeta = 0.05\n",
    "contact.clamped_cor": "[contact]\nclamped_cor = 0.8\n",
    "contact.law": '[contact]\nlaw = "hysteretic"\n',
    "impact.position": "[impact]\nposition_x_over_l = 0.7\n",
    "impact.offset": "[impact]\noffset_m = 0.02\n",
    "impact.speed": "[impact]\nspeed_m_s = 25.0\n",
    "impact.swing": "[impact]\nracket_speed_m_s = 10.0\n",
    "impact.reference": "[impact]\nracket_speed_m_s = 10.0\nreference_x_over_l = 0.6\n",
    "impact.pivot": "[impact]\nracket_speed_m_s = 10.0\npivot_m = 0.1\n",
    "hand.grip": '[hand]\ngrip = "firm"\n',
    "hand.mass": "[hand]\nmass_kg = 0.4\n",
    "hand.window": '[hand]\ngrip = "firm"\nshock_window_s = 0.03\n',
    "strings.tension": "[strings]\ntension_n = 270.0\n",
    "strings.pattern": '[strings]\npattern = "18x20"\n',
    "strings.area": "[strings]\nhead_area_cm2 = 600.0\n",
    "strings.edge": '[strings]\nedge = "hoop"\n',
    "strings.stretch": "[strings]\nstretch = true\n",
    "oblique.angle": "[oblique]\nangle_deg = 30.0\n",
    "oblique.spin": "[oblique]\nspin_rpm = 1500.0\n",
    "oblique.side": "[oblique]\nside_angle_deg = 10.0\n",
    "oblique.clamped": "[oblique]\nclamped = true\n",
    "oblique.face": "[oblique]\nface_angle_deg = 80.0\n",
    "oblique.path": "[oblique]\npath_angle_deg = 19.0\n[impact]\nracket_speed_m_s = 10.0\n",
    "solver.name": '[solver]\nname = "cvode"\n',
    "solver.separation": '[solver]\nseparation = "force"\n',
    "solver.basis": '[solver]\nbasis = "physical"\n',
    "solver.modes": "[solver]\nmodes = 10\n",
    "solver.tolerance": "[solver]\ntolerance = 1e-7\n",
    "solver.rtol": "[solver]\nrtol = 1e-8\n",
    "solver.t_max": "[solver]\nt_max_s = 0.05\n",
    "output.out": '[output]\nout = "r.json"\n',
}
TABLE_KEYS = {
    "simulate.output_step": "[simulate]\noutput_step = 2e-5\n",
    "vtk.output_step": "[vtk]\noutput_step = 2e-5\n",
    "vtk.subdivide": "[vtk]\nsubdivide = 2\n",
    "vtk.field": '[vtk]\nfield = "slope"\n',
    "animate.subdivide": "[animate]\nsubdivide = 2\n",
    "map.power_fraction": "[map]\npower_fraction = 0.8\n",
    "modes.count": "[modes]\ncount = 2\n",
    "customise.maps": '[customise]\nmaps = "maps.nc"\n',
    "compare.offsets": '[compare]\noffsets = "-0.02:0.02:3"\n',
    "calibrate.family": '[calibrate]\nfamily = "hunt-crossley"\n',
    "reproduce.quick": "[reproduce]\nquick = true\n",
}
#: Keys at simulate's defaults: they change nothing, on the command line as in Python.
AT_DEFAULT = {
    "default.elements": "[frame]\nelements = 20\n",
    "default.preset": '[frame]\npreset = "standard"\n',
    "default.position": "[impact]\nposition_x_over_l = 0.75\n",
    "default.swing": "[impact]\nracket_speed_m_s = 0.0\n",
    "default.offset": "[impact]\noffset_m = 0.0\n",
    "default.law": '[contact]\nlaw = "linear"\n',
    "default.modes": "[solver]\nmodes = 80\n",
    "default.solver": '[solver]\nname = "auto"\nseparation = "displacement"\n',
    "default.step": "[simulate]\noutput_step = 1e-5\n",
}
#: Combinations of more than two that one run brings together.
TRIPLES = [
    ("hand.window", "oblique.angle", "impact.swing"),
    ("hand.grip", "oblique.path", "oblique.face"),
    ("hand.grip", "oblique.angle", "solver.modes"),
    ("hand.grip", "oblique.angle", "contact.law"),
    ("hand.grip", "oblique.clamped", "oblique.angle"),
    ("strings.tension", "oblique.angle", "impact.offset"),
    ("strings.tension", "oblique.clamped", "oblique.angle"),
    ("strings.tension", "oblique.angle", "simulate.output_step"),
    ("strings.tension", "impact.offset", "vtk.subdivide"),
    ("strings.stretch", "vtk.output_step", "solver.name"),
    ("oblique.clamped", "contact.kcb", "solver.separation"),
    ("oblique.angle", "contact.law", "solver.separation"),
    ("oblique.angle", "impact.swing", "map.power_fraction"),
    ("oblique.spin", "contact.law", "solver.modes"),
]
#: Command -> its own table, which it needs to run (the targets of fit, customise, closest).
BASE = {
    "fit": "fit.spec",
    "customise": "customise.target",
    "closest": "closest.target",
}
BASES = {
    "fit.spec": "[fit]\nlength = 0.685\nmass = 0.318\nbalance = 0.32\nswing_weight = 316\n",
    "customise.target": "[customise]\nswing_weight = 330\n",
    "closest.target": '[closest]\nswing_weight = 330\nbalance = "0.31:0.33"\n',
}
#: What a run file cannot name, given to the command and its method alike.
CSV = str(ROOT / "meshes" / "rackets.csv")
OPERANDS = {"closest": (CSV,), "compare": ("standard", "rigid")}
#: Command -> its Python method.
METHODS = {
    "simulate": lambda c: c.simulate(),
    "export-vtk": lambda c: c.export_vtk("py_vtk"),
    "animate": lambda c: c.animate("py.gif"),
    "sweep": lambda c: c.sweep(backend="serial"),
    "map": lambda c: c.map(),
    "refine": lambda c: c.refine(),
    "optimize": lambda c: c.optimize("py_design"),
    "sensitivity": lambda c: c.sensitivity("py_sens.png"),
    "modes": lambda c: c.modes(),
    "fit": lambda c: c.fit("py.vtu"),
    "customise": lambda c: c.customise("py.vtu"),
    "closest": lambda c: c.closest(CSV),
    "compare": lambda c: c.compare(list(OPERANDS["compare"]), "py.png"),
    "calibrate": lambda c: c.calibrate("py_calibration"),
    "reproduce": lambda c: reproduce_file(c, "py_paper", "py.md"),
}
#: Extras a command needs (skipped without them).
NEEDS = {"export-vtk": "pyvista", "animate": "imageio", "sensitivity": "SALib"}


def merged(names) -> str:
    """The run file of the snippets ``names``, their tables merged."""
    snippets = {**KEYS, **TABLE_KEYS, **AT_DEFAULT, **BASES}
    tables: dict[str, list[str]] = {}
    for name in names:
        head = None
        for line in snippets[name].splitlines():
            if line.startswith("["):
                head = line
                tables.setdefault(head, [])
            elif line not in tables[head]:
                tables[head].append(line)
    order = sorted(tables, key=lambda h: h.startswith("[["))  # arrays of tables last
    return "".join(h + "\n" + "".join(f"{x}\n" for x in tables[h]) for h in order)


def verdicts(command: str, path: Path) -> tuple[str, str]:
    """("ok" | "refused: ...") of the command and of its Python method, checks only."""
    try:
        _dry_run(command, str(path), OPERANDS.get(command, ()))
        cli = "ok"
    except InputError as exc:
        cli = f"refused: {exc}"
    try:
        with checks_only():
            METHODS[command](load_config(path))
        py = "ran past its checks"  # (work_begins never reached: a failure)
    except ChecksPassed:
        py = "ok"
    except InputError as exc:
        py = f"refused: {exc}"
    return cli, py


def walk(command: str, folder: Path, combos) -> list[str]:
    """The combinations whose verdicts differ (the command and its method), as lines."""
    if command in NEEDS:
        pytest.importorskip(NEEDS[command])
    shutil.copy(ROOT / "meshes" / "standard_racket.vtu", folder)
    path = folder / "run.toml"
    out = []
    for names in combos:
        names = (*names, BASE[command]) if command in BASE else names
        path.write_text(merged(names))
        try:
            load_config(path)
        except InputError:  # the file itself is refused (frame.mesh with frame.elements ...)
            continue
        cli, py = verdicts(command, path)
        if cli.split(":")[0] != py.split(":")[0] or py.startswith("ran"):
            out.append(f"{' + '.join(names)}: command {cli!r}, method {py!r}")
    return out


@pytest.mark.parametrize("command", list(METHODS))
def test_every_key_alone_and_the_meeting_combinations(cwd, command):
    combos = [(n,) for n in [*KEYS, *TABLE_KEYS]] + TRIPLES
    assert walk(command, cwd, combos) == []


@pytest.mark.parametrize("command", ["simulate", "export-vtk", "map", "refine"])
def test_keys_at_their_defaults_change_nothing(cwd, command):
    # alone, and with what refuses options given (a clamped head, a hand, a bed)
    others = [(), ("oblique.clamped",), ("hand.grip",), ("strings.tension",)]
    combos = [(n, *o) for n in AT_DEFAULT for o in others]
    assert walk(command, cwd, combos) == []


@pytest.mark.slow
@pytest.mark.parametrize("command", list(METHODS))
def test_every_pair_of_keys(cwd, command):
    combos = list(itertools.combinations([*KEYS, *TABLE_KEYS], 2))
    assert walk(command, cwd, combos) == []


def test_the_walk_sees_a_refusal_and_a_run(cwd):
    # the walk's two verdicts are real: a hand with a bed is refused by both, a bed runs
    path = cwd / "run.toml"
    path.write_text(merged(["hand.grip", "strings.tension"]))
    cli, py = verdicts("simulate", path)
    assert cli.startswith("refused: ") and py.startswith("refused: ")
    path.write_text(merged(["strings.tension", "oblique.angle"]))
    assert verdicts("simulate", path) == ("ok", "ok")
