"""A run file's impact in Python: :meth:`RunConfig.simulate` = ``fem-racket simulate --config``.

:func:`simulate_file` runs what the command runs on the same file, with the same checks: every
table of the file applies (frame, ball, contact law, impact and swing, hand, string bed, oblique
ball, solver, ``[simulate] output_step``), and a key the run cannot use is refused as the command
refuses it (a hand with ``solver.modes``, ``contact.kcb_n_m`` under another law ...). Histories
are computed as the command computes them: when the file names an output (``output.out`` or
``[simulate] out``), unless ``histories`` says otherwise. The command-line defaults are the
library's (``tests/io/test_config_run.py`` checks both ways).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.frame.model import DEFAULT_MODES
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.io.config_keys import CORE_KEYS
from fem_racket.strings.options import STRING_OPTIONS, bed_from_options
from fem_racket.validation import InputError, show

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any

__all__ = ["HAND_KEYS", "NOT_WITH_HAND", "file_frame", "simulate_file"]

#: ``[hand]`` keys -> :class:`~fem_racket.frame.hand.Hand` fields (``grip`` picks the preset).
HAND_KEYS = {
    "mass_kg": "mass",
    "grip_start_m": "grip_start",
    "grip_end_m": "grip_end",
    "stiffness_n_m2": "stiffness",
    "damping_n_s_m2": "damping",
    "inertia_kg_m2": "inertia",
}
#: Options (argparse dests) the hand-held racket does not take: it keeps its modes by the
#: tolerance or all its DOFs and ends contact when the spring deflection falls to zero.
NOT_WITH_HAND = ("basis", "modes", "t_max", "separation")
#: The options of :func:`fem_racket.simulate` a file or the command line may set, with their
#: defaults (the command line's parser states them too; ``tests/io/test_config_run.py`` compares
#: them): an option at its default that was not given is left to the library.
DEFAULTS: dict[str, Any] = {
    "ball_mass": DEFAULT_BALL_MASS,
    "kcb": None,
    "zeta": None,
    "solver": "auto",
    "separation": "displacement",
    "basis": "modal",
    "modes": DEFAULT_MODES,
    "tolerance": DEFAULT_TOLERANCE,
    "t_max": None,
    "rtol": 1e-10,
    "atol": 1e-12,
    "offset": 0.0,
}
#: argparse dest -> the core key that sets it (for messages).
CORE_DEST_KEYS = {k.dest: f"{t}.{name}" for t, ks in CORE_KEYS.items() for name, k in ks.items()}


def _law(cfg: RunConfig) -> Any:
    from fem_racket.contact.presets import get_law, law_parameters

    d = cfg.defaults()
    law = get_law(d.get("law", "linear"), **law_parameters(d))
    if law is not None:
        for key in ("kcb_n_m", "zeta", "clamped_cor"):
            if key in cfg.values.get("contact", {}):
                value = cfg.values["contact"][key]
                raise InputError(
                    f"contact.{key} = {show(value)} ({cfg.source}) is not allowed with contact "
                    f"law {show(d['law'])}: it sets the paper's linear law's K_CB and zeta only"
                )
    return law


def _hand(cfg: RunConfig) -> Any:
    from fem_racket.frame.hand import GRIPS

    table = cfg.values.get("hand", {})
    if "grip" not in table and not set(table) & set(HAND_KEYS):  # a window alone is no hand
        return None
    fields = {HAND_KEYS[k]: v for k, v in table.items() if k in HAND_KEYS}
    return dataclasses.replace(GRIPS[table.get("grip", "loose")], **fields)


def _output_step(cfg: RunConfig) -> float:
    from fem_racket.impact.settings import Settings

    step = cfg.table("simulate").get("output_step")
    if step is None:
        return Settings().output_step
    if isinstance(step, bool) or not isinstance(step, (int, float)) or not 0 < step < math.inf:
        raise InputError(
            f"simulate.output_step = {show(step)} s is not allowed: must be a finite number > 0"
        )
    return float(step)


def file_frame(cfg: RunConfig) -> Any:
    """The frame of ``cfg``'s ``[frame]`` as the commands build it: a Frame or FrameMesh, with
    its ``[[frame.lead]]`` added last on the meshed frame (as ``--add-mass``)."""
    from fem_racket.frame.segments import PAPER_EI1, standard_frame

    d = cfg.defaults()
    frame = cfg.frame()
    if frame is None:
        frame = standard_frame(d.get("ei1", PAPER_EI1), d.get("ei2"))
    elements = d.get("elements", 20)
    if d.get("add_mass"):  # [[frame.lead]], as --add-mass: added last, on the meshed frame
        from fem_racket.frame.head import DEFAULT_HEAD
        from fem_racket.frame.lead import add_lead
        from fem_racket.frame.mesh import frame_mesh
        from fem_racket.frame.segments import Frame

        mesh = frame_mesh(frame, elements) if isinstance(frame, Frame) else frame
        frame = add_lead(mesh, d["add_mass"], DEFAULT_HEAD.on_frame(mesh.length))
    return frame


def _model_and_swing(cfg: RunConfig) -> tuple[Any, Any]:
    from fem_racket.frame.model import FrameModel
    from fem_racket.impact.swing import DEFAULT_REFERENCE, Swing

    d = cfg.defaults()
    model = FrameModel.build(file_frame(cfg), d.get("elements", 20))
    length = model.mesh.length
    speed = d.get("racket_speed", 0.0)
    reference, pivot = d.get("reference", DEFAULT_REFERENCE), d.get("pivot")
    swing = Swing.from_speed(speed, length, reference=reference, pivot=pivot)  # checks
    return model, (None if speed == 0.0 else swing)


def _check_hand(cfg: RunConfig, d: dict[str, Any]) -> None:
    """As the command: a hand takes no basis, modes, t_max or separation of the file's."""
    for dest in NOT_WITH_HAND:
        if dest in d and d[dest] != DEFAULTS.get(dest):
            raise InputError(
                f"{CORE_DEST_KEYS[dest]} = {show(d[dest])} ({cfg.source}) is not allowed with a "
                "hand: the held racket keeps its modes by --tolerance (exact) or all its DOFs "
                "(cvode, bdf) and ends contact by the spring deflection"
            )


def simulate_file(
    cfg: RunConfig, *, histories: bool | None = None, output_step: float | None = None
) -> Any:
    """The impact ``cfg`` describes, as ``fem-racket simulate --config`` computes it.

    Parameters
    ----------
    cfg : RunConfig
    histories : bool, optional
        Compute the time histories (at ``[simulate] output_step``, 1e-5 s by default); by
        default when the file names an output, as the command does.
    output_step : float, optional
        The histories' step [s] instead of ``[simulate] output_step`` (export-vtk, animate).

    Returns
    -------
    ImpactResult, or HeldRun with a ``[hand]`` table
    """
    from fem_racket.impact.simulate import simulate

    d = cfg.defaults()
    strings = bed_from_options({k: d.get(k) for k in STRING_OPTIONS})
    if histories is None:
        histories = bool(cfg.table("simulate").get("out") or d.get("out"))
    hand = _hand(cfg)
    if hand is None and "hand_shock_window" in d:
        raise InputError(
            f"shock_window = {show(d['hand_shock_window'])} s is not allowed without a hand: "
            "give --grip or a hand parameter"
        )
    if hand is not None:
        if strings is not None:
            raise InputError(f"[hand] ({cfg.source}) is not allowed with [strings]: give one")
        _check_hand(cfg, d)
    model, swing = _model_and_swing(cfg)
    # as the command: the impact point and speed, and every other option the file sets to
    # other than its default (one at its default is left to the library)
    kwargs: dict[str, Any] = {"position": d.get("position", 0.75), "speed": d.get("speed", 20.0)}
    kwargs.update({k: d[k] for k, v in DEFAULTS.items() if k in d and d[k] != v})
    kwargs.update({} if (law := _law(cfg)) is None else {"law": law})
    if strings is not None:  # on the bed (its histories have their own samples: a step only
        kwargs["strings"] = strings  # when the file gives one), as simulate --string-tension
        given = output_step or cfg.table("simulate").get("output_step")
        kwargs.update({"output_step": given} if given else {})
    if cfg.values.get("oblique"):  # the oblique impact, as simulate's --angle ...
        return _oblique(cfg, d, hand, model, swing, kwargs)
    step = (output_step or _output_step(cfg)) if histories else None
    if strings is not None:
        return simulate(model, swing=swing, **kwargs)
    if hand is not None:
        window = d.get("hand_shock_window")
        return simulate(
            model, hand=hand, shock_window=window, swing=swing, output_step=step, **kwargs
        )
    return simulate(model, output_step=step, swing=swing, **kwargs)


#: ``[oblique]`` dests -> :class:`~fem_racket.impact.incidence.Incidence` fields.
INCIDENCE_FIELDS = {
    "angle": "angle",
    "spin": "spin",
    "friction": "friction",
    "ball_inertia": "ball_inertia",
    "ball_radius": "radius",
    "compliance_ratio": "compliance_ratio",
    "side_angle": "side_angle",
    "side_spin": "side_spin",
}
#: What a clamped head takes from the core tables (besides ``[oblique]``).
CLAMPED_TAKES = ("speed", "ball_mass", "kcb", "zeta", "separation")


def _oblique(cfg: RunConfig, d: dict, hand: Any, model: Any, swing: Any, kwargs: dict) -> Any:
    """The oblique impact of an ``[oblique]`` table, as ``simulate --angle ...`` runs it
    (:func:`fem_racket.impact.simulate_oblique.simulate_oblique`, or a stroke with
    ``face_angle_deg``/``path_angle_deg``): an ObliqueResult."""
    from fem_racket.impact.incidence import Incidence
    from fem_racket.impact.oblique.stroke import Stroke
    from fem_racket.impact.simulate_oblique import simulate_oblique
    from fem_racket.impact.simulate_stroke import simulate_stroke

    if hand is not None:
        raise InputError(f"[hand] ({cfg.source}) is not allowed with [oblique]: the racket is free")
    inc = Incidence(**{f: d[k] for k, f in INCIDENCE_FIELDS.items() if k in d})
    stroke_given = {k: d[k] for k in ("face_angle", "path_angle") if k in d}
    if "path_angle" in stroke_given and swing is None:
        raise InputError(
            f"oblique.path_angle_deg = {show(d['path_angle'])} ({cfg.source}) is not allowed "
            "without a swing: give impact.racket_speed_m_s"
        )
    stroke = Stroke(**stroke_given) if stroke_given else None
    if d.get("clamped"):
        others = sorted(
            key for dest, key in CORE_DEST_KEYS.items()
            if dest in d and dest not in CLAMPED_TAKES and dest not in ("clamped", "out")
            and not key.startswith("oblique.") and dest != "overwrite"
        )  # fmt: skip
        if others:
            raise InputError(
                f"{others[0]} ({cfg.source}) is not allowed with oblique.clamped: a clamped head "
                "takes impact.speed_m_s, ball.mass_kg, contact.kcb_n_m, contact.zeta and "
                "solver.separation"
            )
        kw = {k: d.get(k, DEFAULTS.get(k)) for k in ("ball_mass", "kcb", "zeta", "separation")}
        kw.update(incidence=inc, speed=d.get("speed", 20.0), clamped=True)
        return simulate_stroke(stroke=stroke, **kw) if stroke else simulate_oblique(**kw)
    kw = {**kwargs, "incidence": inc}
    if "strings" not in kw:  # (the bed's histories have their own samples)
        kw["output_step"] = _output_step(cfg)
    if stroke is not None:
        return simulate_stroke(model, stroke=stroke, swing=swing, **kw)
    return simulate_oblique(model, swing=swing, **kw)


#: ``[sweep]`` keys that set how the sweep runs or what it prints, not its values.
SWEEP_RUN_KEYS = ("out", "overwrite", "restart", "serial", "workers", "scheduler", "quiet", "json")


def sweep_file(cfg: RunConfig, *, backend: str | None = None, workers: int | None = None) -> Any:
    """The sweep ``cfg`` describes, as ``fem-racket sweep --config`` computes it: the core tables
    fix what ``[sweep]`` does not sweep, ``[sweep]`` gives the grids (arrays or strings as on the
    command line), ``peak_force`` and ``chunk_size``. Returns the dataset the command writes
    (without writing it; ``[sweep]``'s run keys :data:`SWEEP_RUN_KEYS` are the command's)."""
    from fem_racket.contact.presets import law_parameters
    from fem_racket.io.config_unused import refuse_unused
    from fem_racket.studies.grid_values import LAW_PARAMETERS, PARAMETERS
    from fem_racket.studies.sweep import sweep_result

    d = cfg.defaults()
    options = ("ei2", "solver", "separation", "basis", "modes", "rtol", "atol", "tolerance")
    refuse_unused(cfg, "sweep", {*PARAMETERS, *LAW_PARAMETERS, *options, "mesh", "segments", "law"})
    table = {k.replace("-", "_"): v for k, v in cfg.table("sweep").items()}
    settings = {**d, **{k: v for k, v in table.items() if k not in SWEEP_RUN_KEYS}}
    frame = cfg.frame() if "mesh" in d or "segments" in d else None
    grid = {n: settings[n] for n in PARAMETERS if n in settings}
    if frame is not None:  # the file's frame replaces EI1/EI2 (scale it with ei_factor)
        grid.pop("ei1", None)
        if "mesh" in d:
            grid.pop("elements", None)
    kwargs = {k: settings[k] for k in options if k in settings and not (frame and k == "ei2")}
    laws = {k: v for k, v in law_parameters(settings).items() if k in LAW_PARAMETERS}
    result = sweep_result(
        frame,
        **grid,
        **kwargs,
        law=settings.get("law", "linear"),
        peak_force=settings.get("peak_force", False),
        chunk_size=settings.get("chunk_size"),
        backend=backend,
        workers=workers,
        progress=False,
        **laws,
    )
    return result.to_xarray()
