"""``fem-racket fit``: a racket frame from its catalogue numbers, written as a mesh file.

Fit a three-segment frame (handle 0-0.3 L, throat 0.3-0.6 L, head 0.6-1 L; EI with the paper's
0.88 step) to a racket's specification and write it as a mesh file for --mesh. Example:
fem-racket fit --length 0.685 --mass 0.318 --balance 0.320 --swing-weight 316 --f1 150 --out
racket.vtu

The frame is the three-segment one of :mod:`fem_racket.frame.specs` (mass, balance and swing
weight exact, f1 by scaling EI); every ``--mesh`` option loads the file, and its sidecar
``racket.vtu.json`` holds the targets, the fitted values and the provenance.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from fem_racket.cli.common import (
    add_config_option,
    print_json,
    run_parameters,
    significant,
)
from fem_racket.cli.options.lists import add_options
from fem_racket.cli.options.output import add_overwrite_json, print_written
from fem_racket.cli.options.rerun import replace_own
from fem_racket.frame.constants import FIT_ELEMENTS as DEFAULT_ELEMENTS
from fem_racket.outputs import check_output_path
from fem_racket.validation import (
    InputError,
    check_integer,
    check_positive,
    check_range,
    work_begins,
)

#: Where the mesh goes unless --out is given.
DEFAULT_OUTPUT = Path("output") / "racket.vtu"

#: Highest --f1 [Hz]: rackets ring at about 100-200 Hz free-free (the standard racket 122 Hz,
#: the rigid preset 1011 Hz); far above, EI leaves the range a frame can have (the fit refused
#: it naming EI, not the option given).
MAX_F1_HZ = 3000.0
#: Highest --torsion-frequency [Hz]: the standard profile's is 380 Hz (on a 0.68 m frame).
MAX_TORSION_HZ = 5000.0

#: The racket's specification: (option name, default, metavar, help) of each ``--option``.
SPECIFICATION = (
    ("length", None, "M", "length L [m] (required; no default)"),
    ("mass", None, "KG", "mass [kg] (required; no default)"),
    ("balance", None, "M", "balance point from the butt [m] (required; no default)"),
    ("swing_weight", None, "KG_CM2", "moment of inertia about an axis 0.10 m from the butt "
     "[kg cm^2] (required; no default)"),
    ("f1", None, "HZ", "first free-free bending frequency [Hz] (default: none, EI1 = 146 N m^2 "
     "kept)"),
    ("twist_weight", None, "KG_CM2", "polar moment about the long axis [kg cm^2]: writes cell "
     "data GJ and rhoIp (the standard racket's torsion profile scaled) so the frame takes "
     "off-axis impacts (default: none, no torsion data)"),
    ("torsion_frequency", None, "HZ", "first free-free torsion frequency [Hz], with "
     "--twist-weight (default: the profile's own, 380 Hz on a 0.68 m frame)"),
)  # fmt: skip


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``fit`` command's options."""
    g = p.add_argument_group("specification")
    add_options(g, SPECIFICATION, type=float)
    g.add_argument(
        "--elements",
        type=int,
        default=DEFAULT_ELEMENTS,
        metavar="N",
        help=f"cells of the mesh written, on which f1 is matched (default {DEFAULT_ELEMENTS})",
    )
    o = p.add_argument_group("output")
    o.add_argument(
        "--out",
        default=str(DEFAULT_OUTPUT),
        metavar="FILE",
        help=f"mesh file to write (.vtu recommended; default {DEFAULT_OUTPUT}, replacing "
        "the mesh an earlier run wrote there); the specification and provenance go to FILE.json",
    )
    add_overwrite_json(o)
    add_config_option(
        p, private=("out", "elements"), requires=("length", "mass", "balance", "swing_weight")
    )


def run(args: argparse.Namespace) -> int:
    """Fit, write the mesh and its sidecar, print targets against fitted values."""
    from fem_racket.io.racket_files import FitSpec, fit_files, mesh_files

    elements = check_integer("elements", args.elements, minimum=3)
    for name in ("length", "mass", "balance", "swing_weight"):
        if getattr(args, name) is None:
            flag = "--" + name.replace("_", "-")
            raise InputError(f"{name} is required: give {flag} (or {name} in the run file's [fit])")
    for name, high in (("f1", MAX_F1_HZ), ("torsion_frequency", MAX_TORSION_HZ)):
        if getattr(args, name) is not None:
            check_positive(name, getattr(args, name), "Hz")
            check_range(name, getattr(args, name), 0.0, high, unit="Hz", include_low=False)
    out = Path(args.out)
    files = mesh_files(out)
    overwrite = replace_own(args, out == DEFAULT_OUTPUT, files)
    for f in files:
        check_output_path(f, overwrite=overwrite)
    work_begins()
    spec = FitSpec(**{name: getattr(args, name) for name, *_ in SPECIFICATION}, elements=elements)
    _, summary = fit_files(spec, out, run_parameters(args), overwrite=overwrite)
    target, got, segments = summary["target"], summary["fitted"], summary["segments"]
    if args.json:
        print_json(summary)
        return 0
    print(f"{'':<22} {'target':>12} {'fitted':>12}")
    for key in target:
        want = "-" if target[key] is None else significant(target[key], 6)
        print(f"{key:<22} {want:>12} {significant(got[key], 6):>12}")
    for k, s in enumerate(segments):
        print(
            f"segment {k + 1}: {s['length_m']:.4f} m, EI {significant(s['ei_n_m2'], 5)} N m^2, "
            f"rhoA {significant(s['rhoa_kg_m'], 5)} kg/m"
        )
    print_written(files)
    return 0
