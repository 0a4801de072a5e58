"""A catalogue of bad inputs through the CLI, in-process, for every command.

Every case must give: exit code 2, exactly one line on stderr that names the parameter and says
what is allowed, no traceback, and no file or folder left behind or changed (each ``simulate``
case also asks for ``--out result.json``; the other commands write to their default ``output/``
under the test's working folder; so a case that wrongly ran to the end, or failed half-way
through writing, would leave a file).

Extend the lists below; bad mesh files have their own list, ``BAD_MESHES``, each run through a
run file's ``frame.mesh`` and through ``--mesh`` of every command that takes one.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pytest

from tests.clirun import one_error


@dataclass
class Case:
    """argv for ``main``; ``files`` are created in the working folder first (name -> text)."""

    id: str
    argv: list[str]
    names: tuple[str, ...]  # every one must appear in the error line (parameter, allowed form)
    files: dict[str, str] = field(default_factory=dict)


def sim(*argv: str) -> list[str]:
    return ["simulate", *argv]


def sweep(*argv: str) -> list[str]:
    return ["sweep", "--serial", "--quiet", *argv]


def based(command: str, base: dict[str, tuple[str, ...]], argv: tuple[str, ...]) -> list[str]:
    """``command`` with the ``base`` options (name -> values) the case does not give itself,
    then the case's own arguments (an option given twice with two values is refused)."""
    kept = [x for name, values in base.items() if name not in argv for x in (name, *values)]
    return [command, *kept, *argv]


def refine(*argv: str) -> list[str]:
    # Small enough that a case wrongly running to the end costs little (and leaves files).
    base = {"--elements": ("5", "10"), "--family": ("uniform",), "--positions": ("0.75",)}
    return based("refine", base, argv)


def vtk(*argv: str) -> list[str]:
    return based("export-vtk", {"--frames": ("3",)}, argv)


def anim(*argv: str) -> list[str]:
    return based("animate", {"--frames": ("3",), "--size": ("160x160",)}, argv)


def mapc(*argv: str) -> list[str]:
    return based("map", {"--positions": ("0.5:1.0:5",)}, argv)


def fitc(*argv: str, **spec: str) -> list[str]:
    values = {"length": "0.685", "mass": "0.318", "balance": "0.32", "swing-weight": "316"}
    values.update({k.replace("_", "-"): v for k, v in spec.items()})
    return ["fit", *(x for k, v in values.items() for x in (f"--{k}", v)), *argv]


def opt(*argv: str) -> list[str]:
    base = {"--boundaries": ("0.3",), "--speeds": ("30",), "--zone-points": ("3",)}
    return based("optimize", base, argv)


def sens(*argv: str) -> list[str]:
    return based(
        "sensitivity", {"--boundaries": ("0.3",), "--speeds": ("30",), "--designs": ("8",)}, argv
    )


def repro(*argv: str) -> list[str]:
    return ["reproduce", "--quick", *argv]


ELEMENTS_ZERO = "elements = 0 is not allowed: must be an integer from 2 to 50000"
A_FILE = {"afile": "not a folder"}  # a regular file where an output folder should go


def unwritable(case_id: str, argv: list[str], option: str, path: str) -> Case:
    """``--option path`` under the regular file 'afile': refused before anything runs."""
    says = (f"{option} = '{path}'", "cannot be created: 'afile' is a file")
    return Case(case_id, [*argv, f"--{option}", path], says, A_FILE)


def existing(case_id: str, argv: list[str], shown: str, files: dict[str, str]) -> Case:
    """An output that is there already (``files``), named as ``shown``: refused without
    --overwrite."""
    return Case(case_id, argv, (shown, "already exists", "--overwrite"), files)


def toml(text: str, *argv: str, command: str = "simulate") -> tuple[list[str], dict[str, str]]:
    """argv running ``command`` on run.toml holding ``text``, and the files to create."""
    return [command, "--config", "run.toml", *argv], {"run.toml": text}


def T(case_id: str, argv_files: tuple[list[str], dict[str, str]], names: tuple[str, ...]) -> Case:
    """A case running a run file (see :func:`toml`)."""
    return Case(case_id, argv_files[0], names, argv_files[1])


CLI_CASES = [
    Case("speed-zero", sim("--speed", "0"), ("speed = 0", "> 0")),
    Case("speed-negative", sim("--speed", "-3"), ("speed = -3", "> 0")),
    Case("speed-nan", sim("--speed", "nan"), ("speed = nan", "finite")),
    Case("speed-inf", sim("--speed", "inf"), ("speed = inf", "finite")),
    Case("speed-not-a-number", sim("--speed", "fast"), ("--speed", "float")),
    Case("position-off-tip", sim("--position", "1.5"), ("position = 1.5", "[0, 1]")),
    Case("position-off-grip", sim("--position", "-0.1"), ("position = -0.1", "[0, 1]")),
    Case("position-nan", sim("--position", "nan"), ("position", "finite")),
    Case("ei1-negative", sim("--ei1", "-146"), ("ei1 = -146", "must lie in [6.96e-07")),
    Case("ei1-zero", sim("--ei1", "0"), ("ei1 = 0", "must lie in [6.96e-07")),
    Case("ei1-inf", sim("--ei1", "inf"), ("ei1 = inf", "finite")),
    Case("ei2-nan", sim("--ei2", "nan"), ("ei2 = nan", "finite")),
    Case("ball-mass-zero", sim("--ball-mass", "0"), ("ball mass = 0", "> 0")),
    Case("ball-mass-negative", sim("--ball-mass", "-0.057"), ("ball mass", "> 0")),
    Case("kcb-zero", sim("--kcb", "0"), ("kcb = 0", "> 0")),
    Case("kcb-negative", sim("--kcb", "-1"), ("kcb = -1", "> 0")),
    Case("zeta-one", sim("--zeta", "1"), ("zeta = 1", "[0, 1)")),
    Case("zeta-negative", sim("--zeta", "-0.2"), ("zeta = -0.2", "[0, 1)")),
    Case("zeta-nan", sim("--zeta", "nan"), ("zeta", "finite")),
    Case("elements-one", sim("--elements", "1"), ("elements = 1", "from 2 to 50000")),
    Case("elements-zero", sim("--elements", "0"), ("elements = 0", "from 2 to 50000")),
    Case("modes-zero", sim("--modes", "0"), ("modes = 0", ">= 1")),
    Case("unknown-solver", sim("--solver", "euler"), ("--solver", "choose from", "exact")),
    Case("unknown-separation", sim("--separation", "x"), ("--separation", "choose from")),
    Case("exact-physical", sim("--basis", "physical"), ("basis = 'physical'", "'modal'")),
    Case("t-max-zero", sim("--t-max", "0"), ("t_max = 0", "> 0")),
    Case("t-max-negative", sim("--t-max", "-1"), ("t_max = -1", "> 0")),
    Case("rtol-zero", sim("--solver", "cvode", "--rtol", "0"), ("rtol = 0", "> 0")),
    Case("atol-nan", sim("--atol", "nan"), ("atol = nan", "finite")),
    # The standard impact lasts 4.04 ms: 0.1 ms is far too short to separate (exact and CVODE).
    Case("no-separation-exact", sim("--t-max", "1e-4"), ("t_max = 0.0001 s", "raise t_max")),
    Case(
        "no-separation-cvode",
        sim("--t-max", "1e-4", "--solver", "cvode"),
        ("t_max = 0.0001 s", "raise t_max"),
    ),
    Case("output-step-zero", sim("--output-step", "0"), ("output_step = 0.0 s", "> 0")),
    Case("output-step-nan", sim("--output-step", "nan"), ("output_step = nan", "finite")),
    # A hand on the grip (fem_racket.frame.hand; the standard frame is 0.68 m long).
    Case("grip-unknown", sim("--grip", "tight"), ("--grip", "choose from", "loose", "firm")),
    Case("grip-stiffness-negative", sim("--grip-stiffness", "-1"), ("grip stiffness = -1", ">= 0")),
    Case(
        "grip-damping-nan",
        sim("--grip", "firm", "--grip-damping", "nan"),
        ("grip damping", "finite"),
    ),
    Case("grip-end-beyond-frame", sim("--grip-end", "0.9"), ("grip_end = 0.9", "beyond the frame")),
    Case(
        "grip-start-after-end",
        sim("--grip-start", "0.2", "--grip-end", "0.1"),
        ("grip = (0.2, 0.1)", "grip_start < grip_end"),
    ),
    Case("hand-mass-zero", sim("--hand-mass", "0"), ("hand mass = 0", "> 0")),
    Case("hand-inertia-negative", sim("--hand-inertia", "-0.0001"), ("hand inertia", "> 0")),
    Case(
        "shock-window-shorter-than-contact",
        sim("--grip", "firm", "--shock-window", "0.001"),
        ("window = 0.001", "exceed the contact time"),
    ),
    Case(
        "shock-window-inf", sim("--grip", "firm", "--shock-window", "inf"), ("shock_window = inf",)
    ),
    Case(
        "shock-window-long", sim("--grip", "firm", "--shock-window", "5"), ("shock_window = 5", "1")
    ),
    Case(
        "shock-window-without-hand",
        sim("--shock-window", "0.03"),
        ("shock_window", "without a hand"),
    ),
    Case(
        "grip-without-stiffness-exact",
        sim("--grip-stiffness", "0"),
        ("grip stiffness = 0", "> 0", "cvode"),
    ),
    Case(
        "hand-elements-exact", sim("--grip", "firm", "--elements", "500"), ("elements = 500", "200")
    ),
    Case(
        "hand-elements-cvode",
        sim("--grip", "firm", "--elements", "60", "--solver", "cvode"),
        ("elements = 60", "at most 40", "exact"),
    ),
    Case(
        "hand-rtol-zero", sim("--grip", "firm", "--solver", "cvode", "--rtol", "0"), ("rtol = 0",)
    ),
    Case("hand-with-modes", sim("--grip", "firm", "--modes", "10"), ("--modes", "with a hand")),
    Case(
        "hand-with-separation",
        sim("--grip", "firm", "--separation", "force"),
        ("--separation", "with a hand"),
    ),
    Case(
        "hand-with-general",
        sim("--grip", "firm", "--solver", "general"),
        ("solver = 'general'", "exact"),
    ),
    Case(
        "hand-with-a-nonlinear-law",
        sim("--grip", "firm", "--law", "hunt-crossley"),
        ("law = 'hunt-crossley'", "linear"),
    ),
    # One racket per command: a second --mesh used to replace the first silently.
    Case(
        "mesh-twice",
        sim("--mesh", "a.vtu", "--mesh", "b.vtu"),
        ("--mesh is given twice", "'a.vtu'", "'b.vtu'"),
    ),
    # A nonlinear law with the paper's K_CB or zeta, or with the exact solver: refused, not
    # ignored or switched (the library's ImpactProblem and solvers).
    Case(
        "law-with-exact",
        sim("--law", "hunt-crossley", "--solver", "exact"),
        ("solver = 'exact'", "general"),
    ),
    Case("law-with-modes", sim("--law", "hysteretic", "--modes", "10"), ("modes = 10",)),
    Case("modes-count-zero", ["modes", "--count", "0"], ("count = 0", ">= 1")),
    Case("modes-ei1-nan", ["modes", "--ei1", "nan"], ("ei1 = nan", "finite")),
    Case("unknown-command", ["nonsense"], ("COMMAND", "choose from")),
    Case("config-needs-a-mode", ["config"], ("--example", "--check", "required")),
]

SWEEP_CASES = [
    Case("sweep-grid-two-parts", sweep("--speed", "1:2"), ("speed = '1:2'", "start:stop:num")),
    Case("sweep-grid-letters", sweep("--speed", "a,b"), ("speed = 'a,b'", "a comma list")),
    Case(
        "sweep-grid-num-zero",
        sweep("--position", "0.5:0.9:0"),
        ("position = '0.5:0.9:0'", "num must be an integer from 1 to 10000000"),
    ),
    Case(
        "sweep-grid-unknown-spacing",
        sweep("--ei1", "50:3000:60:lin"),
        ("ei1 = '50:3000:60:lin'", "start:stop:num[:log]"),
    ),
    Case("sweep-grid-log-negative", sweep("--ei1=-5:100:3:log"), ("ei1", "start, stop > 0")),
    Case("sweep-ei1-negative-in-list", sweep("--ei1=-5,100"), ("ei1 = -5", "> 0")),
    Case("sweep-position-off-frame", sweep("--position", "0.5,1.5"), ("position = 1.5", "[0, 1]")),
    Case("sweep-speed-nan", sweep("--speed", "nan"), ("speed = nan", "finite")),
    Case("sweep-repeated-values", sweep("--speed", "20,20"), ("speed = [20.0, 20.0]", "distinct")),
    Case("sweep-zeta-one", sweep("--zeta", "0.5,1"), ("zeta = 1", "[0, 1)")),
    Case("sweep-elements-fraction", sweep("--elements", "10.5"), ("elements = 10.5", "integer")),
    # The same words as simulate's --elements (before: "finite number > 0", "np.float64(0.0)").
    Case("sweep-elements-zero", sweep("--elements", "0"), (ELEMENTS_ZERO,)),
    Case("sweep-elements-range-from-zero", sweep("--elements", "0:10:3"), (ELEMENTS_ZERO,)),
    Case("simulate-elements-zero", sim("--elements", "0"), (ELEMENTS_ZERO,)),
    Case(
        "sweep-range-underflows-to-zero",
        sweep("--speed", "1e-400:3:2"),
        ("speed = 0.0 m/s is not allowed",),
    ),
    Case(
        "sweep-long-list-shortened",
        sweep("--position", ",".join(["0.5"] * 80)),
        ("position = [0.5, 0.5,", "... (80 values)] is not allowed", "distinct"),
    ),
    Case(
        "sweep-scheduler-form",
        ["sweep", "--quiet", "--scheduler", "localhost:8786"],
        ("scheduler = 'localhost:8786'", "tcp://HOST:PORT"),
    ),
    Case("sweep-workers-zero", ["sweep", "--quiet", "--workers", "0"], ("workers = 0", ">= 1")),
    Case("sweep-modes-zero", sweep("--modes", "0"), ("modes = 0", ">= 1")),
    existing("sweep-out-exists", sweep("--out", "old.nc"), "out = 'old.nc'", {"old.nc": "mine"}),
    unwritable("sweep-out-unwritable", sweep(), "out", "afile/s.nc"),
    Case(
        "sweep-ei1-with-run-file-segments",
        ["sweep", "--serial", "--ei1", "100", "--config", "run.toml"],
        ("--ei1 cannot be combined with frame.segments",),
        {"run.toml": "[frame]\nsegments = [{length_m=0.7, ei_n_m2=150, rhoa_kg_m=0.5}]\n"},
    ),
    Case(
        "sweep-racket-away-before-any-file",
        sweep("--law", "hysteretic", "--racket-speed=-30,0", "--out", "x.nc"),
        ("racket speed at the impact point = -30 m/s", "must close"),
    ),
    Case(
        "sweep-pivot-at-reference",
        sweep("--racket-speed", "10", "--pivot", "0,0.51", "--out", "x.nc"),
        ("pivot = 0.51", "reference point"),
    ),
    Case(
        "sweep-law-parameter-range",
        sweep("--law", "hunt-crossley", "--hc-exponent", "0.5:2:3"),
        ("hc_exponent = 0.5", "[1, 20]"),
    ),
    Case(
        "sweep-law-parameter-form",
        sweep("--law", "series", "--string-cubic", "1:2"),
        ("string_cubic = '1:2'", "start:stop:num"),
    ),
    Case(
        "sweep-law-parameter-other-family",
        sweep("--law", "hysteretic", "--hc-alpha", "0.1,0.2"),
        ("hc_alpha", "law 'hysteretic'", "k1"),
    ),
    Case(
        "sweep-law-parameter-of-a-preset",
        sweep("--law", "kawazoe-1997-nonlinear", "--k1", "1e15,2e15"),
        ("k1", "preset"),
    ),
    Case(
        "sweep-law-parameter-in-run-file",
        ["sweep", "--serial", "--quiet", "--config", "run.toml"],
        ("sweep.k2 = 0.0", "> 0"),
        {"run.toml": '[contact]\nlaw = "hysteretic"\n[sweep]\nk2 = [0.0, 1e17]\n'},
    ),
]

VTK_CASES = [
    Case("vtk-unknown-field", vtk("--field", "stress"), ("field = 'stress'", "must be one of")),
    Case("vtk-negative-scale", vtk("--scale", "-1"), ("scale = -1", "(0, 1e+06]")),
    Case("vtk-huge-scale", vtk("--scale", "1e300"), ("scale = 1e+300", "(0, 1e+06]")),
    Case("vtk-frames-one", vtk("--frames", "1"), ("frames = 1", ">= 2")),
    Case("vtk-frames-too-many", vtk("--frames", "100000"), ("frames = 100000", "406 output")),
    Case("vtk-subdivide-zero", vtk("--subdivide", "0"), ("subdivide = 0", ">= 1")),
    Case("vtk-output-step-zero", vtk("--output-step", "0"), ("output_step = 0", "> 0")),
    Case("vtk-speed-zero", vtk("--speed", "0"), ("speed = 0", "> 0")),
    unwritable("vtk-out-unwritable", vtk(), "out", "afile/vtk"),
    Case(
        "vtk-out-is-a-file", vtk("--out", "afile"), ("out = 'afile'", "is a file", "folder"), A_FILE
    ),
    existing("vtk-out-exists", vtk("--out", "old"), "out = 'old'", {"old/provenance.json": "{}"}),
    Case(
        "vtk-overwrite-foreign-folder",
        vtk("--out", "mine", "--overwrite"),
        ("out = 'mine'", "without 'provenance.json'", "refusing"),
        {"mine/notes.txt": "precious"},
    ),
    Case("anim-unknown-field", anim("--field", "heat"), ("field = 'heat'", "must be one of")),
    Case("anim-negative-scale", anim("--scale", "-10"), ("scale = -10", "(0, 1e+06]")),
    Case("anim-frames-one", anim("--frames", "1"), ("frames = 1", ">= 2")),
    Case("anim-bad-suffix", anim("--out", "a.avi"), ("out = 'a.avi'", ".gif or .mp4")),
    Case("anim-fps-zero", anim("--fps", "0"), ("fps = 0", "[0.01, 100]")),
    Case("anim-fps-tiny", anim("--fps", "0.001"), ("fps = 0.001", "[0.01, 100]")),
    Case("anim-fps-nan", anim("--fps", "nan"), ("fps = nan", "finite")),
    Case("anim-size-not-16", anim("--size", "170x160"), ("size = (170, 160)", "multiple of 16")),
    Case("anim-size-form", anim("--size", "big"), ("--size", "WIDTHxHEIGHT")),
    unwritable("anim-out-unwritable", anim(), "out", "afile/a.gif"),
    existing(
        "anim-sidecar-exists", anim("--out", "a.gif"), "out = 'a.gif.json'", {"a.gif.json": "{}"}
    ),
]

REFINE_CASES = [
    Case(
        "refine-elements-zero",
        refine("--elements", "5", "0"),
        ("elements = [5, 0]", "from 1 to 50000"),
    ),
    Case(
        "refine-elements-over-limit",
        refine("--elements", "5", "60000"),
        ("elements = [5, 60000]", "from 1 to 50000"),
    ),
    Case("refine-elements-fraction", refine("--elements", "5", "2.5"), ("--elements", "int")),
    Case(
        "refine-elements-comma-fraction",
        refine("--elements", "5,2.5"),
        ("--elements", "'5,2.5'", "integer", "spaces or commas"),
    ),
    Case("refine-elements-empty-item", refine("--elements", "5,,10"), ("--elements", "'5,,10'")),
    Case(
        "refine-positions-comma-off-frame",
        refine("--position", "0.5,1.2"),
        ("position = 1.2", "[0, 1]"),
    ),
    Case("refine-position-off-frame", refine("--positions", "0.5", "1.2"), ("position = 1.2",)),
    Case("refine-position-negative", refine("--positions", "-0.1"), ("position = -0.1", "[0, 1]")),
    Case("refine-count-zero", refine("--count", "0"), ("count = 0", ">= 1")),
    Case("refine-grading-below-one", refine("--grading", "0.5"), ("grading = 0.5", ">= 1")),
    Case("refine-speed-negative", refine("--speed", "-20"), ("speed = -20", "> 0")),
    Case("refine-ei1-nan", refine("--ei1", "nan"), ("ei1 = nan", "finite")),
    existing("refine-csv-exists", refine("--csv", "r.csv"), "csv = 'r.csv'", {"r.csv": "mine"}),
    unwritable("refine-plot-unwritable", refine(), "plot", "afile/r.png"),
]

REPRODUCE_CASES = [
    Case(
        "reproduce-out-unwritable",
        repro("--out", "afile/paper"),
        ("out = 'afile/paper/", "cannot be created: 'afile' is a file"),
        A_FILE,
    ),
    unwritable("reproduce-report-unwritable", repro(), "report", "afile/R.md"),
    existing(
        "reproduce-report-exists",
        repro(),
        "report = 'REPRODUCTION.md'",
        {"REPRODUCTION.md": "mine"},
    ),
]

MAP_CASES = [
    Case("map-speed-zero", mapc("--speed", "0"), ("speed = 0", "> 0")),
    Case("map-positions-off-tip", mapc("--positions", "0.5:1.5:9"), ("position =", "[0, 1]")),
    Case("map-one-position", mapc("--positions", "0.7"), ("positions", "at least 3")),
    Case("map-power-fraction", mapc("--power-fraction", "0"), ("power_fraction = 0", "(0, 1]")),
    Case("map-pivot-at-reference", mapc("--racket-speed", "9", "--pivot", "0.51"), ("pivot",)),
    Case("map-racket-away", mapc("--racket-speed", "-40"), ("racket_speed = -40", "must close")),
    Case("map-reference-off", mapc("--reference", "2"), ("reference = 2", "[0, 1]")),
    Case("map-law-parameter-linear", mapc("--hc-alpha", "0.1"), ("hc_alpha", "law 'linear'")),
    Case("map-kcb-with-a-law", mapc("--law", "hysteretic", "--kcb", "5e4"), ("kcb", "contact law")),
    Case("map-law-range", mapc("--law", "hysteretic", "--hyst-exponent", "30"), ("hyst_exponent",)),
    Case("map-bad-suffix", mapc("--out", "m.txt"), ("m.txt", ".png")),
    Case("map-unknown-preset", mapc("--preset", "soft"), ("--preset", "choose from")),
    Case("map-ball-mass", mapc("--ball-mass", "0"), ("ball mass = 0", "> 0")),
    Case("map-tolerance", mapc("--tolerance", "-1"), ("tolerance = -1",)),
]

FIT_CASES = [
    Case("fit-mass-zero", fitc(mass="0"), ("mass = 0", "> 0")),
    Case("fit-balance-off", fitc(balance="0.9"), ("balance = 0.9", "must lie in")),
    Case("fit-balance-extreme", fitc(balance="0.6"), ("balance = 0.6", "must lie in")),
    Case("fit-swing-weight-high", fitc(swing_weight="600"), ("swing weight = 600", "kg cm^2")),
    Case("fit-swing-weight-low", fitc(swing_weight="100"), ("swing weight = 100", "kg cm^2")),
    Case("fit-f1-negative", fitc("--f1", "-5"), ("f1 = -5", "> 0")),
    Case("fit-elements-two", fitc("--elements", "2"), ("elements = 2", ">= 3")),
    Case("fit-length-nan", fitc(length="nan"), ("length = nan", "finite")),
    Case("fit-no-mass", ["fit", "--length", "0.68"], ("mass is required", "--mass")),
]

LEAD_CASES = [
    Case("lead-no-grams", ["modes", "--add-mass", "3/9"], ("add-mass = '3/9'", "LOCATION:GRAMS")),
    Case("lead-unknown-place", ["modes", "--add-mass", "13:5"], ("place = '13'", "3/9")),
    Case(
        "customise-unreachable",
        ["customise", "--swing-weight", "290", "--places", "12"],
        ("swing-weight = 290..290", "can reach"),
    ),
    Case("customise-no-target", ["customise"], ("targets = none", "--swing-weight")),
    Case("customise-mass-order", ["customise", "--mass", "0.4:0.3"], ("need 0 < LOW <= HIGH",)),
    Case(
        "customise-unknown-place",
        ["customise", "--mass", "0.4", "--places", "13"],
        ("place = '13' is not allowed",),
    ),
    Case(
        "customise-twist-unreachable",
        ["customise", "--twist-weight", "15", "--places", "3/9"],
        ("twist-weight = 15..15 kg cm^2", "can reach"),
    ),
    Case("closest-no-file", ["closest", "none.csv", "--mass", "0.3"], ("none.csv", "no such file")),
    Case("compare-one", ["compare", "standard"], ("need at least 2",)),
    Case("compare-bad-suffix", ["compare", "standard", "rigid", "--out", "c.txt"], ("c.txt",)),
]

DESIGN_CASES = [
    Case("optimize-speed-high", opt("--speeds", "200"), ("speed = 200", "[1, 100]")),
    Case("optimize-ei-bounds", opt("--ei-bounds", "0,100"), ("ei_1 bounds", "0 < low < high")),
    Case("optimize-vary", opt("--vary", "stiffness"), ("vary = 'stiffness'", "ei")),
    Case("optimize-objective", opt("--objective", "speed"), ("objective = 'speed'", "cor")),
    Case(
        "optimize-mass-range",
        opt("--mass-range", "0.4,0.3"),
        ("mass_kg = [0.4, 0.3]", "LOW < HIGH"),
    ),
    Case("optimize-zone-range", opt("--zone-range", "0.9,0.6"), ("zone range", "LOW < HIGH")),
    Case(
        "optimize-mass-position",
        opt("--vary", "mass", "--mass-positions", "1.2"),
        ("mass position = 1.2", "[0, 1]"),
    ),
    Case("optimize-nsga2-one-objective", opt("--method", "nsga2"), ("objectives", "2 or 3")),
    Case("optimize-racket-speed", opt("--racket-speed", "-5"), ("racket speed = -5", "[0, 100]")),
    Case(
        "optimize-shock-window",
        opt("--objective", "handle_shock", "--shock-window", "-1"),
        ("shock window = -1", "> 0"),
    ),
    Case("optimize-out-is-file", opt("--out", "afile"), ("afile", "folder"), A_FILE),
    Case(
        "optimize-position-bounds",
        opt("--vary", "position", "--mass-positions", "0.8", "--position-bounds", "0.5,1.2"),
        ("pos_1 bounds = [0.5, 1.2]", "0 <= low < high <= 1"),
    ),
    Case(
        "optimize-position-bounds-order",
        opt("--vary", "position", "--mass-positions", "0.8", "--position-bounds", "0.9,0.5"),
        ("position bounds = [0.9, 0.5]", "LOW < HIGH"),
    ),
    Case("optimize-ei-points", opt("--ei-points", "0.2,0.6,1"), ("ei_points", "first 0")),
    Case(
        "optimize-rhoa-points", opt("--rhoa-points", "0,0.7,0.5,1"), ("rhoa_points", "increasing")
    ),
    Case(
        "optimize-string-bounds",
        opt("--vary", "string", "--string-bounds", "0,2"),
        ("kcb_factor bounds = [0.0, 2.0]", "0 < low < high"),
    ),
    Case(
        "optimize-string-law",
        opt("--vary", "string", "--law", "hysteretic"),
        ("vary = 'string'", "linear and series"),
    ),
    Case(
        "optimize-cubic-bounds",
        opt("--vary", "string_cubic", "--law", "series", "--cubic-bounds=-1,5"),
        ("k_3 bounds = [-1.0, 5.0]", "0 <= low < high"),
    ),
    Case("sensitivity-output", sens("--output", "nothing"), ("output = 'nothing'", "cor")),
    Case("sensitivity-designs", sens("--designs", "2"), ("designs = 2", ">= 6")),
]

OUTPUT_CASES = [
    unwritable("out-under-a-regular-file", sim(), "out", "afile/result.json"),
    existing("out-exists", sim("--out", "old.json"), "out = 'old.json'", {"old.json": "{}"}),
    Case(
        "out-folder-not-made-when-the-run-fails",  # the check passes, the impact fails later
        sim("--out", "new/deeper/r.json", "--t-max", "1e-4"),
        ("t_max = 0.0001 s", "raise t_max"),
    ),
    Case("out-is-a-folder", sim("--out", ".", "--overwrite"), ("out = '.'", "must be a file")),
    Case("out-bad-suffix", sim("--out", "r.txt"), ("out = 'r.txt'", ".json or .csv")),
    existing(
        "out-csv-sidecar-exists", sim("--out", "r.csv"), "out = 'r.csv.json'", {"r.csv.json": "{}"}
    ),
    Case(
        "config-example-out-exists",
        ["config", "--example", "--out", "run.toml"],
        ("already exists", "--overwrite"),
        {"run.toml": "# mine\n"},
    ),
]

TOML_CASES = [
    T("toml-hand-grip-unknown", toml('[hand]\ngrip = "tight"\n'), ("hand.grip", "loose", "firm")),
    T(
        "toml-hand-stiffness-negative",
        toml("[hand]\nstiffness_n_m2 = -5\n"),
        ("hand.stiffness_n_m2 = -5", "[0, inf]"),
    ),
    T("toml-hand-unknown-key", toml("[hand]\nmass = 0.4\n"), ("hand.mass", "mass_kg")),
    T(
        "toml-malformed",
        toml("[impact]\nspeed_m_s = = 30\n"),
        ("run.toml", "not valid TOML", "line 2"),
    ),
    T("toml-unclosed-table", toml("[impact\nspeed_m_s = 3\n"), ("not valid TOML", "line 1")),
    Case("toml-missing-file", ["simulate", "--config", "nope.toml"], ("config = 'nope.toml'",)),
    Case("toml-folder", ["simulate", "--config", "."], ("config = '.'", "must be a TOML file")),
    T(
        "toml-unknown-key",
        toml("[impact]\nspeed = 30\n"),
        ("impact.speed is not a known key", "did you mean 'speed_m_s'"),
    ),
    T(
        "toml-key-in-wrong-table",
        toml("[ball]\nspeed_m_s = 30\n"),
        ("ball.speed_m_s", "did you mean 'impact.speed_m_s'"),
    ),
    T(
        "toml-unknown-table",
        toml("[impakt]\nspeed_m_s = 30\n"),
        ("impakt is not a known key", "did you mean 'impact'"),
    ),
    T("toml-top-level-key", toml("speed_m_s = 30\n"), ("speed_m_s", "impact.speed_m_s")),
    T(
        "toml-string-for-number",
        toml("[impact]\nspeed_m_s = '30'\n"),
        ("impact.speed_m_s = '30'", "must be a number"),
    ),
    T(
        "toml-bool-for-number",
        toml("[contact]\nkcb_n_m = true\n"),
        ("contact.kcb_n_m = True", "must be a number"),
    ),
    T(
        "toml-speed-negative",
        toml("[impact]\nspeed_m_s = -3\n"),
        ("impact.speed_m_s = -3 m/s", "> 0"),
    ),
    T("toml-speed-zero", toml("[impact]\nspeed_m_s = 0.0\n"), ("impact.speed_m_s = 0.0",)),
    T("toml-speed-nan", toml("[impact]\nspeed_m_s = nan\n"), ("impact.speed_m_s", "finite")),
    T("toml-speed-inf", toml("[impact]\nspeed_m_s = inf\n"), ("impact.speed_m_s", "finite")),
    T(
        "toml-position-off-frame",
        toml("[impact]\nposition_x_over_l = 1.2\n"),
        ("impact.position_x_over_l = 1.2", "[0, 1]"),
    ),
    T(
        "toml-unknown-solver",
        toml("[solver]\nname = 'euler'\n"),
        ("solver.name = 'euler'", "must be one of", "exact"),
    ),
    T(
        "toml-modes-float",
        toml("[solver]\nmodes = 1.5\n"),
        ("solver.modes = 1.5", "integer >= 1"),
    ),
    T(
        "toml-elements-zero",
        toml("[frame]\nelements = 0\n"),
        ("frame.elements = 0", "integer >= 1"),
    ),
    T(
        "toml-segment-negative-length",
        toml("[[frame.segments]]\nlength_m = -0.2\nei_n_m2 = 146\nrhoa_kg_m = 0.7\n"),
        ("frame.segments[0].length_m = -0.2 m", "> 0"),
    ),
    T(
        "toml-segment-missing-key",
        toml("[[frame.segments]]\nlength_m = 0.2\nei_n_m2 = 146\n"),
        ("frame.segments[0]", "rhoa_kg_m"),
    ),
    T("toml-segments-empty", toml("[frame]\nsegments = []\n"), ("frame.segments", "non-empty")),
    T(
        "toml-segments-and-preset",
        toml("[frame]\npreset = 'rigid'\nsegments = [{length_m=1, ei_n_m2=1, rhoa_kg_m=1}]\n"),
        ("frame.segments, frame.preset cannot be combined", "one of"),
    ),
    T(
        "toml-unknown-preset",
        toml("[frame]\npreset = 'wooden'\n"),
        ("frame.preset = 'wooden'", "standard, rigid"),
    ),
    T(
        "toml-zeta-and-clamped-cor",
        toml("[contact]\nzeta = 0.05\nclamped_cor = 0.8\n"),
        ("contact.zeta and contact.clamped_cor cannot be combined",),
    ),
    T(
        "toml-clamped-cor-zero",
        toml("[contact]\nclamped_cor = 0\n"),
        ("contact.clamped_cor = 0", "(0, 1]"),
    ),
    T(
        "toml-ball-mass-zero",
        toml("[ball]\nmass_kg = 0\n"),
        ("ball.mass_kg = 0 kg", "> 0"),
    ),
    T(
        "toml-overwrite-not-bool",
        toml("[output]\noverwrite = 'yes'\n"),
        ("output.overwrite = 'yes'", "true or false"),
    ),
    T(
        "toml-no-separation",
        toml("[solver]\nt_max_s = 1e-4\n"),
        ("solver.t_max_s = 0.0001 s", "raise t_max"),
    ),
    T(
        "toml-command-table-unknown-key",
        toml("[simulate]\njsn = true\n"),
        ("simulate.jsn is not a known key", "did you mean 'json'"),
    ),
    T(
        "toml-command-table-core-key",
        toml("[simulate]\nspeed = 30\n"),
        ("simulate.speed", "set impact.speed_m_s instead"),
    ),
    T(
        "toml-command-table-wrong-type",
        toml("[modes]\ncount = 1.5\n", command="modes"),
        ("modes.count = 1.5", "must be an integer"),
    ),
    T(
        "toml-command-table-bad-value",
        toml("[modes]\ncount = 0\n", command="modes"),
        ("count = 0", ">= 1"),
    ),
    T(
        "toml-segments-with-cli-ei1",
        toml("[frame]\nsegments = [{length_m=0.7, ei_n_m2=150, rhoa_kg_m=0.5}]\n", "--ei1", "9"),
        ("--ei1 cannot be combined with frame.segments",),
    ),
    T(  # before: elements silently ignored (the command line refuses --mesh with --elements)
        "toml-mesh-with-elements",
        toml("[frame]\nmesh = 'racket.vtu'\nelements = 40\n"),
        ("frame.elements = 40 is not allowed with frame.mesh", "remove one of them"),
    ),
    T(
        "toml-missing-mesh",
        toml("[frame]\nmesh = 'meshes/none.vtu'\n"),
        ("frame.mesh = 'meshes/none.vtu'", "no such file", "relative to the run file"),
    ),
    T(
        "toml-sweep-grid",
        toml("[sweep]\nspeed = '1:2'\n", command="sweep"),
        ("sweep.speed = '1:2'", "start:stop:num"),
    ),
    T(
        "toml-sweep-grid-array",
        toml("[sweep]\nposition = [0.5, 1.5]\n", command="sweep"),
        ("sweep.position = 1.5", "[0, 1]"),
    ),
    T(
        "toml-sweep-grid-table",
        toml("[sweep]\nspeed = {min = 20}\n", command="sweep"),
        ("sweep.speed = {'min': 20}", "an array of numbers"),
    ),
    T(
        "toml-sweep-unknown-key",
        toml("[sweep]\nspeeds = [20, 30]\n", command="sweep"),
        ("sweep.speeds is not a known key", "did you mean 'speed'"),
    ),
    T(
        "toml-sweep-core-key",
        toml("[sweep]\nsolver = 'cvode'\n", command="sweep"),
        ("sweep.solver", "set solver.name instead"),
    ),
    T(
        "toml-vtk-frames-one",
        toml("[vtk]\nframes = 1\n", command="export-vtk"),
        ("frames = 1", ">= 2"),
    ),
    T(
        "toml-animate-bad-suffix",
        toml("[animate]\nout = 'a.avi'\n", command="animate"),
        ("out = 'a.avi'", ".gif or .mp4"),
    ),
    T(
        "toml-animate-size-array",
        toml("[animate]\nsize = [960, 400]\n", command="animate"),
        ("animate.size = [960, 400]", "--size"),
    ),
    T(
        "toml-refine-elements-zero",
        toml("[refine]\nelements = [5, 0]\n", command="refine"),
        ("elements = [5, 0]", "from 1 to 50000"),
    ),
    T(
        "toml-refine-elements-not-array",
        toml("[refine]\nelements = 20\n", command="refine"),
        ("refine.elements = 20", "must be an array"),
    ),
    *(
        T(f"toml-lead-{k}", toml(f"[frame]\nlead = {lead}\n", command="modes"), (says,))
        for k, (lead, says) in enumerate(
            [
                ('[{ place = "3/9" }]', "frame.lead[0] is missing mass_g"),
                (
                    '[{ place = "3/9", mass_g = -1 }]',
                    "mass_g = -1.0 is not allowed: must be > 0 g",
                ),
                ('[{ place = "3/9", mass = 1 }]', "did you mean 'mass_g'"),
                ("[]", "frame.lead is not allowed: must be a non-empty array"),
            ]
        )
    ),
    *(  # a mistyped table: the closest name, and the command whose table it is
        Case(
            f"toml-table-{table}",
            ["config", "--check", "run.toml"],
            (f"fem-racket config: error: run.toml: {table} is not a known key: {hint}",),
            {"run.toml": f"[{table}]\nseed = 2\n"},
        )
        for table, hint in [
            ("export-vtk", "did you mean 'vtk'? (the table of fem-racket export-vtk)"),
            ("optimize", "did you mean 'design'? (the table of fem-racket optimize)"),
            ("simulat", "did you mean 'simulate'?"),
        ]
    ),
    T(
        "toml-reproduce-quick-not-bool",
        toml("[reproduce]\nquick = 'yes'\n", command="reproduce"),
        ("reproduce.quick = 'yes'", "true or false"),
    ),
    Case(
        "toml-check-bad-file",
        ["config", "--check", "run.toml"],
        ("impact.speed_m_s = -1", "> 0"),
        {"run.toml": "[impact]\nspeed_m_s = -1\n"},
    ),
]


# -- bad mesh files ------------------------------------------------------------------------------
def _write_line_mesh(path: Path, x: list, cells: list, EI=None, rhoA=None) -> None:
    """A line mesh along x; EI / rhoA per cell (146 N m^2, 0.5 kg/m when None; "-" leaves the
    cell data out)."""
    import meshio

    pts = np.zeros((len(x), 3))
    pts[:, 0] = x
    n = len(cells)
    data = {}
    for name, values, default in (("EI", EI, 146.0), ("rhoA", rhoA, 0.5)):
        if values != "-":
            data[name] = [np.full(n, default) if values is None else np.asarray(values, float)]
    meshio.write(path, meshio.Mesh(pts, [("line", np.array(cells))], cell_data=data))


def _mesh(*args, **kw):
    return lambda path: _write_line_mesh(path, *args, **kw)


def _garbage(path: Path) -> None:
    path.write_bytes(b"not a mesh at all\x00\x01")


#: (id, function writing the bad mesh to the path it is given, words the error must contain).
#: "Unsorted nodes" is a chain of cells whose nodes go back along x: the cells overlap. (Nodes
#: merely numbered out of order, or cells listed in any order, are a valid mesh: read_mesh sorts
#: them; tests/test_mesh_io.py checks that.)
BAD_MESHES = [
    ("mesh-gap", _mesh([0, 0.3, 0.35, 0.68], [[0, 1], [2, 3]]), ("gap between x = 0.3 m",)),
    ("mesh-overlap", _mesh([0, 0.4, 0.3, 0.68], [[0, 1], [2, 3]]), ("overlap between x = 0.4",)),
    (
        "mesh-unsorted-nodes",
        _mesh([0, 0.5, 0.3, 0.68], [[0, 1], [1, 2], [2, 3]]),
        ("overlap", "cells must join end to end"),
    ),
    (
        "mesh-zero-length-cell",
        _mesh([0, 0.3, 0.3, 0.68], [[0, 1], [1, 2], [2, 3]]),
        ("zero-length cell at x = 0.3 m",),
    ),
    ("mesh-missing-EI", _mesh([0, 0.68], [[0, 1]], EI="-"), ("'EI' is missing", "need EI")),
    ("mesh-missing-rhoA", _mesh([0, 0.68], [[0, 1]], rhoA="-"), ("'rhoA' is missing",)),
    (
        "mesh-rhoA-zero",
        _mesh([0, 0.3, 0.68], [[0, 1], [1, 2]], rhoA=[0.7, 0.0]),
        ("rhoA = 0.0 kg/m in cell 1", "> 0"),
    ),
    (
        "mesh-EI-negative",
        _mesh([0, 0.3, 0.68], [[0, 1], [1, 2]], EI=[-146, 128]),
        ("EI = -146.0 N m^2 in cell 0", "> 0"),
    ),
    ("mesh-EI-nan", _mesh([0, 0.68], [[0, 1]], EI=[np.nan]), ("EI = nan", "finite")),
    ("mesh-unreadable", _garbage, ("could not be read",)),
    (  # before: silently mirrored (the grip taken at the smallest x, the tip's end)
        "mesh-negative-x",
        _mesh([-0.68, -0.3, 0], [[0, 1], [1, 2]]),
        ("x runs from -0.68 to 0 m", "must be >= 0", "mirror the file"),
    ),
]

#: How a bad mesh reaches each command: a run file, or --mesh.
MESH_ENTRIES = {
    "run-file": ["simulate", "--config", "run.toml"],
    "simulate": ["simulate", "--mesh", "bad.vtu"],
    "modes": ["modes", "--mesh", "bad.vtu"],
    "sweep": sweep("--mesh", "bad.vtu"),
    "refine": refine("--mesh", "bad.vtu"),
    "export-vtk": vtk("--mesh", "bad.vtu"),
    "animate": anim("--mesh", "bad.vtu"),
    "map": mapc("--mesh", "bad.vtu"),
    "optimize": opt("--mesh", "bad.vtu"),
    "sensitivity": sens("--mesh", "bad.vtu"),
    "customise": ["customise", "--mesh", "bad.vtu", "--mass", "0.4"],
}


LAW_CASES = [
    Case("law-unknown", sim("--law", "rubber"), ("--law", "invalid choice")),
    Case("law-option-of-other-family", sim("--law", "series", "--k1", "3"), ("k1", "series")),
    Case("law-preset-with-option", sim("--law", "itf-ball", "--hc-alpha", "0.1"), ("preset",)),
    Case("law-negative-stiffness", sim("--law", "hysteretic", "--k1", "-1"), ("k1 = -1", "> 0")),
    Case("law-bdf", sim("--law", "hysteretic", "--solver", "bdf"), ("solver = 'bdf'", "general")),
    Case("calibrate-family", ["calibrate", "--family", "rubber"], ("--family", "invalid choice")),
    Case("calibrate-mass", ["calibrate", "--ball-mass", "0"], ("ball_mass = 0", "> 0")),
    Case("calibrate-out-file", ["calibrate", "--out", "afile"], ("afile",), A_FILE),
]

ALL_CASES = (
    CLI_CASES
    + SWEEP_CASES
    + VTK_CASES
    + REFINE_CASES
    + REPRODUCE_CASES
    + OUTPUT_CASES
    + TOML_CASES
    + LAW_CASES
    + MAP_CASES
    + FIT_CASES
    + DESIGN_CASES
    + LEAD_CASES
)
MESH_CASES = {c[0]: c[1] for c in BAD_MESHES}


def test_catalogue_size():
    assert len(ALL_CASES) + len(BAD_MESHES) >= 30
    assert len({c.id for c in ALL_CASES} | set(MESH_CASES)) == len(ALL_CASES) + len(BAD_MESHES)


def test_catalogue_covers_every_command():
    from fem_racket.cli import COMMANDS, build_parser

    parser = build_parser()
    subs = next(a for a in parser._actions if hasattr(a, "choices") and a.choices)
    commands = set(subs.choices)
    assert len(commands) >= len(COMMANDS)
    assert commands <= {c.argv[0] for c in ALL_CASES}
    with_mesh = {n for n, p in subs.choices.items() if any(a.dest == "mesh" for a in p._actions)}
    assert with_mesh <= {argv[0] for argv in MESH_ENTRIES.values()}


def _check_one_error(capsys, tmp_path, case: Case) -> None:
    for name, text in case.files.items():
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
    before = {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*")}
    argv = list(case.argv)
    if argv[0] == "simulate" and "--out" not in argv:
        argv += ["--out", "result.json"]
    line = one_error(capsys, *argv)
    for needle in case.names:
        assert needle in line, f"{needle!r} not in {line!r}"
    after = {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*")}
    assert after == before, "a file was written or changed"


@pytest.mark.parametrize("case", ALL_CASES, ids=[c.id for c in ALL_CASES])
def test_bad_input_gives_one_line_exit_2_and_no_file(capsys, tmp_path, monkeypatch, case):
    monkeypatch.chdir(tmp_path)
    _check_one_error(capsys, tmp_path, case)


@pytest.mark.parametrize("entry", list(MESH_ENTRIES))
@pytest.mark.parametrize(("mesh_id", "write", "names"), BAD_MESHES, ids=list(MESH_CASES))
def test_bad_mesh_gives_one_line_exit_2_and_no_file(
    capsys, tmp_path, monkeypatch, mesh_id, write, names, entry
):
    monkeypatch.chdir(tmp_path)
    write(tmp_path / "bad.vtu")
    files = {"run.toml": "[frame]\nmesh = 'bad.vtu'\n"} if entry == "run-file" else {}
    case = Case(mesh_id, MESH_ENTRIES[entry], ("mesh = 'bad.vtu'", *names), files)
    _check_one_error(capsys, tmp_path, case)
