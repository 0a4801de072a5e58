"""Set-ups named on the command line: a preset, a mesh file or a run file, with optional lead.

``SOURCE[+LOCATION:GRAMS...]``: SOURCE is a preset (``standard``, ``rigid``), a run file
(``.toml``: its ``[frame]`` with any ``[[frame.lead]]``, ``[ball]`` and ``[contact]``, i.e. the
racket with its own strings and ball) or a mesh file (any other suffix); each ``+LOCATION:GRAMS``
adds lead (``standard+12:10+3/9:6``). How the set-ups are played (speed, swing, impact point) is
the command's, the same for all, so a run file may not set ``[impact]``, ``[hand]``,
``[solver]`` or ``[output]`` here.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from fem_racket.frame.head import DEFAULT_HEAD
from fem_racket.frame.lead import Lead, add_lead, parse_lead
from fem_racket.frame.mesh import FrameMesh, frame_mesh
from fem_racket.frame.segments import standard_frame
from fem_racket.io.config_file import load_run_file
from fem_racket.io.config_keys import PRESETS
from fem_racket.io.config_kwargs import keyword_law
from fem_racket.io.mesh_files import read_mesh
from fem_racket.studies.compare import Setup
from fem_racket.validation import InputError

__all__ = ["compare_play", "read_setup", "read_setups"]

#: Run-file tables a set-up may hold (the racket, its strings and its ball).
SETUP_TABLES = ("frame", "ball", "contact")


def _from_run_file(path: Path, elements: int) -> tuple[Setup, list[Lead]]:
    cfg = load_run_file(path)
    extra = sorted(set(cfg.values) - set(SETUP_TABLES)) + sorted(cfg.tables)
    if extra:
        raise InputError(
            f"{path}: [{extra[0]}] is not allowed in a compared set-up: it may hold only "
            f"{', '.join(f'[{t}]' for t in SETUP_TABLES)} (the command plays every set-up alike)"
        )
    d = cfg.defaults()
    try:  # an implausible frame refused, the run file named as in its other refusals
        frame = cfg.frame() or standard_frame()
    except InputError as exc:
        raise InputError(f"{path}: {exc}") from None
    kwargs = {k: d[k] for k in ("ball_mass", "kcb", "zeta") if k in d}
    law = keyword_law(d)
    return (
        Setup(path.stem, frame, law=law, elements=d.get("elements", elements), **kwargs),
        list(d.get("add_mass", [])),
    )


def read_setup(text: str, *, elements: int = 20, leads: Sequence[Lead] = ()) -> Setup:
    """The set-up ``text`` names (module docstring), with ``leads`` added to every one."""
    source, *extra = str(text).split("+")
    more = [parse_lead(e) for e in extra]
    if source in PRESETS:
        setup, own = Setup(source, standard_frame(PRESETS[source]), elements=elements), []
    elif Path(source).suffix.lower() == ".toml":
        setup, own = _from_run_file(Path(source), elements)
    else:
        setup, own = Setup(Path(source).stem, read_mesh(source), elements=elements), []
    all_leads = [*own, *leads, *more]
    if not all_leads:
        return setup
    mesh = setup.frame
    mesh = mesh if isinstance(mesh, FrameMesh) else frame_mesh(mesh, setup.elements)
    mesh = add_lead(mesh, all_leads, DEFAULT_HEAD.on_frame(mesh.length))
    name = setup.name + "".join(f"+{lead.label()}" for lead in [*leads, *more])
    return Setup(name, mesh, setup.ball_mass, setup.kcb, setup.zeta, setup.law, setup.elements)


def read_setups(
    texts: Sequence[str], *, elements: int = 20, leads: Sequence[Lead] = ()
) -> list[Setup]:
    """The set-ups ``texts`` name (:func:`read_setup`), named apart where two share a name."""
    from fem_racket.studies.compare import unique_names

    setups = [read_setup(s, elements=elements, leads=leads) for s in texts]
    names = unique_names([s.name for s in setups])
    return [
        Setup(n, s.frame, s.ball_mass, s.kcb, s.zeta, s.law, s.elements)
        for n, s in zip(names, setups, strict=True)
    ]


def compare_play(options: Mapping[str, Any]) -> Any:
    """How ``fem-racket compare`` plays every set-up: the :class:`~fem_racket.studies.compare.Play`
    of its options (argparse dests: ``speed`` [m/s], ``positions`` and ``offsets`` as text
    grids, ``point`` [x/L], ``grip``, and the swing's ``racket_speed``, ``reference``,
    ``pivot``)."""
    from fem_racket.studies.compare import Play
    from fem_racket.studies.grid import as_values

    offsets = options["offsets"]
    swing = {k: options[k] for k in ("racket_speed", "reference", "pivot")}
    return Play(
        speed=options["speed"],
        positions=as_values("position", options["positions"]),
        position=options["point"],
        grip=options["grip"],
        offsets=None if offsets is None else as_values("offset", offsets),
        **swing,
    )
