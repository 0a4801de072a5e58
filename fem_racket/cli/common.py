"""Options shared by the commands that run an impact, and their translation to library calls."""

from __future__ import annotations

import argparse
import json
import math
import sys
from typing import Any

from ..impact import BASES
from ..integrators import SOLVERS
from ..mesh import FrameMesh, read_mesh
from ..model import DEFAULT_MODES, FrameModel
from ..params import Frame, standard_frame
from ..system import SEPARATION_EVENTS
from ..validation import InputError

__all__ = [
    "add_frame_options",
    "add_impact_options",
    "add_mesh_option",
    "build_model",
    "frame_from_args",
    "impact_kwargs",
    "print_json",
]

#: Frame options that a mesh file replaces (giving one with --mesh is an error).
MESH_EXCLUSIVE = ("ei1", "ei2", "elements")


class _Explicit(argparse._StoreAction):
    """Store the value and remember that the option was given on the command line."""

    def __call__(self, parser, namespace, values, option_string=None):
        super().__call__(parser, namespace, values, option_string)
        namespace.explicit_options = {*getattr(namespace, "explicit_options", ()), self.dest}


def add_mesh_option(group: argparse._ArgumentGroup) -> None:
    """--mesh FILE: a 1-D line mesh with cell data EI [N m^2] and rhoA [kg/m]."""
    group.add_argument(
        "--mesh",
        default=None,
        metavar="FILE",
        help="frame from a mesh file meshio reads (.vtu, ...; line cells along x with cell "
        "data EI [N m^2] and rhoA [kg/m]); replaces --ei1, --ei2 and --elements",
    )


def add_frame_options(parser: argparse.ArgumentParser) -> None:
    """Frame options: --ei1, --ei2, --elements, --mesh."""
    g = parser.add_argument_group("frame")
    g.add_argument(
        "--ei1",
        type=float,
        default=146.0,
        metavar="N_M2",
        action=_Explicit,
        help="grip-side bending rigidity EI1 [N m^2] (default 146, the paper's)",
    )
    g.add_argument(
        "--ei2",
        type=float,
        default=None,
        metavar="N_M2",
        action=_Explicit,
        help="top-side bending rigidity EI2 [N m^2] (default 0.88 * EI1)",
    )
    g.add_argument(
        "--elements",
        type=int,
        default=20,
        metavar="N",
        action=_Explicit,
        help="number of beam elements (default 20, as in the paper)",
    )
    add_mesh_option(g)


def frame_from_args(args: argparse.Namespace) -> Frame | FrameMesh:
    """The mesh read from --mesh, or the paper's stepped frame with --ei1/--ei2.

    --mesh together with an explicit --ei1, --ei2 or --elements is an error: the file fixes the
    cells and their EI and rhoA.
    """
    path = getattr(args, "mesh", None)
    if path is None:
        return standard_frame(args.ei1, args.ei2)
    clash = sorted(set(getattr(args, "explicit_options", ())) & set(MESH_EXCLUSIVE))
    if clash:
        raise InputError(
            f"--{clash[0]} is not allowed with --mesh: the mesh file gives the cells and their "
            "EI and rhoA"
        )
    return read_mesh(path)


def add_impact_options(parser: argparse.ArgumentParser) -> None:
    """Frame options plus the ball, the ball/string law, the impact and the solver."""
    add_frame_options(parser)
    g = parser.add_argument_group("impact")
    g.add_argument(
        "--speed",
        type=float,
        default=20.0,
        metavar="M_S",
        help="incident ball speed V_B0 [m/s] (default 20)",
    )
    g.add_argument(
        "--position",
        type=float,
        default=0.75,
        metavar="X_OVER_L",
        help="impact point x/L from the grip end, 0..1 (default 0.75)",
    )
    g.add_argument(
        "--ball-mass",
        type=float,
        default=0.057,
        metavar="KG",
        help="ball mass m_B [kg] (default 0.057; not stated in the paper)",
    )
    g.add_argument(
        "--kcb",
        type=float,
        default=None,
        metavar="N_M",
        help="ball/string stiffness K_CB [N/m] (default: from the speed)",
    )
    g.add_argument(
        "--zeta",
        type=float,
        default=None,
        help="ball/string damping ratio, 0..1 (default 0.0592, clamped COR 0.83)",
    )
    s = parser.add_argument_group("solver")
    s.add_argument(
        "--solver", default="exact", choices=sorted(SOLVERS), help="integrator (default exact)"
    )
    s.add_argument(
        "--separation",
        default="displacement",
        choices=SEPARATION_EVENTS,
        help="end of contact: spring deflection or force back to zero "
        "(default displacement, the paper's)",
    )
    s.add_argument(
        "--basis",
        default="modal",
        choices=BASES,
        help="frame coordinates for the BDF solvers (default modal)",
    )
    s.add_argument(
        "--modes",
        type=int,
        default=DEFAULT_MODES,
        metavar="N",
        help=f"flexible frame modes kept in the modal basis (default {DEFAULT_MODES})",
    )


def build_model(args: argparse.Namespace) -> FrameModel:
    """Assemble the frame the options describe (a --mesh file as it is)."""
    return FrameModel.build(frame_from_args(args), args.elements)


def impact_kwargs(args: argparse.Namespace) -> dict[str, Any]:
    """Keyword arguments of :func:`fem_racket.simulate` from the parsed options."""
    return {
        "position": args.position,
        "speed": args.speed,
        "ball_mass": args.ball_mass,
        "kcb": args.kcb,
        "zeta": args.zeta,
        "solver": args.solver,
        "separation": args.separation,
        "basis": args.basis,
        "modes": args.modes,
    }


def print_json(data: Any) -> None:
    """Print ``data`` as JSON (NaN and inf become null)."""

    def clean(v: Any) -> Any:
        if isinstance(v, float) and not math.isfinite(v):
            return None
        if isinstance(v, dict):
            return {k: clean(x) for k, x in v.items()}
        if isinstance(v, (list, tuple)):
            return [clean(x) for x in v]
        return v

    json.dump(clean(data), sys.stdout, indent=2)
    sys.stdout.write("\n")
