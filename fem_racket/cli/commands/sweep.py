"""``fem-racket sweep``: a grid of impacts -> one netCDF dataset (see :func:`fem_racket.sweep`).

Simulate every combination of the given values. Each parameter takes a number, a comma list
(20,30,40) or start:stop:num with an optional :log (50:3000:60:log); so do the contact law's
parameters (--law hunt-crossley --hc-exponent 1.3:1.7:5). Example: fem-racket sweep --position
0.55:0.95:9 --speed 20,30,40 --ei1 50:3000:60:log --out fig13.nc
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path
from typing import TYPE_CHECKING, Any

from fem_racket.cli.common import (
    add_config_option,
    add_mesh_option,
    add_solver_options,
    note,
    print_json,
    run_parameters,
)
from fem_racket.cli.options.drawing import add_quiet_option, progress_of
from fem_racket.cli.options.fields import fields_from_args
from fem_racket.cli.options.laws import add_law_options
from fem_racket.cli.options.rerun import replace_own
from fem_racket.cli.options.runfile import given_options
from fem_racket.impact.incidence import (
    DEFAULT_BALL_INERTIA,
    DEFAULT_BALL_RADIUS,
    DEFAULT_COMPLIANCE_RATIO,
)
from fem_racket.studies.grid_parameters import PARAMETERS
from fem_racket.validation import InputError, show

if TYPE_CHECKING:
    from fem_racket.frame.mesh import FrameMesh
    from fem_racket.frame.segments import Frame

#: Where the result goes unless --out is given.
DEFAULT_OUTPUT = Path("output") / "sweep.nc"

_HELP = {
    "position": "impact point x/L [-] from the grip end (default 0.75)",
    "offset": "lateral offset [m] of the impact point from the long axis, on the head (default 0)",
    "speed": "incident ball speed [m/s] (default 20)",
    "racket_speed": "racket speed towards the ball at --reference [m/s] (default 0)",
    "reference": "point x/L [-] whose speed --racket-speed gives (default 0.75)",
    "pivot": "pivot of the swing [m from the butt] (default: none, the racket translates)",
    "ei1": "grip-side EI1 [N m^2], EI2 = 0.88 EI1 unless --ei2 (default 146)",
    "ei_factor": "factor on every segment's EI [-] (default 1)",
    "ball_mass": "ball mass [kg] (default 0.057)",
    "zeta": "ball/string damping ratio [-], 0..1 (default 0.0592: clamped COR 0.83)",
    "kcb": "ball/string stiffness K_CB [N/m] (default: from the speed; allowed [100, 1e+07])",
    "elements": "number of beam elements (default 20)",
    "string_tension": "tension per string [N]: a string bed replaces the lumped K_CB "
    "(default: none; with --pattern alone 246)",
    "pattern": "string pattern MAINSxCROSSES [-], e.g. 16x19,18x20 (default: none; with "
    "--string-tension alone 16x19)",
    "angle": "incidence angle [deg] from the face normal: an oblique ball (default: head-on)",
    "spin": "incoming spin [rpm], positive = topspin (default 0 with an oblique ball)",
    "side_angle": "angle [deg] of the ball's path from the plane of the long axis, in (-90, 90), "
    "positive toward +y: a 3-D oblique ball (default 0 with an oblique ball)",
    "side_spin": "incoming side spin [rpm] about the long axis's direction, positive = rolling "
    "toward +y (default 0 with an oblique ball)",
    "friction": "Coulomb friction ball/strings [-] (default 0.4 with an oblique ball)",
    "ball_inertia": f"ball's I/(m R^2) [-], 0..2/3 (default {DEFAULT_BALL_INERTIA:g} with an "
    "oblique ball)",
    "ball_radius": f"ball radius R [m] (default {DEFAULT_BALL_RADIUS:g} with an oblique ball)",
    "compliance_ratio": "normal over tangential contact stiffness eta^2 [-] (default "
    f"{DEFAULT_COMPLIANCE_RATIO:g} with an oblique ball)",
}

#: Plural spellings, as the commands taking one list of these spell them (map, optimize).
_PLURAL = {"position": ("--positions",), "speed": ("--speeds",)}


def _grid_value(where: str, value: Any) -> Any:
    """A run file's sweep value: a number, an array of numbers or a string as on the command
    line (``"50:3000:60:log"``); checked here so ``config --check`` reports it."""
    name = where.rpartition(".")[2]
    if isinstance(value, bool) or not isinstance(value, (int, float, str, list)):
        raise InputError(
            f"{where} = {show(value)} is not allowed: must be a number, an array of numbers or a "
            "string like '0.55:0.95:9'"
        )
    from fem_racket.studies.grid import as_values

    try:
        as_values(name, value)
    except InputError as exc:
        text = str(exc)
        raise InputError(where + text[len(name) :] if text.startswith(name) else text) from None
    return value


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``sweep`` command's options."""
    # the law families' parameters, by the registry's names (as studies.grid.LAW_PARAMETERS)
    from fem_racket.contact.registry import LAW_PARAMETERS as declared

    g = p.add_argument_group("swept or fixed parameters")
    for name, text in _HELP.items():
        flags = ["--" + name.replace("_", "-"), *_PLURAL.get(name, ())]
        g.add_argument(*flags, dest=name, metavar="VALUES", help=text)
    g.add_argument(
        "--ei2",
        type=float,
        metavar="N_M2",
        help="fixed top-side EI2 [N m^2] (default 0.88 EI1)",
    )
    add_mesh_option(g, replaces="replaces --ei1, --ei2 and --elements; scale it with --ei-factor")
    add_law_options(p, swept=True)
    add_solver_options(p, t_max=False)
    r = p.add_argument_group("execution and output")
    r.add_argument(
        "--out",
        type=Path,
        default=DEFAULT_OUTPUT,
        metavar="FILE",
        help=f"output file: the netCDF result, or a CSV table (+ JSON sidecar) for a .csv name "
        f"(default {DEFAULT_OUTPUT}, replacing the sweep an "
        "earlier run wrote there)",
    )
    r.add_argument("--overwrite", action="store_true", help="replace an existing result file")
    r.add_argument(
        "--restart",
        action="store_true",
        help="discard the checkpoint of an interrupted run instead of resuming it",
    )
    where = r.add_mutually_exclusive_group()
    where.add_argument(
        "--serial", action="store_true", help="run in this process only (default: a process pool)"
    )
    where.add_argument(
        "--workers", type=int, metavar="N", help="local worker processes (default: all cores)"
    )
    where.add_argument(
        "--scheduler",
        metavar="tcp://HOST:PORT",
        help="run on a Dask distributed scheduler (workers need fem_racket installed) "
        "(default: none, local processes)",
    )
    r.add_argument(
        "--chunk-size",
        type=int,
        metavar="N",
        help="impacts per task and checkpoint file (default: about a quarter of each worker's "
        "share, at most 32768 for exact and 4 for cvode/bdf; 64 under a contact law)",
    )
    r.add_argument(
        "--peak-force",
        action="store_true",
        help="also compute the largest contact force (variable peak_force_n; slower)",
    )
    add_quiet_option(r)
    r.add_argument("--json", action="store_true", help="print a JSON summary")
    add_config_option(
        p,
        own=[*PARAMETERS, *declared],
        private=("out",),
        convert={name: _grid_value for name in [*PARAMETERS, *declared]},
    )


def _note_modes(args: argparse.Namespace, frame: Frame | FrameMesh | None) -> None:
    """Say so when a chosen --modes exceeds the flexible modes of the coarsest mesh swept."""
    import numpy as np

    from fem_racket.frame.mesh import FrameMesh, frame_mesh
    from fem_racket.frame.model import DEFAULT_MODES
    from fem_racket.frame.segments import standard_frame
    from fem_racket.studies.grid import as_values

    chosen = "modes" in getattr(args, "explicit_options", ()) or args.modes != DEFAULT_MODES
    if args.basis != "modal" or not chosen:
        return
    if isinstance(frame, FrameMesh):
        cells = frame.n_elements
    else:
        counts = as_values("elements", args.elements)
        coarsest = 20 if counts is None else int(np.min(counts))
        cells = frame_mesh(frame or standard_frame(), coarsest).n_elements
    if args.modes > 2 * cells:  # 2 DOFs per node, less the 2 rigid-body modes
        note(
            args,
            f"modes = {args.modes}: the {cells}-element mesh has {2 * cells} flexible modes; "
            f"using all {2 * cells}",
        )


def run(args: argparse.Namespace) -> int:
    """Run the sweep, write the file and print a summary."""
    from fem_racket.cli.common import frame_from_args
    from fem_racket.contact.presets import law_parameters
    from fem_racket.studies.executors import check_scheduler
    from fem_racket.studies.sweep import sweep_result
    from fem_racket.studies.sweep_options import SOLVING_DEFAULTS, SweepRun, SweepSolving

    given = getattr(args, "explicit_options", set())
    if given & {"workers", "scheduler"} and "serial" not in given:
        args.serial = False  # the command line's choice wins over a run file's serial = true
    # No choice made: the library picks (serial for small exact sweeps, else a local pool).
    backend = "serial" if args.serial else ("dask" if args.scheduler else None)
    if args.workers is not None and backend is None:
        backend = "processes"
    if args.scheduler is not None:
        check_scheduler(args.scheduler)  # before the checkpoint folder is made
    values = {name: getattr(args, name) for name in PARAMETERS}
    custom = args.mesh is not None or getattr(args, "segments", None)
    frame = frame_from_args(args, exclusive=("ei1", "ei2")) if custom else None
    start = time.perf_counter()
    running = fields_from_args(
        args,
        SweepRun,
        output=args.out,
        overwrite=replace_own(args, Path(args.out) == DEFAULT_OUTPUT, [args.out]),
        backend=backend,
        progress=progress_of(args),
        parameters=run_parameters(args),
    )
    told = given_options(args)  # the solver's options given, at any value (as simulate's)
    solving = {
        k: v
        for k, v in fields_from_args(args, SweepSolving).items()
        if k not in SOLVING_DEFAULTS or k in told
    }
    if "law" not in told:  # the paper's law by default; named, it is refused with a bed
        solving["law"] = None
    result = sweep_result(frame, **values, **solving, **running, **law_parameters(vars(args)))
    wall = time.perf_counter() - start
    _note_modes(args, frame)
    done = result.summary()
    n = done["impacts"]
    summary = {
        "output": str(args.out),
        "impacts": n,
        "dims": done["dims"],
        "wall_s": wall,
        "impacts_per_s": n / wall if wall > 0 else None,
        **{k: done[k] for k in ("cor_min", "cor_max", "solver", "contact_law", "backend")},
        **{k: done[k] for k in ("ball_law",) if k in done},  # a string bed's ball
    }
    if args.json:
        print_json(summary)
        return 0
    shape = " x ".join(f"{d} {k}" for d, k in summary["dims"].items()) or "one case"
    print(f"wrote {args.out}: {n} impacts ({shape}) in {wall:.2f} s ({n / wall:.0f} impacts/s)")
    print(_cor_range(summary, result.failed))
    return 0


def _cor_range(summary: dict[str, Any], failed: int) -> str:
    """The COR range of the cases that succeeded, and how many failed (NaN) if any."""
    n = summary["impacts"]
    if failed == n:
        return f"COR: every case failed ({failed} of {n})"
    line = f"COR from {summary['cor_min']:.6f} to {summary['cor_max']:.6f}"
    return line + (f" ({failed} of {n} cases failed)" if failed else "")
