"""The string bed on the command line: tension, pattern, head size and string, and the run of
``fem-racket simulate`` with it (:func:`run_strung`).

Any of these options replaces the paper's lumped K_CB by the string bed (:mod:`fem_racket.strings`,
:mod:`fem_racket.impact.strung`): the ball's own law then acts on the bed. Without them the
paper's spring stays, unchanged. (``--string-stiffness`` and ``--string-cubic`` are parameters
of the ``series`` contact law, a different, lumped model.)

The head: ``--head-length`` and ``--head-width`` set the ellipse's axes; ``--head-area`` scales
the default head (0.326 m x 0.252 m, 645 cm^2) keeping its shape, or, with one axis given, sets
the other; all three together are refused.

:func:`run_strung` runs :func:`fem_racket.simulate` with the bed and prints the
outcome with the bed's stiffness and first frequencies, the peak deflections of the bed and the
ball and the energy the bed returns and the ball loses. Options that belong to the paper's lumped
spring or to paths the strung racket does not take are refused in one line (by the problem and
its solver).
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING, Any

from fem_racket.cli.options.impact import impact_kwargs, swing_from_args
from fem_racket.cli.options.output import (
    core_rows,
    offset_rows,
    print_result,
    run_parameters,
    write_result_files,
)
from fem_racket.cli.options.runfile import given_options
from fem_racket.cli.text import significant
from fem_racket.outputs import provenance
from fem_racket.strings.bed import EDGES, StringBed
from fem_racket.strings.materials import STRINGS
from fem_racket.strings.options import STRING_OPTIONS, bed_from_options

if TYPE_CHECKING:
    from fem_racket.impact.strung.impact import StrungImpact

__all__ = [
    "STRING_DESTS",
    "add_strings_options",
    "run_strung",
    "strings_from_args",
    "strung_from_args",
]

#: The argparse destinations of the string-bed options.
STRING_DESTS = STRING_OPTIONS


def add_strings_options(parser: argparse.ArgumentParser) -> None:
    """Add the string-bed options (all default to None: the paper's K_CB)."""
    d = StringBed()
    g = parser.add_argument_group(
        "string bed (any of these replaces the paper's K_CB by a membrane bed and the ball's law)"
    )
    g.add_argument(
        "--string-tension",
        type=float,
        default=None,
        metavar="N",
        help=f"tension per string [N] (default {d.tension_n:g}, the paper's 55 lb)",
    )
    g.add_argument(
        "--pattern",
        default=None,
        metavar="MAINSxCROSSES",
        help=f"string pattern, mains along the racket x crosses (default {d.pattern})",
    )
    g.add_argument(
        "--head-area",
        type=float,
        default=None,
        metavar="CM2",
        help=f"string-bed area [cm^2] (default {d.area_m2 * 1e4:.0f}; the ellipse keeps its shape)",
    )
    g.add_argument(
        "--head-length",
        type=float,
        default=None,
        metavar="M",
        help=f"string-bed length along the racket [m] (default {d.head_length_m:g})",
    )
    g.add_argument(
        "--head-width",
        type=float,
        default=None,
        metavar="M",
        help=f"string-bed width across the racket [m] (default {d.head_width_m:g})",
    )
    g.add_argument(
        "--string-material",
        default=None,
        choices=tuple(STRINGS),
        help=f"string material (default {d.string})",
    )
    g.add_argument(
        "--bed-edge",
        default=None,
        choices=EDGES,
        help="how the head ring follows the frame: point (with the impact point; default, the "
        "paper's point contact when the bed is stiff) or hoop (each edge point with the frame's "
        "bending and twist at its place)",
    )
    g.add_argument(
        "--string-stretch",
        action="store_const",
        const=True,
        default=None,
        help="the strings stretch as the bed deflects, their tension rising in the impact "
        "(integrated by cvode; default: off, the linear bed)",
    )


def strings_from_args(args: argparse.Namespace) -> StringBed | None:
    """The string bed the options ask for, or None when no string option is given."""
    return bed_from_options({k: getattr(args, k, None) for k in STRING_DESTS})


def _histories(result: StrungImpact) -> dict[str, Any]:

    return {
        "time [s]": result.t,
        "ball deflection [m]": result.ball_deflection,
        "bed deflection [m]": result.bed_deflection,
        "contact force [N]": result.force,
    }


def _write(args: argparse.Namespace, result: StrungImpact, summary: dict, files: list) -> None:

    meta = provenance(run_parameters(args))
    meta["used"] = summary
    write_result_files(args, meta, summary, files, _histories(result))


def _rows(s: dict[str, Any]) -> list[tuple[str, str, str]]:
    freqs = ", ".join(f"{f:.0f}" for f in s["stringbed_frequencies_hz"])
    return [
        *core_rows(s),
        *(offset_rows(s) if s["offset_m"] else []),
        ("impact speed", significant(s["speed_m_s"], 5), "m/s"),
        ("string bed", f"{s['pattern']} {s['string']}", ""),
        ("string tension", significant(s["string_tension_n"], 4), "N"),
        ("head area", significant(s["head_area_cm2"], 4), "cm^2"),
        ("stringbed stiffness", significant(s["stringbed_stiffness_n_m"], 4), "N/m"),
        ("stringbed frequencies", freqs, "Hz"),
        ("peak bed deflection", significant(s["peak_bed_deflection_m"] * 1e3, 4), "mm"),
        ("peak ball deflection", significant(s["peak_ball_deflection_m"] * 1e3, 4), "mm"),
        ("energy returned by the bed", significant(s["bed_energy_returned_j"], 4), "J"),
        ("energy lost in the ball", significant(s["energy_lost_in_ball_j"], 4), "J"),
        *(
            [("string stretch", "on (tension rises with the deflection)", "")]
            if s["string_stretch"]
            else []
        ),
        ("ball law", s["ball_law"], ""),
        ("solver", f"{s['solver']} (modal, {s['elements']} elements + bed)", ""),
    ]


def strung_from_args(
    args: argparse.Namespace, strings: StringBed, model, incidence: Any = None
) -> Any:
    """The impact the options ask for on ``strings`` and the frame ``model`` (a StrungImpact;
    an ObliqueResult with an ``incidence``), through :func:`fem_racket.simulate` (which refuses,
    in one line, what the strung racket does not take: K_CB, zeta, a swing, the options of
    other solvers)."""
    from fem_racket.impact.simulate import simulate
    from fem_racket.impact.solvers import auto_method

    auto = getattr(args, "solver", "auto") == "auto"
    kwargs = impact_kwargs(args)
    if auto:  # on the bed a linear ball (a preset of the linear law too) is solved exactly,
        law = kwargs.get("law")  # a stretching bed by CVODE (the library's "auto" picks it)
        linear = law is None or law.name == "linear"
        args.solver = "cvode" if strings.stretch else auto_method(linear)  # printed
        kwargs["solver"] = "auto" if strings.stretch else args.solver
    if "output_step" in given_options(args):  # on the command line or in the run file:
        kwargs["output_step"] = args.output_step  # refused there, not ignored here
    if hasattr(args, "racket_speed"):  # commands with the swing options
        kwargs["swing"] = swing_from_args(args, model.mesh.length)
    if incidence is not None:
        kwargs["incidence"] = incidence
    if "law" in given_options(args) and args.law == "linear":  # refused by the library, as
        kwargs["law"] = "linear"  # kcb and zeta are (the linear law's K_CB is ball and strings)
    return simulate(model, strings=strings, **kwargs)


def run_strung(args: argparse.Namespace, strings: StringBed, model, files: list[Path]) -> int:
    """Simulate the ball on ``strings`` and the frame ``model``; print, write."""
    result = strung_from_args(args, strings, model)
    summary = {
        **result.summary(),
        "ball_law": "kawazoe-1997-ball" if args.law == "linear" else args.law,
        "elements": model.mesh.n_elements,
    }
    if args.out:
        _write(args, result, summary, files)
    return print_result(args, summary, _rows, files)
