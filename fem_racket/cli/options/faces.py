"""``fem-racket map`` over the whole string face: e_A (``--offsets``) or the oblique ball's
outgoing spin and angle (``--angle``, ``--spin``, ``--friction``, ``--side-angle``,
``--side-spin``).

``--offsets`` maps e_A and v_out over (x, y) (:mod:`fem_racket.studies.face_map`);
any of the oblique options maps the outgoing spin ``spin_out_rpm`` and angle
``angle_out_deg`` of an oblique, spinning ball over the face (and with a side angle or side
spin its ``side_spin_out_rpm``, ``side_angle_out_deg`` and the racket's
``racket_yaw_rate_rad_s``)
(:mod:`fem_racket.studies.spin_map`), on the grid of ``--positions`` and ``--offsets``
(defaults :data:`fem_racket.studies.spin_map.SPIN_POSITIONS` and ``SPIN_OFFSETS``: each point
is one oblique impact).
Options the spin map cannot use are refused in one line, and ``--friction`` without an angle
or a spin (the ball head-on and spinless: no tangential force), as ``simulate`` refuses it.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path
from typing import Any

from fem_racket.cli.common import print_json, run_parameters, significant, swing_kwargs
from fem_racket.cli.options.output import print_written
from fem_racket.cli.options.runfile import given_options
from fem_racket.studies.spin_defaults import SPIN_OFFSETS, SPIN_POSITIONS, SPIN_REFUSES
from fem_racket.validation import InputError

__all__ = [
    "MAP_IMPACT",
    "add_face_options",
    "check_map_size",
    "face_asked",
    "map_impact",
    "map_rackets",
    "print_maps_json",
    "run_face",
]

#: The ball, law and solver options of ``map``, passed on as they are to the maps along the axis,
#: over the face and of the spin.
MAP_IMPACT = ("ball_mass", "kcb", "zeta", "separation", "modes", "tolerance")

#: The oblique ball's options: dest -> (option, metavar, help).
OBLIQUE = {
    "angle": ("--angle", "DEG", "incidence angle [deg] from the face normal, in the plane of the "
              "long axis: map the outgoing spin and angle over the face (default: none)"),
    "spin": ("--spin", "RPM", "incoming spin [rpm], positive = topspin (default 0 with --angle)"),
    "friction": ("--friction", "MU", "Coulomb friction ball/strings [-] (default 0.4 with "
                 "--angle)"),
    "side_angle": ("--side-angle", "DEG", "angle [deg] of the ball's path from the plane of the "
                   "long axis, in (-90, 90), + toward +y: a 3-D oblique ball; maps the outgoing "
                   "side spin and angle too (default 0)"),
    "side_spin": ("--side-spin", "RPM", "incoming side spin [rpm] about the long axis's "
                  "direction, + rolling toward +y (default 0)"),
}  # fmt: skip


#: The printed ranges over the face of a ball crossing it: field, label, unit.
_SIDE_ROWS = (
    ("side_spin_out_rpm", "side spin out", "rpm"),
    ("side_angle_out_deg", "side angle out", "deg"),
    ("racket_yaw_rate_rad_s", "racket yaw rate", "rad/s"),
)


def add_face_options(g: argparse._ArgumentGroup) -> None:
    """``--offsets`` and the oblique ball's options of ``map``."""
    g.add_argument(
        "--offsets",
        default=None,
        metavar="VALUES",
        help="lateral offsets y [m] from the long axis (start:stop:num or a comma list): map "
        "the whole string face over (x, y), the frame bending and twisting; points off the "
        "head outline (100 in^2 ellipse, 0.326 x 0.252 m) are left blank; prints the power "
        f"area (default: along the axis only; {SPIN_OFFSETS} with --angle)",
    )
    for dest, (option, metavar, text) in OBLIQUE.items():
        g.add_argument(option, dest=dest, type=float, default=None, metavar=metavar, help=text)


def map_impact(args: argparse.Namespace) -> dict[str, Any]:
    """The options of :data:`MAP_IMPACT` given (on the command line or in a run file) as
    keywords of the maps, which take the same defaults and refuse what the solver or the law
    cannot use (``--modes`` or ``--separation`` with ``--law``)."""
    given = given_options(args)
    return {dest: getattr(args, dest) for dest in MAP_IMPACT if dest in given}


def print_maps_json(maps: list) -> None:
    """``map --json``: the summary of the one racket's map, or ``{"rackets": [...]}``."""
    objs = [m.summary() for m in maps]
    print_json(objs[0] if len(objs) == 1 else {"rackets": objs})


def _oblique(args: argparse.Namespace) -> bool:
    return any(getattr(args, d, None) is not None for d in OBLIQUE)


def _oblique_given(args: argparse.Namespace) -> str:
    """The oblique options given, as the refusals name them (``--angle, --spin``)."""
    return ", ".join(OBLIQUE[d][0] for d in OBLIQUE if getattr(args, d, None) is not None)


def check_map_size(args: argparse.Namespace) -> None:
    """Refuse a map of more points than :data:`~fem_racket.studies.map_options.MAX_MAP_POINTS`
    (``--positions`` x ``--offsets``, counted from their text before any array is made)."""
    from fem_racket.studies.grid_values import value_count
    from fem_racket.studies.map_options import check_map_points

    spin = _oblique(args) and "positions" not in given_options(args)
    offsets = args.offsets or (SPIN_OFFSETS if _oblique(args) else None)
    check_map_points(
        value_count(SPIN_POSITIONS if spin else args.positions),
        1 if offsets is None else value_count(offsets),
    )


def face_asked(args: argparse.Namespace) -> bool:
    """True when the map is over the whole face."""
    return args.offsets is not None or _oblique(args)


def run_face(
    args: argparse.Namespace, outs: list[Path], positions: Any, law: Any, rackets: list
) -> int:
    """The face map the options ask for, its files and its printed summary."""
    if _oblique(args):
        return _run_spin(args, outs, law, rackets)
    return _run_power(args, outs, positions, law, rackets)


def map_rackets(study: Callable[..., Any], args: argparse.Namespace, rackets: list, **kw) -> list:
    """One map per racket, in order: ``study(model, name=NAME, speed=--speed, **kw)`` for each
    (NAME, frame) of ``rackets``, its model built with ``--elements`` cells (``study``:
    :func:`~fem_racket.studies.racket_map.racket_map`, ``face_map`` or ``spin_map``)."""
    from fem_racket.frame.model import FrameModel

    return [
        study(FrameModel.build(frame, args.elements), name=name, speed=args.speed, **kw)
        for name, frame in rackets
    ]


def _run_spin(args: argparse.Namespace, outs: list[Path], law: Any, rackets: list) -> int:
    """``--angle`` ...: the oblique ball's spin over the face."""
    import numpy as np

    from fem_racket.cli.options.incidence_checks import refuse_idle_options
    from fem_racket.frame.torsion import check_off_axis
    from fem_racket.impact.incidence import Incidence
    from fem_racket.io.spin_map_files import write_spin_map
    from fem_racket.studies.grid import as_values
    from fem_racket.studies.spin_map import spin_map

    given = given_options(args)
    for dest, why in SPIN_REFUSES.items():
        if dest in given:
            raise InputError(f"{dest} is not allowed with {_oblique_given(args)}: {why}")
    inc = Incidence(**{d: getattr(args, d) for d in OBLIQUE if getattr(args, d) is not None})
    refuse_idle_options(args, {d: d for d in OBLIQUE})  # --friction on a head-on, spinless ball
    positions = as_values("position", args.positions if "positions" in given else SPIN_POSITIONS)
    offsets = as_values("offset", args.offsets or SPIN_OFFSETS)
    if np.any(np.asarray(offsets) != 0.0):  # each racket struck off its axis: named
        given_offsets = (
            f"offsets = {args.offsets} m"
            if args.offsets
            else f"offsets = {SPIN_OFFSETS} m (the spin map's default: no --offsets given)"
        )
        for name, frame in rackets:
            why = "the spin map's offsets cross the face (simulate --angle strikes on the axis)"
            check_off_axis(frame, given_offsets, where=f"racket {name!r}", allowed=why)
    options = {**map_impact(args), "law": law}
    if law is not None:
        for dest in ("kcb", "zeta", "separation", "modes"):
            if dest in given:
                raise InputError(f"{dest} is not allowed with --law {law.name}: the law's own")
    maps = map_rackets(
        spin_map,
        args,
        rackets,
        positions=positions,
        offsets=offsets,
        incidence=inc,
        options=options,
    )
    for path in outs:
        write_spin_map(maps, path, parameters=run_parameters(args))
    if args.json:
        print_maps_json(maps)
        return 0
    for m in maps:
        lo, x_lo, hi, x_hi, y_hi = m.extreme()
        a_lo, _, a_hi, _, _ = m.extreme("angle_out_deg")
        print(m.name)
        print(f"  {'spin out min':<26} {significant(lo, 4):>10} rpm at {significant(x_lo, 4)} x/L")
        print(f"  {'spin out max':<26} {significant(hi, 4):>10} rpm at {significant(x_hi, 4)} x/L,"
              f" y = {y_hi:g} m")  # fmt: skip
        ahead, points = m.forward()  # the convention stated where the ball goes on (COR < 0)
        note = f" (> 90: the ball keeps moving forward, COR < 0, at {ahead} of {points} points)"
        print(f"  {'angle out':<26} {significant(a_lo, 4):>10} to {significant(a_hi, 4)} deg"
              f"{note if ahead else ''}")  # fmt: skip
        for key, label, unit in _SIDE_ROWS if inc.lateral else ():
            lo, _, hi, _, _ = m.extreme(key)
            print(f"  {label:<26} {significant(lo, 4):>10} to {significant(hi, 4)} {unit}")
        print(f"  {'contact regimes':<26} {', '.join(m.summary()['contact_regimes'])}")
    print_written(outs)
    return 0


def _run_power(
    args: argparse.Namespace, outs: list[Path], positions: Any, law: Any, rackets: list
) -> int:
    """``--offsets``: the power map of the whole face (:mod:`fem_racket.studies.face_map`)."""
    from fem_racket.io.face_files import write_face
    from fem_racket.studies.face_map import DEFAULT_AREA_FRACTION, face_map
    from fem_racket.studies.grid import as_values

    if law is not None:
        raise InputError(
            f"law = {law.name!r} is not allowed with --offsets: the face map runs the paper's "
            "linear law (the batched engine)"
        )
    offsets = as_values("offset", args.offsets)
    if args.power_fraction is None:
        args.power_fraction = DEFAULT_AREA_FRACTION
    options = {**map_impact(args), "power_fraction": args.power_fraction}
    maps = map_rackets(
        face_map,
        args,
        rackets,
        positions=positions,
        offsets=offsets,
        options=options,
        **swing_kwargs(args),
    )
    for path in outs:
        write_face(maps, path, overwrite=args.overwrite, parameters=run_parameters(args))
    if args.json:
        print_maps_json(maps)
        return 0
    for m in maps:
        x, y, e = m.max_apparent_cor
        print(m.name)
        print(f"  {'power area':<26} {significant(m.power_area_cm2, 4):>10} cm^2")
        print(f"  {'max apparent COR':<26} {significant(e, 4):>10}")
        print(f"  {'  at':<26} {significant(x, 4):>10} x/L, y = {y:g} m")
        print(f"  {'mode-1 node':<26} {significant(m.node, 4):>10} x/L")
        cop = "-" if m.cop != m.cop else significant(m.cop, 4)
        print(f"  {'centre of percussion':<26} {cop:>10} x/L")
    print_written(outs)
    return 0
