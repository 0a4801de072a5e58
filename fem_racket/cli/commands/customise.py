"""``fem-racket customise``: the least lead tape that brings a racket to catalogue targets.

Find the least added mass (lead tape) at the allowed places that gives the racket the target specs
(each a value or LOW:HIGH), write the customised racket as a mesh file and map it before and
after. Example: fem-racket customise --swing-weight 310 --balance 0.3079 --places 12,handle --out
custom.vtu

The least total mass meeting every target is solved by :mod:`fem_racket.studies.customise`; the
mesh file gets a ``.json`` sidecar, the maps of e_A and v_out before and after go to ``--maps``
(.png, .nc or .csv; beside the mesh unless given, :mod:`fem_racket.io.customise_files`), all
written as one set, and the placement is printed; unreachable targets are refused with the range
the places can reach. At the default ``--out`` (maps beside it) an earlier customise's files are
replaced; anything else only with ``--overwrite``. A swing's closing speed is the library's to
check, at the maps' impact points (:func:`fem_racket.studies.swing_points.check_swing_points`).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from fem_racket.cli.common import (
    add_config_option,
    add_frame_options,
    add_speed_option,
    add_swing_options,
    frame_from_args,
    print_json,
    print_written,
    run_parameters,
    significant,
)
from fem_racket.cli.options.impact import check_swing_options, racket_speed_named
from fem_racket.cli.options.output import add_overwrite_json
from fem_racket.cli.options.rerun import replace_own
from fem_racket.cli.options.targets import (
    add_target_options,
    places_of,
    targets_from_args,
)

#: Where the mesh goes unless --out is given (the maps beside it unless --maps is given).
DEFAULT_OUTPUT = Path("output") / "customised.vtu"


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``customise`` command's options."""
    add_frame_options(p)
    add_target_options(p)
    m = p.add_argument_group("maps before and after")
    add_speed_option(m, "ball speed [m/s] (default 20)")
    add_swing_options(p)
    o = p.add_argument_group("output")
    o.add_argument(
        "--out",
        default=str(DEFAULT_OUTPUT),
        metavar="FILE",
        help=f"customised racket's mesh file (default {DEFAULT_OUTPUT}, replacing an earlier "
        "customise's files there); summary in FILE.json",
    )
    o.add_argument(
        "--maps",
        default=None,
        metavar="FILE",
        help="maps before and after: .png, .nc or .csv (default beside --out: its name less "
        "the suffix, then _map.png)",
    )
    add_overwrite_json(o)
    add_config_option(p, private=("out",), requires=("a target: swing_weight, balance, mass",))


@racket_speed_named  # a swing's closing speed: the library's check, named as the option
def run(args: argparse.Namespace) -> int:
    """Solve, write the mesh, its sidecar and the maps, print the placement."""
    from fem_racket.frame.catalogue import catalogue
    from fem_racket.frame.mesh import FrameMesh, frame_mesh
    from fem_racket.io.customise_files import customise_files, customise_targets
    from fem_racket.outputs import check_targets
    from fem_racket.studies.map_options import MapPlay
    from fem_racket.studies.swing_points import check_swing_points
    from fem_racket.validation import work_begins

    places = places_of(args)
    files = customise_targets(args.out, args.maps)
    default = Path(args.out) == DEFAULT_OUTPUT and args.maps is None
    overwrite = replace_own(args, default, [t.path for t in files])
    check_targets(files, overwrite=overwrite)
    frame = frame_from_args(args)
    mesh = frame if isinstance(frame, FrameMesh) else frame_mesh(frame, args.elements)
    targets = targets_from_args(args, catalogue(mesh, f1=False))
    # the swing's checks before work (config --check); its closing speed at the maps' points
    check_swing_options(args, pivot_at_rest=True, at_reference=False)
    play = {k: getattr(args, k) for k in ("speed", "racket_speed", "reference", "pivot")}
    check_swing_points(mesh, MapPlay(**play))
    work_begins()
    parameters = run_parameters(args)
    _, summary = customise_files(mesh, targets, places, play, files, parameters, overwrite)
    if args.json:
        print_json(summary)
        return 0
    print(f"{'added mass':<24} {significant(summary['added_mass_g'], 5):>10} g")
    for place, grams in summary["placement_g"].items():
        print(f"  at {place:<20} {significant(grams, 5):>10} g")
    print(f"{'':<24} {'before':>12} {'after':>12}")
    for key, value in summary["before"].items():
        after = summary["after"][key]
        text = [("-" if v is None else significant(v, 6)) for v in (value, after)]
        print(f"{key:<24} {text[0]:>12} {text[1]:>12}")
    for name in ("before", "customised"):
        spots = summary["maps"][name]
        best = significant(spots["max_apparent_cor_x_over_l"], 4)
        print(f"{'max e_A ' + name:<24} {best:>12} x/L")
    print_written([t.path for t in files])
    return 0
