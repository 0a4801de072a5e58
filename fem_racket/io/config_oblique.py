"""A run file's ``[oblique]`` table in Python: the oblique, spinning ball of
``fem-racket simulate --config`` (its ``--angle``, ``--spin``, ..., ``--clamped``,
``--face-angle``, ``--path-angle``).

:func:`oblique_file` runs what the command runs for the file's ``[oblique]`` table, on the
structure the other tables give: the free racket, the racket held in the file's ``[hand]``
(``simulate --grip ... --angle ...``), the string bed of ``[strings]``, or a clamped head
(``clamped = true``: eqs 1-3, which takes only the ball, the paper's law, the speed and the
separation; any other key of the impact's tables is refused, as the command refuses it).
"""

from __future__ import annotations

from typing import Any

from fem_racket.io.config_defaults import DEFAULT_STEP, given
from fem_racket.io.config_keys import CORE_KEYS
from fem_racket.validation import InputError, show

__all__ = ["CLAMPED_TAKES", "INCIDENCE_FIELDS", "oblique_file"]

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any

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
#: argparse dest -> the core key that sets it (for messages).
CORE_DEST_KEYS = {k.dest: f"{t}.{name}" for t, ks in CORE_KEYS.items() for name, k in ks.items()}
#: Keys that do not state the impact (where and whether the command writes).
_OUTPUT = ("clamped", "out", "overwrite")


def _clamped(cfg: RunConfig, d: dict, hand: Any, inc: Any, stroke: Any) -> Any:
    """The clamped head of ``oblique.clamped = true``, as ``simulate --clamped``."""
    from fem_racket.impact.simulate_oblique import simulate_oblique
    from fem_racket.impact.simulate_stroke import simulate_stroke

    if hand is not None:
        raise InputError(
            f"[hand] ({cfg.source}) is not allowed with oblique.clamped: give one of them"
        )
    changed = given(d)  # (a key at simulate's default changes nothing, as on the command line)
    others = sorted(
        key for dest, key in CORE_DEST_KEYS.items()
        if dest in changed and dest not in CLAMPED_TAKES and dest not in _OUTPUT
        and not key.startswith("oblique.")
    )  # fmt: skip
    step = cfg.table("simulate").get("output_step")
    if step is not None and step != DEFAULT_STEP:
        others.insert(0, f"simulate.output_step = {show(step)}")  # its histories: 400 times
    if others:
        raise InputError(
            f"{others[0]} ({cfg.source}) is not allowed with oblique.clamped: a clamped head "
            "takes impact.speed_m_s, ball.mass_kg, contact.kcb_n_m, contact.zeta and "
            "solver.separation"
        )
    # the keys the file gives; the others at the library's defaults (the command's too)
    kw = {k: d[k] for k in ("ball_mass", "kcb", "zeta", "separation") if k in d}
    kw.update(incidence=inc, speed=d.get("speed", 20.0), clamped=True)
    return simulate_stroke(stroke=stroke, **kw) if stroke else simulate_oblique(**kw)


def oblique_file(
    cfg: RunConfig, hand: Any, model: Any, swing: Any, kwargs: dict[str, Any], step: float
) -> Any:
    """The oblique impact of ``cfg``'s ``[oblique]`` table, as ``simulate --angle ...`` runs it
    (:func:`fem_racket.impact.simulate_oblique.simulate_oblique`, or a stroke with
    ``face_angle_deg``/``path_angle_deg``): an ObliqueResult.

    Parameters
    ----------
    cfg : RunConfig
    hand : Hand or None
        The file's ``[hand]``: the racket held (its ``shock_window_s`` too), as ``--grip``.
    model : FrameModel
        The file's frame.
    swing : Swing or None
    kwargs : dict
        The normal impact's keywords of the other tables (a string bed's ``strings`` too).
    step : float
        The histories' output step [s] (not with a string bed: its histories have their own
        samples, unless the file gives one).
    """
    from fem_racket.impact.incidence import Incidence
    from fem_racket.impact.oblique.stroke import Stroke
    from fem_racket.impact.simulate_oblique import simulate_oblique
    from fem_racket.impact.simulate_stroke import simulate_stroke

    d = cfg.defaults()
    inc = Incidence(**{f: d[k] for k, f in INCIDENCE_FIELDS.items() if k in d})
    stroke_given = {k: d[k] for k in ("face_angle", "path_angle") if k in d}
    if "path_angle" in stroke_given and swing is None:
        raise InputError(
            f"oblique.path_angle_deg = {show(d['path_angle'])} ({cfg.source}) is not allowed "
            "without a swing: give impact.racket_speed_m_s"
        )
    stroke = Stroke(**stroke_given) if stroke_given else None
    if d.get("clamped"):
        return _clamped(cfg, d, hand, inc, stroke)
    kw = {**kwargs, "incidence": inc}
    if "strings" in kw:  # the strung racket is free and at rest, as simulate's
        for dest in ("face_angle", "path_angle"):
            if dest in d:
                raise InputError(
                    f"{CORE_DEST_KEYS[dest]} = {show(d[dest])} ({cfg.source}) is not allowed "
                    "with a string bed: the strung racket is free and at rest"
                )
    else:  # (the bed's histories have their own samples)
        kw["output_step"] = step
    if hand is not None:  # the held racket, as simulate --grip ... --angle ...
        kw.update(hand=hand, shock_window=d.get("hand_shock_window"))
    if stroke is not None:
        return simulate_stroke(model, stroke=stroke, swing=swing, **kw)
    return simulate_oblique(model, swing=swing, **kw)
