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

from fem_racket.io.config_defaults import DEFAULT_STEP, DEFAULTS
from fem_racket.io.config_named import keys_named
from fem_racket.io.config_oblique import CORE_DEST_KEYS, oblique_file
from fem_racket.strings.options import STRING_OPTIONS, bed_from_options
from fem_racket.validation import InputError, show

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any

__all__ = ["HAND_KEYS", "NOT_WITH_HAND", "file_frame", "file_law", "run_file", "simulate_file"]

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


def file_law(cfg: RunConfig) -> Any:
    """The contact law of ``cfg``'s ``[contact]`` (None: the paper's linear law); the linear
    law's keys with another law are refused, as the commands refuse them."""
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


def _output_step(cfg: RunConfig, table: str) -> float:
    """The table's ``output_step`` [s]: a number, or a text holding one as the command line
    takes it; 1e-5 s when not given."""
    from fem_racket.io.config_tables import number

    step = cfg.table(table).get("output_step")
    if step is None:
        return DEFAULT_STEP
    value = number(f"{table}.output_step", step)
    if not 0 < value < math.inf:
        raise InputError(
            f"{table}.output_step = {show(step)} s is not allowed: must be a finite number > 0"
        )
    return value


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
    from fem_racket.impact.swing import Swing
    from fem_racket.studies.map_options import check_at_rest

    d = cfg.defaults()
    model = FrameModel.build(file_frame(cfg), d.get("elements", 20))
    length = model.mesh.length
    speed = d.get("racket_speed", 0.0)
    reference, pivot = d.get("reference"), d.get("pivot")
    # checks: the racket speed's bound first, then a swing's point without a swing, as the
    # command does (cli.options.impact)
    swing = Swing.from_speed(speed, length, reference=reference, pivot=pivot)
    check_at_rest(speed, reference, pivot)
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


#: Suffixes of the file ``simulate`` writes (``--out``, ``output.out``, ``[simulate] out``).
OUT_SUFFIXES = (".json", ".csv")


def _check_simulate_table(cfg: RunConfig) -> None:
    """``[simulate]`` as the command reads it: its options only (not the core tables'), each
    of its type, and the output named by it or ``[output]`` a .json or .csv file (the method
    writes none: its state is not checked)."""
    from pathlib import Path

    from fem_racket.io.config_keys import reject_unknown
    from fem_racket.io.config_run_keys import RUN_KEYS, run_keys
    from fem_racket.io.config_unused import refuse_core_only
    from fem_racket.validation import show_path

    own = {k.replace("-", "_"): v for k, v in cfg.table("simulate").items()}
    for key in own:
        refuse_core_only(f"simulate.{key}", key)
    reject_unknown(own, [*RUN_KEYS["simulate"], "output_step"], "simulate")
    _output_step(cfg, "simulate")  # used or not
    out = run_keys("simulate", own).get("out") or cfg.defaults().get("out")
    if out is not None and Path(out).suffix.lower() not in OUT_SUFFIXES:
        raise InputError(
            f"out = {show_path(Path(out))} is not allowed: must end in {' or '.join(OUT_SUFFIXES)}"
        )


def unwritten(key: str) -> str:
    """The refusal of the run-file key ``key`` (``simulate.output_step = 2e-05 (run.toml)``)
    where nothing is written: the command's and the Python method's one line."""
    return f"{key} is not allowed without out: it sets the histories or files written, and none are"


def _written(cfg: RunConfig) -> bool:
    """Whether the file names the output ``fem-racket simulate --config`` writes."""
    return bool(cfg.table("simulate").get("out") or cfg.defaults().get("out"))


def _check_overwrite_used(cfg: RunConfig) -> None:
    """Refuse ``overwrite = true`` (``[simulate]``'s, else ``[output]``'s) where the file names
    no output, as ``fem-racket simulate --config`` refuses it: nothing would use it."""
    from fem_racket.io.config_tables import overwrite_set

    given = overwrite_set(cfg, "simulate")
    if given is not None and not _written(cfg):
        raise InputError(unwritten(given))


def _check_step_used(cfg: RunConfig, histories: bool | None) -> None:
    """Refuse ``[simulate] output_step`` (at other than its default) where the head-on or held
    impact computes no histories: no output in the file and ``histories`` not asked, as
    ``fem-racket simulate --config`` refuses it (an oblique impact takes it; on a string bed
    the solver refuses it)."""
    step = cfg.table("simulate").get("output_step")
    d = cfg.defaults()
    if histories or step is None or _output_step(cfg, "simulate") == DEFAULT_STEP:
        return
    if _written(cfg) or cfg.values.get("oblique"):
        return
    if bed_from_options({k: d.get(k) for k in STRING_OPTIONS}) is None:
        raise InputError(unwritten(f"simulate.output_step = {show(step)} ({cfg.source})"))


def simulate_file(cfg: RunConfig, *, histories: bool | None = None) -> Any:
    """The impact ``cfg`` describes, as ``fem-racket simulate --config`` computes it: the
    result of :func:`run_file` on ``[simulate]`` (its keys checked as the command checks
    them; ``[simulate] output_step`` refused where no histories are computed, ``overwrite``
    where no output is named)."""
    _check_simulate_table(cfg)
    _check_overwrite_used(cfg)
    _check_step_used(cfg, histories)
    return run_file(cfg, histories=histories)[1]


def run_file(cfg: RunConfig, *, histories: bool | None = None, table: str = "simulate") -> Any:
    """The frame model and the impact ``cfg`` describes, as ``fem-racket simulate --config``
    computes it.

    Parameters
    ----------
    cfg : RunConfig
    histories : bool, optional
        Compute the time histories (at ``[simulate] output_step``, 1e-5 s by default); by
        default when the file names an output, as the command does.
    table : str
        The command table whose ``output_step`` sets the histories' step: ``"vtk"`` and
        ``"animate"`` for the drawings of ``export-vtk`` and ``animate``.

    Returns
    -------
    model : FrameModel
        The file's frame.
    result : ImpactResult, HeldRun with a ``[hand]`` table, StrungImpact with ``[strings]``, or
        ObliqueResult with ``[oblique]``

    A library refusal of a value of the file's core tables names its key
    (:mod:`.config_named`).
    """
    with keys_named(cfg, table):
        return _run(cfg, histories, table)


def _run(cfg: RunConfig, histories: bool | None, table: str) -> Any:
    from fem_racket.impact.simulate import simulate

    d = cfg.defaults()
    strings = bed_from_options({k: d.get(k) for k in STRING_OPTIONS})
    if histories is None:
        histories = bool(cfg.table("simulate").get("out") or d.get("out"))
    hand = _hand(cfg)
    if hand is None and "hand_shock_window" in d:
        raise InputError(
            f"shock_window = {show(d['hand_shock_window'])} s is not allowed without a hand: "
            "give --grip or a hand parameter",
            parameter="shock_window",
            value=d["hand_shock_window"],
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
    kwargs.update({} if (law := file_law(cfg)) is None else {"law": law})
    if strings is not None:  # on the bed (its histories have their own samples: a step only
        kwargs["strings"] = strings  # when the file gives one), as simulate --string-tension
        step = _output_step(cfg, table)
        if step != DEFAULT_STEP:
            kwargs["output_step"] = step  # (a step at the default changes nothing)
    if cfg.values.get("oblique"):  # the oblique impact, as simulate's --angle ...
        return model, oblique_file(cfg, hand, model, swing, kwargs, _output_step(cfg, table))
    if strings is None:
        kwargs["output_step"] = _output_step(cfg, table) if histories else None
    if hand is not None:
        kwargs.update(hand=hand, shock_window=d.get("hand_shock_window"))
    return model, simulate(model, swing=swing, **kwargs)
