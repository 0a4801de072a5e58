"""``fem-racket customise``: the least lead tape that brings a racket to catalogue targets.

Find the least added mass (lead tape) at the allowed places that gives the racket the target specs
(each a value or LOW:HIGH), write the customised racket as a mesh file and map it before and
after. Example: fem-racket customise --swing-weight 310 --balance 0.3079 --places 12,handle --out
custom.vtu

The least total mass meeting every target is solved by :mod:`fem_racket.studies.customise`; the
mesh file gets a ``.json`` sidecar, the maps of e_A and v_out before and after go to ``--maps``
(.png, .nc or .csv) and the placement is printed; unreachable targets are refused with the range
the places can reach.
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
    swing_kwargs,
)
from fem_racket.cli.options.output import add_overwrite_json
from fem_racket.cli.options.targets import (
    add_target_options,
    places_of,
    targets_from_args,
)
from fem_racket.io.constants import CUSTOMISE_MAPS

#: Where the mesh and the maps go unless --out / --maps are given.
DEFAULT_OUTPUT = Path("output") / "customised.vtu"
DEFAULT_MAPS = Path(CUSTOMISE_MAPS)


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
        help=f"customised racket's mesh file (default {DEFAULT_OUTPUT}); summary in FILE.json",
    )
    o.add_argument(
        "--maps",
        default=str(DEFAULT_MAPS),
        metavar="FILE",
        help=f"maps before and after: .png, .nc or .csv (default {DEFAULT_MAPS})",
    )
    add_overwrite_json(o)
    add_config_option(p, private=("out",), requires=("a target: swing_weight, balance, mass",))


def run(args: argparse.Namespace) -> int:
    """Solve, write the mesh, its sidecar and the maps, print the placement."""
    from fem_racket.frame.catalogue import catalogue
    from fem_racket.frame.mesh import FrameMesh, frame_mesh
    from fem_racket.io.map_files import check_map_outputs, map_targets
    from fem_racket.io.racket_files import customise_files, mesh_files
    from fem_racket.outputs import check_output_path
    from fem_racket.validation import work_begins

    places = places_of(args)
    out, maps_path = Path(args.out), Path(args.maps)
    files = mesh_files(out)
    for f in files:
        check_output_path(f, overwrite=args.overwrite)
    check_map_outputs([maps_path], overwrite=args.overwrite)
    map_files = [t.path for t in map_targets([maps_path])]
    frame = frame_from_args(args)
    mesh = frame if isinstance(frame, FrameMesh) else frame_mesh(frame, args.elements)
    targets = targets_from_args(args, catalogue(mesh, f1=False))
    play = {"speed": args.speed, **swing_kwargs(args)}  # its checks before work (config --check)
    work_begins()
    files_out, parameters = (out, maps_path), run_parameters(args)
    _, summary = customise_files(mesh, targets, places, play, files_out, parameters, args.overwrite)
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
    print_written([*files, *map_files])
    return 0
