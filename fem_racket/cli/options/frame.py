"""The frame on the command line: --ei1, --ei2, --elements and --mesh, and the model they give."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from fem_racket.cli.options.lead import add_lead_option, with_lead
from fem_racket.cli.options.once import Once
from fem_racket.frame.constants import PAPER_EI1
from fem_racket.io.config_defaults import FRAME_ELEMENTS
from fem_racket.validation import InputError

if TYPE_CHECKING:
    from fem_racket.frame.mesh import FrameMesh
    from fem_racket.frame.model import FrameModel
    from fem_racket.frame.segments import Frame

__all__ = [
    "MESH_EXCLUSIVE",
    "add_ei_options",
    "add_elements_option",
    "add_frame_options",
    "add_mesh_option",
    "build_model",
    "frame_from_args",
]

#: Frame options that a mesh file replaces (giving one with --mesh is an error).
MESH_EXCLUSIVE = ("ei1", "ei2", "elements")


def add_mesh_option(
    group: argparse._ArgumentGroup, replaces: str = "replaces --ei1, --ei2 and --elements"
) -> None:
    """--mesh FILE: a 1-D line mesh with cell data EI [N m^2] and rhoA [kg/m]; ``replaces``
    says which of the command's options the file takes the place of."""
    group.add_argument(
        "--mesh",
        action=Once,
        default=None,
        metavar="FILE",
        help="frame from a mesh file meshio reads (.vtu, ...; line cells along x with cell "
        f"data EI [N m^2] and rhoA [kg/m]); {replaces} (default: the paper's stepped frame)",
    )


def add_ei_options(group: argparse._ArgumentGroup) -> None:
    """--ei1 and --ei2 of the paper's stepped frame (EI2 = 0.88 EI1 unless given)."""
    group.add_argument(
        "--ei1",
        type=float,
        default=PAPER_EI1,
        metavar="N_M2",
        help=f"grip-side bending rigidity EI1 [N m^2] (default {PAPER_EI1:g}, the paper's)",
    )
    group.add_argument(
        "--ei2",
        type=float,
        default=None,
        metavar="N_M2",
        help="top-side bending rigidity EI2 [N m^2] (default 0.88 * EI1)",
    )


def add_elements_option(
    group: argparse._ArgumentGroup,
    text: str = "number of beam elements (default 20, as in the paper)",
) -> None:
    """--elements N: the cells a frame of segments is meshed with, 20 by default (the paper's);
    ``text`` its help."""
    group.add_argument("--elements", type=int, default=FRAME_ELEMENTS, metavar="N", help=text)


def add_frame_options(parser: argparse.ArgumentParser) -> None:
    """Frame options: --ei1, --ei2, --elements, --mesh, --add-mass."""
    g = parser.add_argument_group("frame")
    add_ei_options(g)
    add_elements_option(g)
    add_mesh_option(g)
    add_lead_option(g)


def frame_from_args(
    args: argparse.Namespace, exclusive: tuple[str, ...] = MESH_EXCLUSIVE
) -> Frame | FrameMesh:
    """The frame the options describe.

    A mesh file (``--mesh`` or a run file's ``frame.mesh``) wins over segments (a run file's
    ``[[frame.segments]]``), which win over the paper's stepped frame with --ei1/--ei2.
    --mesh together with an explicit --ei1, --ei2 or --elements is an error: the file fixes the
    cells and their EI and rhoA. ``exclusive`` names the options a mesh file replaces (refine's
    --elements is a list of counts to refine the file's profile with, so not one of them there).
    Lead (--add-mass, a run file's ``[[frame.lead]]``) is added last: the frame becomes a mesh
    (``--elements`` cells for a Frame) with the strips on it.
    """
    return with_lead(_bare_frame(args, exclusive), args, getattr(args, "elements", FRAME_ELEMENTS))


def _bare_frame(args: argparse.Namespace, exclusive: tuple[str, ...]) -> Frame | FrameMesh:
    from fem_racket.cli.options.runfile_named import where_set
    from fem_racket.frame.plausible import check_implement
    from fem_racket.frame.segments import Frame, standard_frame
    from fem_racket.io.mesh_files import read_mesh

    path = getattr(args, "mesh", None)
    if path is None:
        segments = getattr(args, "segments", None)
        if segments:
            return check_implement(Frame(tuple(segments)), "frame.segments")
        return standard_frame(args.ei1, args.ei2)
    clash = sorted(set(getattr(args, "explicit_options", ())) & set(exclusive))
    if clash:
        raise InputError(
            f"--{clash[0]} is not allowed with {where_set(args, 'mesh')}: the mesh file gives "
            "the cells and their EI and rhoA"
        )
    return read_mesh(path)


def build_model(args: argparse.Namespace) -> FrameModel:
    """Assemble the frame the options describe (a --mesh file as it is)."""
    from fem_racket.frame.model import FrameModel

    return FrameModel.build(frame_from_args(args), args.elements)
