"""``fem-racket export-vtk`` and ``fem-racket animate``: the impact for ParaView, GIF or MP4."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from fem_racket.cli.common import (
    add_config_option,
    add_impact_options,
    add_output_step_option,
    build_model,
    check_output_step,
    impact_kwargs,
    note_modes,
    run_parameters,
)
from fem_racket.cli.options.drawing import add_quiet_option, progress_of
from fem_racket.cli.options.output import print_written, print_written_folder
from fem_racket.cli.options.rerun import replace_own
from fem_racket.cli.options.runfile import given_options, option_name
from fem_racket.cli.options.strings import add_strings_options, strings_from_args, strung_from_args
from fem_racket.extras import check_installed
from fem_racket.validation import InputError

#: Where export-vtk and animate write unless --out is given.
DEFAULT_FOLDER = Path("output") / "impact_vtk"
DEFAULT_ANIMATION = Path("output") / "impact.gif"


def _size(text: str) -> tuple[int, int]:
    try:
        w, h = text.lower().split("x")
        return int(w), int(h)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"size = {text!r}: must be WIDTHxHEIGHT, e.g. 960x400"
        ) from None


def _add_common(
    p: argparse.ArgumentParser, out: dict[str, Any], *, scale: float, frames: int | None
) -> None:
    """What export-vtk and animate both take, in this order: ``--out`` (``out``: its default,
    metavar and help), the impact, the drawing (``scale`` and ``frames`` their defaults),
    ``--overwrite``, ``--quiet`` and the string bed."""
    p.add_argument("--out", type=Path, **out)
    add_impact_options(p)
    g = p.add_argument_group("drawing")
    g.add_argument(
        "--subdivide",
        type=int,
        default=8,
        metavar="N",
        help="straight segments per element along the Hermite shape (default 8)",
    )
    g.add_argument(
        "--frames",
        type=int,
        default=frames,
        metavar="N",
        help="output times kept, evenly spread, first and last included (default "
        + ("every output time" if frames is None else str(frames))
        + ")",
    )
    add_output_step_option(g)
    g.add_argument(
        "--scale",
        type=float,
        default=scale,
        help=f"deflection exaggeration of the geometry [-], in (0, 1e6] (default {scale:g})",
    )
    g.add_argument(
        "--field",
        default="deflection",
        metavar="NAME",
        help="frame colouring: deflection, slope, velocity, curvature or moment "
        "(default deflection)",
    )
    p.add_argument(
        "--overwrite", action="store_true", help="replace an existing output file or folder"
    )
    add_quiet_option(p)
    add_strings_options(p)


def add_export_arguments(p: argparse.ArgumentParser) -> None:
    """The ``export-vtk`` command's options."""
    out = {
        "default": DEFAULT_FOLDER,
        "metavar": "DIR",
        "help": f"output folder (default {DEFAULT_FOLDER}, replacing the series an earlier run "
        "wrote there); open DIR/impact.pvd in ParaView",
    }
    _add_common(p, out, scale=1.0, frames=None)
    add_config_option(p, private=("out",))  # a folder, not output.out


def add_animate_arguments(a: argparse.ArgumentParser) -> None:
    """The ``animate`` command's options."""
    out = {
        "default": DEFAULT_ANIMATION,
        "metavar": "FILE",
        "help": f"output file, .gif or .mp4 (default {DEFAULT_ANIMATION}, replacing the "
        "animation an earlier run wrote there)",
    }
    _add_common(a, out, scale=10.0, frames=100)
    a.add_argument(
        "--fps",
        type=float,
        default=25.0,
        help="frames per second [1/s], in [0.01, 100] (default 25)",
    )
    a.add_argument(
        "--size",
        type=_size,
        default="960x400",
        metavar="WxH",
        help="image size in pixels, multiples of 16 (default 960x400)",
    )
    add_config_option(a, private=("out",))  # a .gif or .mp4, not output.out


def _simulate(args: argparse.Namespace):
    from fem_racket.impact.simulate import simulate

    check_output_step(args.output_step)
    model = build_model(args)
    result = simulate(model, output_step=args.output_step, **impact_kwargs(args))
    note_modes(args, model)
    return result


def _check_early(args: argparse.Namespace) -> bool:
    """Reject bad drawing options and destinations before the simulation runs; the overwrite
    the writer takes (:func:`fem_racket.cli.options.rerun.replace_own`)."""
    from fem_racket.io.vtk import PROVENANCE_NAME
    from fem_racket.io.vtk_series import check_scale, field_name
    from fem_racket.outputs import check_output_folder, check_targets

    # before the simulation, without importing them: the writers do (config --check runs this)
    check_installed("pyvista", f"fem-racket {args.command}")
    if args.command == "animate":
        check_installed("imageio", "fem-racket animate")
    field_name(args.field)
    check_scale(args.scale)
    if args.frames is not None and args.frames < 2:
        raise InputError(f"frames = {args.frames} is not allowed: must be an integer >= 2")
    if args.subdivide < 1:
        raise InputError(f"subdivide = {args.subdivide} is not allowed: must be an integer >= 1")
    if args.command == "export-vtk":
        overwrite = replace_own(args, Path(args.out) == DEFAULT_FOLDER, [args.out])
        check_output_folder(args.out, overwrite=overwrite, marker=PROVENANCE_NAME)
        return overwrite
    from fem_racket.io.animate import animation_targets, check_fps, check_size

    targets = animation_targets(args.out)
    check_fps(args.fps)
    check_size(args.size)
    default = Path(args.out) == DEFAULT_ANIMATION
    overwrite = replace_own(args, default, [t.path for t in targets])
    check_targets(targets, overwrite=overwrite)
    return overwrite


def run_export(args: argparse.Namespace) -> int:
    """Simulate and write the VTK time series."""
    from fem_racket.io.vtk import write_vtk_series

    overwrite = _check_early(args)
    strings = strings_from_args(args)
    if strings is not None:
        return _export_strung(args, strings, overwrite)
    result = _simulate(args)
    pvd = write_vtk_series(
        result,
        args.out,
        subdivide=args.subdivide,
        frames=args.frames,
        scale=args.scale,
        field=args.field,
        overwrite=overwrite,
        parameters=run_parameters(args),
        progress=progress_of(args),
    )
    print_written_folder(pvd.parent, f"open {pvd.name} in ParaView")
    return 0


def _export_strung(args: argparse.Namespace, strings, overwrite: bool) -> int:
    """The strung racket's series: frame, ball and the bed's surface (part ``strings``); 101
    steps unless --frames says (its histories have 801 output times)."""
    from fem_racket.io.config_drawings import STRUNG_FRAMES
    from fem_racket.io.strung_vtk import write_strung_vtk

    for dest in ("subdivide", "field"):  # on the command line or in the run file
        if dest in given_options(args):
            name = (
                f"--{dest}"
                if dest in getattr(args, "explicit_options", ())
                else option_name(args, dest)
            )
            raise InputError(
                f"{name} is not allowed with a string bed: the strung series draws the "
                "deflection at the frame's nodes and the bed's vertices"
            )
    model = build_model(args)
    result = strung_from_args(args, strings, model)
    pvd = write_strung_vtk(
        result,
        model,
        args.out,
        frames=STRUNG_FRAMES if args.frames is None else args.frames,
        scale=args.scale,
        overwrite=overwrite,
        parameters=run_parameters(args),
    )
    print_written_folder(pvd.parent, f"open {pvd.name} in ParaView")
    return 0


def run_animate(args: argparse.Namespace) -> int:
    """Simulate and render the animation (with a string bed: the bed beside the frame)."""
    from fem_racket.io.animate import AnimationOptions, animation_targets, render_animation

    overwrite = _check_early(args)
    options = AnimationOptions.of(vars(args))
    strings = strings_from_args(args)
    model = None
    if strings is None:
        result = _simulate(args)
    else:
        model = build_model(args)
        result = strung_from_args(args, strings, model)
    path = render_animation(
        result,
        args.out,
        options,
        model=model,
        overwrite=overwrite,
        parameters=run_parameters(args),
        progress=progress_of(args),
    )
    print_written(t.path for t in animation_targets(path))
    return 0
