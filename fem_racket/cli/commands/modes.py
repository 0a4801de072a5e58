"""``fem-racket modes``: free-free mass properties, natural frequencies and vibration nodes."""

from __future__ import annotations

import argparse

from fem_racket.cli.common import (
    add_config_option,
    add_frame_options,
    build_model,
    note,
    print_json,
)
from fem_racket.cli.options.drawing import add_quiet_option, progress_of
from fem_racket.progress import progress_bar


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``modes`` command's options."""
    add_frame_options(p)
    p.add_argument(
        "--count",
        type=int,
        default=4,
        metavar="N",
        help="number of flexible modes to report (default 4; a mesh of n elements has 2n)",
    )
    p.add_argument("--json", action="store_true", help="print a JSON object")
    add_quiet_option(p)
    add_config_option(p)


def run(args: argparse.Namespace) -> int:
    """Compute and print the modal analysis."""
    from fem_racket.frame.catalogue import catalogue
    from fem_racket.frame.modal import mode_nodes
    from fem_racket.io.config_modes import RacketModes
    from fem_racket.validation import InputError, work_begins

    if args.count < 1:
        raise InputError(f"count = {args.count} is not allowed: must be an integer >= 1")
    model = build_model(args)
    work_begins()
    fm = model.modes(args.count)
    if fm.omega.size < args.count:
        n, shown = model.mesh.n_elements, fm.omega.size
        note(
            args,
            f"count = {args.count}: the {n}-element mesh has {shown} flexible modes; "
            f"showing {shown}",
        )
    props = fm.props
    modes = progress_bar(range(fm.omega.size), desc="nodes", unit="mode", enabled=progress_of(args))
    nodes = tuple(mode_nodes(model.fe, fm.shapes[:, k]) for k in modes)
    # the frame in torsion (fem_racket.frame.torsion) where the mesh has its data
    torsion = model.torsion.modes(args.count) if model.mesh.has_torsion else None
    specs = catalogue(model.mesh, f1=False)
    data = RacketModes(fm, torsion, nodes, specs, model.mesh.n_elements).summary()
    if args.json:
        print_json(data)
        return 0
    print(f"{'mass':<28} {props.mass:>12.4f} kg")
    print(f"{'centre of gravity':<28} {props.cg_over_length:>12.4f} x/L ({props.cg * 1e3:.1f} mm)")
    print(f"{'inertia about CG':<28} {props.inertia:>12.6f} kg m^2")
    print(f"{'mode':>4} {'frequency [Hz]':>16}  nodes [x/L]")
    for k, (f, nd) in enumerate(zip(fm.frequencies, data["nodes_x_over_l"], strict=True), start=1):
        print(f"{k:>4} {f:>16.2f}  " + ", ".join(f"{x:.3f}" for x in nd))
    if model.mesh.has_torsion:
        ip = data["polar_moment_kg_m2"]
        print(f"{'polar moment (twistweight)':<28} {ip:>12.6f} kg m^2 ({ip * 1e4:.2f} kg cm^2)")
        print(f"{'torsion':>7} {'frequency [Hz]':>13}")
        for k, f in enumerate(data["torsion_frequencies_hz"], start=1):
            print(f"{k:>7} {f:>13.2f}")
    return 0
