"""``fem-racket map``: e_A and v_out along the frame, with sweet spots, for one or more rackets.

e_A (the free racket's COR at the closing speed) and the ball's speed after impact
v_out = e_A v_in + (1 + e_A) v_r along the frame, for a ball speed and a swing; sweet spots:
centre of percussion (with --pivot), mode-1 node, max e_A, max v_out, power region; under the
paper's linear law or another (--law). Example: fem-racket map --speed 20 --racket-speed 25
--pivot 0.1 --law kawazoe-1997-nonlinear

Rackets: ``--preset standard rigid`` and/or ``--mesh A.vtu B.vtu`` (each option also repeatable);
the paper's standard racket when neither is given. ``--out`` takes one or more files, the
format from the suffix: .png (curves with the sweet spots marked), .nc (netCDF) and .csv (with a
``.json`` sidecar); ``output/map.png`` by default, where a rerun replaces its own earlier map
(:mod:`fem_racket.cli.options.rerun`). ``--json`` prints the sweet spots and curves and writes
only what ``--out`` names; ``--no-files`` writes nothing.
``--offsets`` maps e_A over the whole face, ``--angle``/``--spin``/``--friction`` the oblique
ball's outgoing spin and angle over it, and with ``--side-angle``/``--side-spin`` (a ball across
the face) its side spin and side angle and the racket's yaw too
(:mod:`fem_racket.cli.options.faces`).
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from fem_racket.cli.common import (
    add_config_option,
    add_elements_option,
    add_speed_option,
    add_swing_options,
    print_written,
    run_parameters,
    significant,
    swing_kwargs,
)
from fem_racket.cli.options.faces import (
    add_face_options,
    check_map_size,
    face_asked,
    map_impact,
    map_rackets,
    print_maps_json,
    run_face,
)
from fem_racket.cli.options.impact import racket_speed_named
from fem_racket.cli.options.laws import add_law_options, law_from_args
from fem_racket.cli.options.lead import add_lead_option, with_lead
from fem_racket.cli.options.rerun import replace_own
from fem_racket.cli.options.runfile import given_options, option_name
from fem_racket.cli.options.runfile_named import where_set
from fem_racket.frame.constants import DEFAULT_MODES
from fem_racket.impact.constants import DEFAULT_TOLERANCE, SEPARATION_EVENTS
from fem_racket.io.config_named import GRIDS, grid_value
from fem_racket.io.constants import PRESETS
from fem_racket.studies.map_defaults import MAP_POSITIONS as DEFAULT_POSITIONS
from fem_racket.studies.map_defaults import MAP_POWER_FRACTION as DEFAULT_POWER_FRACTION
from fem_racket.validation import InputError

#: Where the map goes unless --out is given.
DEFAULT_OUTPUT = Path("output") / "map.png"


class _Extend(argparse.Action):
    """Collect the values of every use of the option (``--mesh A B --mesh C``)."""

    def __call__(self, parser, namespace, values, option_string=None) -> None:  # noqa: D102
        old = getattr(namespace, self.dest, None)
        setattr(namespace, self.dest, (old if isinstance(old, list) else []) + list(values))


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``map`` command's options."""
    r = p.add_argument_group("rackets (several are overlaid)")
    r.add_argument(
        "--preset",
        action=_Extend,
        nargs="+",
        choices=sorted(PRESETS),
        default=None,
        help="the paper's stepped frame: standard (EI1 146 N m^2) or rigid (9999) (default: "
        "standard when no --mesh is given)",
    )
    r.add_argument(
        "--mesh",
        action=_Extend,
        nargs="+",
        default=None,
        metavar="FILE",
        help="mesh file(s) with cell data EI [N m^2] and rhoA [kg/m], e.g. from fem-racket fit "
        "(default: none)",
    )
    add_elements_option(r, "beam elements of a preset (default 20)")
    add_lead_option(r)
    g = p.add_argument_group("impact")
    add_speed_option(g, "incoming ball speed [m/s] (default 20)")
    start, stop, num = DEFAULT_POSITIONS
    g.add_argument(
        "--positions",
        "--position",
        default=f"{start}:{stop}:{num}",
        metavar="VALUES",
        help=f"impact points x/L [-]: start:stop:num or a comma list "
        f"(default {start}:{stop}:{num})",
    )
    g.add_argument(
        "--ball-mass", type=float, default=0.057, metavar="KG", help="m_B [kg] (default 0.057)"
    )
    g.add_argument(
        "--kcb",
        type=float,
        default=None,
        metavar="N_M",
        help="K_CB [N/m] of the linear law (default: from the closing speed; allowed [100, 1e+07])",
    )
    g.add_argument(
        "--zeta",
        type=float,
        default=None,
        metavar="ZETA",
        help="ball/string damping ratio [-] (default 0.0592)",
    )
    g.add_argument(
        "--separation",
        default="displacement",
        choices=SEPARATION_EVENTS,
        help="end of contact: spring deflection or force back to zero (default displacement)",
    )
    g.add_argument(
        "--modes",
        type=int,
        default=DEFAULT_MODES,
        metavar="N",
        help=f"flexible modes kept (default {DEFAULT_MODES})",
    )
    g.add_argument(
        "--tolerance",
        type=float,
        default=DEFAULT_TOLERANCE,
        metavar="COR",
        help="COR error [-] the batched engine may make: modes far above the contact frequency "
        f"become one residual mode (default {DEFAULT_TOLERANCE:g}; 0: every mode)",
    )
    add_face_options(g)
    add_swing_options(p)
    add_law_options(p)
    o = p.add_argument_group("output")
    o.add_argument(
        "--power-fraction",
        type=float,
        metavar="F",
        default=None,
        help="power region: v_out >= F [-] x its maximum, 0 < F <= 1 (default 0.95); with "
        "--offsets the power area, where e_A >= F x its maximum (default 0.9)",
    )
    o.add_argument(
        "--out",
        nargs="+",
        default=None,
        metavar="FILE",
        help=f"file(s) to write: .png, .nc, .csv (default {DEFAULT_OUTPUT}, replacing the map an "
        "earlier run wrote there; none with --json)",
    )
    o.add_argument(
        "--overwrite", action="store_true", help="replace existing output files (default: refuse)"
    )
    o.add_argument("--no-files", action="store_true", help="write no file, print only")
    o.add_argument(
        "--json",
        action="store_true",
        help="print sweet spots and curves as JSON (default: a table)",
    )
    convert = dict.fromkeys(GRIDS, grid_value)  # arrays too: one parser with load_config's
    add_config_option(p, private=("out", "mesh"), convert=convert)


def _rackets(args: argparse.Namespace) -> list[tuple[str, Any]]:
    """(name, frame) of every racket the options name, presets first, each with the lead of
    --add-mass."""
    from fem_racket.frame.segments import standard_frame
    from fem_racket.io.mesh_files import read_mesh

    out: list[tuple[str, Any]] = []
    for name in args.preset or []:
        out.append((name, standard_frame(PRESETS[name])))
    for path in args.mesh or []:
        out.append((Path(path).stem, read_mesh(path)))
    out = out or [("standard", standard_frame())]
    return [(name, with_lead(frame, args, args.elements)) for name, frame in out]


@racket_speed_named  # a swing's closing speed: the library's check, named as the option
def run(args: argparse.Namespace) -> int:
    """Map every racket, write the files and print the sweet spots; a library refusal of a
    value of the run file's ``[map]`` table names its key (``run.toml: map.positions = ...``),
    as a core table's value is named (:func:`fem_racket.io.config_named.named_by_key`)."""
    try:
        return _run(args)
    except InputError as exc:
        named = _named_by_key(exc, args)
        if named is exc:
            raise
        raise named from None


def _named_by_key(exc: InputError, args: argparse.Namespace) -> InputError:
    """``exc`` named by the ``[map]`` key that set the value it refused, or ``exc`` itself."""
    from fem_racket.io.config_named import named_by_table

    keys = {d: k for d, k in getattr(args, "file_options", {}).items() if k.startswith("map.")}
    return named_by_table(exc, keys, vars(args), args.config) if keys else exc


def _run(args: argparse.Namespace) -> int:
    from fem_racket.io.map_files import check_map_outputs, map_targets, write_maps
    from fem_racket.studies.grid import as_values
    from fem_racket.studies.racket_map import racket_map

    if args.no_files and args.out:
        raise InputError("no_files = True is not allowed with --out: give one of them")
    default = not (args.out or args.no_files or args.json)
    outs = [Path(p) for p in (args.out or [])] or ([DEFAULT_OUTPUT] if default else [])
    if not outs and "overwrite" in given_options(args):  # on the command line or in the file
        name = option_name(args, "overwrite") if "overwrite" in args.file_options else "--overwrite"
        raise InputError(
            f"{name} is not allowed without files: --no-files or --json without --out writes none"
        )
    if args.mesh and not args.preset and "elements" in given_options(args):
        raise InputError(
            f"{where_set(args, 'elements')} is not allowed with {where_set(args, 'mesh')}: the "
            "mesh file gives the cells and their EI and rhoA (--elements meshes a --preset)"
        )
    check_map_size(args)
    files = [t.path for t in map_targets(outs)]
    overwrite = replace_own(args, default, files)
    check_map_outputs(outs, overwrite=overwrite)  # also: no path given twice
    positions = as_values("position", args.positions)
    law = law_from_args(args)
    if face_asked(args):  # the whole face: e_A (--offsets) or the spin (--angle ...)
        return run_face(args, outs, positions, law, _rackets(args))
    if args.power_fraction is None:
        args.power_fraction = DEFAULT_POWER_FRACTION
    maps = map_rackets(
        racket_map,
        args,
        _rackets(args),
        positions=positions,
        power_fraction=args.power_fraction,
        law=law,
        **swing_kwargs(args),
        **map_impact(args),
    )
    if outs:  # as one set: all of them or none
        write_maps(maps, outs, overwrite=overwrite, parameters=run_parameters(args))
    if args.json:
        print_maps_json(maps)
        return 0
    for m in maps:
        s = m.spots
        print(f"{m.name}")
        rows = [
            ("centre of percussion", s.cop),
            ("mode-1 node", s.node),
            ("max apparent COR", s.max_apparent_cor),
            ("max ball speed", s.max_ball_speed),
            ("power region start", s.power_region[0]),
            ("power region end", s.power_region[1]),
        ]
        for label, value in rows:
            text = "-" if value != value else significant(value, 4)
            print(f"  {label:<26} {text:>10} x/L")
    print_written(files)
    return 0
