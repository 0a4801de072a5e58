"""``fem-racket export-vtk`` and ``fem-racket animate``: the impact for ParaView, GIF or MP4."""

from __future__ import annotations

import argparse
from pathlib import Path

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
from fem_racket.impact.simulate import simulate
from fem_racket.validation import InputError


def _size(text: str) -> tuple[int, int]:
    try:
        w, h = text.lower().split("x")
        return int(w), int(h)
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"size = {text!r}: must be WIDTHxHEIGHT, e.g. 960x400"
        ) from None


def _add_common(p: argparse.ArgumentParser, *, scale: float, frames: int | None) -> None:
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


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``export-vtk`` and ``animate`` commands."""
    p = sub.add_parser(
        "export-vtk",
        help="write the impact as a VTK time series (.pvd + .vtu) for ParaView",
    )
    p.add_argument(
        "--out",
        type=Path,
        default=Path("output/impact_vtk"),
        metavar="DIR",
        help="output folder (default output/impact_vtk); open DIR/impact.pvd in ParaView",
    )
    _add_common(p, scale=1.0, frames=None)
    add_config_option(p, private=("out",))  # a folder, not output.out
    p.set_defaults(func=run_export)

    a = sub.add_parser("animate", help="render the impact offscreen as a GIF or MP4")
    a.add_argument(
        "--out",
        type=Path,
        default=Path("output/impact.gif"),
        metavar="FILE",
        help="output file, .gif or .mp4 (default output/impact.gif)",
    )
    _add_common(a, scale=10.0, frames=100)
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
    a.set_defaults(func=run_animate)


def _simulate(args: argparse.Namespace):
    check_output_step(args.output_step)
    model = build_model(args)
    result = simulate(model, output_step=args.output_step, **impact_kwargs(args))
    note_modes(args, model)
    return result


def _check_early(args: argparse.Namespace) -> None:
    """Reject bad drawing options before the simulation runs."""
    from fem_racket.io.vtk import PROVENANCE_NAME
    from fem_racket.io.vtk_series import check_scale, field_name
    from fem_racket.outputs import check_output_folder, check_targets

    field_name(args.field)
    check_scale(args.scale)
    if args.frames is not None and args.frames < 2:
        raise InputError(f"frames = {args.frames} is not allowed: must be an integer >= 2")
    if args.subdivide < 1:
        raise InputError(f"subdivide = {args.subdivide} is not allowed: must be an integer >= 1")
    if args.command == "export-vtk":
        check_output_folder(args.out, overwrite=args.overwrite, marker=PROVENANCE_NAME)
        return
    from fem_racket.io.animate import animation_targets, check_fps, check_size

    targets = animation_targets(args.out)
    check_fps(args.fps)
    check_size(args.size)
    check_targets(targets, overwrite=args.overwrite)


def run_export(args: argparse.Namespace) -> int:
    """Simulate and write the VTK time series."""
    from fem_racket.io.vtk import write_vtk_series

    _check_early(args)
    result = _simulate(args)
    pvd = write_vtk_series(
        result,
        args.out,
        subdivide=args.subdivide,
        frames=args.frames,
        scale=args.scale,
        field=args.field,
        overwrite=args.overwrite,
        parameters=run_parameters(args),
        progress=progress_of(args),
    )
    print(pvd)
    return 0


def run_animate(args: argparse.Namespace) -> int:
    """Simulate and render the animation."""
    from fem_racket.io.animate import render_animation

    _check_early(args)
    result = _simulate(args)
    path = render_animation(
        result,
        args.out,
        field=args.field,
        frames=args.frames,
        fps=args.fps,
        scale=args.scale,
        subdivide=args.subdivide,
        size=args.size,
        overwrite=args.overwrite,
        parameters=run_parameters(args),
        progress=progress_of(args),
    )
    print(path)
    return 0
