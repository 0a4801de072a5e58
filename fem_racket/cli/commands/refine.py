"""``fem-racket refine``: mesh-refinement study against the exact beam frequencies."""

from __future__ import annotations

import argparse
from pathlib import Path

from fem_racket.cli.common import (
    add_config_option,
    add_ei_options,
    add_mesh_option,
    frame_from_args,
    number_list,
    print_json,
    print_written,
    run_parameters,
)
from fem_racket.cli.options.drawing import add_figure_options, add_quiet_option, progress_of
from fem_racket.cli.options.fields import fields_from_args
from fem_racket.cli.options.impact import add_ball_options, add_separation_option, add_speed_option
from fem_racket.cli.options.output import overwrite_of
from fem_racket.cli.options.rerun import replace_own
from fem_racket.cli.options.runfile import given_options
from fem_racket.frame.constants import DEFAULT_MODES
from fem_racket.studies.refine_options import (
    DEFAULT_ELEMENTS,
    DEFAULT_GRADING,
    DEFAULT_POSITIONS,
    FAMILIES,
    graded,
)
from fem_racket.validation import InputError, show, work_begins

FAMILY_CHOICES = (*FAMILIES, "both")

#: Where the table goes unless --csv is given (the plot beside it).
DEFAULT_CSV = "output/refine.csv"


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``refine`` command's options."""
    g = p.add_argument_group("frame")
    add_ei_options(g)
    add_mesh_option(
        g,
        replaces="replaces --ei1 and --ei2; its piecewise-uniform EI and rhoA profile is "
        "re-meshed with each of --elements",
    )
    r = p.add_argument_group("refinement")
    r.add_argument(
        "--elements",
        **number_list(int),
        default=list(DEFAULT_ELEMENTS),
        metavar="N",
        help="element counts of the meshes compared, space- or comma-separated (default "
        + ",".join(map(str, DEFAULT_ELEMENTS))
        + ")",
    )
    r.add_argument(
        "--family",
        default="both",
        choices=FAMILY_CHOICES,
        help="uniform cells per segment, cells graded towards steps and ends, or both "
        "(default both)",
    )
    r.add_argument(
        "--grading",
        type=float,
        default=DEFAULT_GRADING,
        help=f"largest / smallest cell of a graded segment [-], >= 1 (default {DEFAULT_GRADING:g})",
    )
    r.add_argument(
        "--count",
        type=int,
        default=4,
        metavar="N",
        help="flexible frequencies compared (default 4)",
    )
    i = p.add_argument_group("impact")
    i.add_argument(
        "--positions",
        "--position",
        dest="positions",
        **number_list(float),
        default=list(DEFAULT_POSITIONS),
        metavar="X_OVER_L",
        help="impact points x/L [-] from the grip end, space- or comma-separated (default "
        + ",".join(map(str, DEFAULT_POSITIONS))
        + ")",
    )
    add_speed_option(i)
    add_ball_options(i, ball_mass=None)  # None: the study's own default
    add_separation_option(i)
    i.add_argument(
        "--impact-modes",
        type=int,
        default=DEFAULT_MODES,
        metavar="N",
        help=f"flexible modes in the impact's modal basis (default {DEFAULT_MODES})",
    )
    i.add_argument(
        "--impact-nodes", action="store_true", help="put a mesh node at every impact point"
    )
    o = p.add_argument_group("output")
    o.add_argument(
        "--csv",
        default=DEFAULT_CSV,
        metavar="FILE",
        help="output file: CSV table, provenance in FILE.json beside it (default %(default)s, "
        "replacing the table an earlier run wrote there; none with --json)",
    )
    o.add_argument(
        "--plot",
        default=None,
        metavar="FILE",
        help="output file: log-log convergence plot, .png, .svg or .pdf (default "
        "output/refine.png, or the --format suffix)",
    )
    add_figure_options(o, "plot")
    add_quiet_option(o)
    o.add_argument("--no-files", action="store_true", help="write neither the CSV nor the plot")
    o.add_argument("--overwrite", action="store_true", help="replace existing output files")
    o.add_argument(
        "--json", action="store_true", help="print a JSON object (writes only --csv, --plot)"
    )
    add_config_option(p, private=("elements",))


def _plot_path(args: argparse.Namespace) -> Path:
    """--plot, or output/refine.<--format>; a --plot whose suffix contradicts --format is an
    error."""
    from fem_racket.io.figure_files import figure_format

    if args.plot is None:
        return Path(f"output/refine.{args.format or 'png'}")
    path = Path(args.plot)
    fmt = figure_format(path)
    if args.format is not None and fmt != args.format:
        raise InputError(
            f"format = {args.format!r} is not allowed with --plot '{path}': give one of them, "
            "or a --plot ending in ." + args.format
        )
    return path


def _refuse_unwritten(args: argparse.Namespace, writes: bool) -> None:
    """Refuse --csv or --plot with --no-files, and --format, --dpi or --overwrite when nothing
    is written (--no-files, or --json without --csv or --plot): they would be ignored."""
    given = given_options(args)
    if args.no_files:
        for dest in ("csv", "plot"):
            if dest in given:
                raise InputError(f"no_files = True is not allowed with --{dest}: give one of them")
    if not writes:
        why = "--no-files" if args.no_files else "--json without --csv or --plot"
        for dest in ("format", "dpi"):
            if dest in given:
                raise InputError(
                    f"{dest} = {show(getattr(args, dest))} is not allowed with {why}: "
                    "no plot is drawn"
                )
        overwrite_of(args, False, "a file to write (--csv, --plot)")


def run(args: argparse.Namespace) -> int:
    """Run the study, print the table (or JSON), write the CSV and the plot."""
    from fem_racket.io.figure_files import check_dpi
    from fem_racket.io.refine_files import format_study, refine_targets, write_outputs
    from fem_racket.outputs import check_targets
    from fem_racket.studies.refine import refinement_study
    from fem_racket.studies.refine_options import RefineOptions

    if args.count < 1:
        raise InputError(f"count = {args.count} is not allowed: must be an integer >= 1")
    most = 2 * max([n for n in args.elements if isinstance(n, int)] or [1])
    if args.count > most:  # the finest mesh's flexible modes
        raise InputError(
            f"count = {args.count} is not allowed: must be an integer from 1 to {most} (the "
            f"flexible modes of the finest mesh, {most // 2} elements)"
        )
    if not args.grading >= 1.0 or args.grading == float("inf"):  # also NaN
        raise InputError(
            f"grading = {show(args.grading)} is not allowed: must be a finite number >= 1"
        )
    frame = frame_from_args(args, exclusive=("ei1", "ei2"))
    plot = _plot_path(args)
    check_dpi(args.dpi)
    default = args.csv == DEFAULT_CSV and args.plot is None
    outputs = [] if args.no_files or (args.json and default) else [Path(args.csv), plot]
    _refuse_unwritten(args, bool(outputs))
    overwrite = replace_own(args, default, [t.path for t in refine_targets(args.csv, plot)])
    if outputs:  # fail before the work, not after it
        check_targets(refine_targets(args.csv, plot), overwrite=overwrite)
    families = FAMILIES if args.family == "both" else (args.family,)
    options = fields_from_args(args, RefineOptions, n_modes=args.count, progress=progress_of(args))
    if "grading" not in given_options(args):  # refused with --family uniform when given
        del options["grading"]
    work_begins()
    studies = {  # the uniform family has no grading (refused by refinement_study)
        fam: refinement_study(frame, args.elements, **graded(options, fam, args.family))
        for fam in families
    }
    if outputs:
        write_outputs(
            studies,
            *outputs,
            overwrite=overwrite,
            parameters=run_parameters(args),
            dpi=args.dpi,
        )
    first, *rest = studies.values()
    if args.json:
        data = first.to_dict()
        for s in rest:
            data[s.family] = s.to_dict()
        data["files"] = [str(p) for p in outputs]
        print_json(data)
        return 0
    print("\n\n".join(format_study(s) for s in studies.values()))
    print_written([t.path for t in refine_targets(args.csv, plot)] if outputs else [])
    return 0
