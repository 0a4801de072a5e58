"""A run file's VTK series and animation in Python: :meth:`RunConfig.export_vtk` =
``fem-racket export-vtk --config`` and :meth:`RunConfig.animate` = ``fem-racket animate
--config``.

Both commands draw the impact of the file's core tables (frame, ball, contact law, impact,
solver, and a ``[strings]`` bed) at the output step of their own table (``[vtk]``,
``[animate]``: the long options, ``--output-step`` -> ``output_step``), with that table's
drawing options; these functions do the same and write the same files. With a string bed the
series is the strung one (:func:`fem_racket.io.strung_vtk.write_strung_vtk`: frame, ball and
the bed's surface, 101 steps unless ``frames`` says, no ``subdivide`` or ``field``; the
animation draws the bed beside the frame), the bed's histories at their own samples unless the
table gives ``output_step``. Their defaults are :data:`VTK_DEFAULTS` and
:data:`ANIMATE_DEFAULTS` (checked against the parsers by ``tests/io/test_config_commands.py``).
A table or key the commands take no option of (``[hand]``, ``[oblique]``, the swing's keys of
``[impact]``) is refused here rather than dropped.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from fem_racket.io.config_keys import reject_unknown
from fem_racket.io.config_run_keys import run_keys
from fem_racket.validation import InputError, show

__all__ = ["ANIMATE_DEFAULTS", "VTK_DEFAULTS", "animate_file", "vtk_file"]

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any

#: ``fem-racket export-vtk``'s drawing options and defaults.
VTK_DEFAULTS: dict[str, Any] = {
    "out": Path("output") / "impact_vtk",
    "subdivide": 8,
    "frames": None,
    "scale": 1.0,
    "field": "deflection",
    "output_step": 1e-5,
    "overwrite": False,
}
#: ``fem-racket animate``'s drawing options and defaults.
ANIMATE_DEFAULTS: dict[str, Any] = {
    **VTK_DEFAULTS,
    "out": Path("output") / "impact.gif",
    "frames": 100,
    "scale": 10.0,
    "fps": 25.0,
    "size": (960, 400),
}
#: Steps of the strung series unless ``frames`` says (its histories have 801 output times).
STRUNG_FRAMES = 101
#: Keys of the command tables that only set how the command prints.
_PRINT_KEYS = ("quiet",)


def _drawing(cfg: RunConfig, table: str, defaults: dict[str, Any], refused: tuple) -> dict:
    for name in refused:
        if cfg.values.get(name):
            raise InputError(
                f"[{name}] ({cfg.source}) is not allowed with fem-racket "
                f"{'export-vtk' if table == 'vtk' else table}: it draws the head-on impact "
                "of the free racket at rest"
            )
    if cfg.get("impact.racket_speed_m_s", 0.0) != 0.0:  # the commands take no swing options
        raise InputError(  # (a swing of 0 m/s, and its point without one, change nothing)
            f"impact.racket_speed_m_s ({cfg.source}) is not allowed with fem-racket "
            f"{'export-vtk' if table == 'vtk' else table}: it draws the racket at rest"
        )
    own = {k.replace("-", "_"): v for k, v in cfg.table(table).items()}
    reject_unknown(own, [*defaults, *_PRINT_KEYS], table)
    own.update(run_keys(table, own))  # out, overwrite, quiet: checked as the command
    core = {k: v for k, v in cfg.defaults().items() if k == "overwrite"}  # [output] overwrite
    out = {**defaults, **core, **{k: v for k, v in own.items() if k not in _PRINT_KEYS}}
    if isinstance(out.get("size"), str):
        w, h = out["size"].lower().split("x")
        out["size"] = (int(w), int(h))
    return out


def _strung(cfg: RunConfig, table: str, o: dict[str, Any]) -> bool:
    """Whether the file strings the racket; refuse what the strung series does not draw, as
    ``export-vtk`` refuses ``--subdivide`` and ``--field`` with a string bed."""
    if not cfg.values.get("strings"):
        return False
    for key in ("subdivide", "field") if table == "vtk" else ():
        if o[key] != VTK_DEFAULTS[key]:  # (a key at its default changes nothing)
            raise InputError(
                f"{table}.{key} = {show(o[key])} ({cfg.source}) is not allowed with a string bed: "
                "the strung series draws the deflection at the frame's nodes and the bed's vertices"
            )
    return True


def _replace_own(path: Path, o: dict[str, Any], default: Path, files: list[Path]) -> bool:
    """The overwrite of the writes to ``path``, as the commands': ``overwrite`` from the file,
    or their own earlier output at their ``default`` (:mod:`fem_racket.io.config_rerun`)."""
    from fem_racket.io.config_rerun import rerun_overwrite

    return rerun_overwrite(bool(o["overwrite"]), path == default, files)


def vtk_file(cfg: RunConfig, out: Any = None, parameters: dict | None = None) -> Path:
    """Write the VTK series ``export-vtk --config`` writes (into ``out``, else the file's
    ``[vtk] out``, else ``output/impact_vtk``); return the ``.pvd`` path. An existing folder is
    refused before the impact is computed, as the command refuses it: replaced with
    ``overwrite`` in the file, or at the default when it holds an earlier series."""
    from fem_racket.io.config_run import run_file
    from fem_racket.io.vtk import PROVENANCE_NAME, write_vtk_series
    from fem_racket.outputs import check_output_folder

    o = _drawing(cfg, "vtk", VTK_DEFAULTS, ("hand", "oblique"))
    strung = _strung(cfg, "vtk", o)
    out = Path(out or o["out"])
    o["overwrite"] = _replace_own(out, o, VTK_DEFAULTS["out"], [out])
    check_output_folder(out, overwrite=o["overwrite"], marker=PROVENANCE_NAME)
    model, result = run_file(cfg, histories=True, table="vtk")
    if strung:
        from fem_racket.io.strung_vtk import write_strung_vtk

        return write_strung_vtk(
            result,
            model,
            out,
            frames=STRUNG_FRAMES if o["frames"] is None else o["frames"],
            scale=o["scale"],
            overwrite=o["overwrite"],
            parameters=parameters,
        )
    return write_vtk_series(
        result,
        out,
        subdivide=o["subdivide"],
        frames=o["frames"],
        scale=o["scale"],
        field=o["field"],
        overwrite=o["overwrite"],
        parameters=parameters,
        progress=False,
    )


def animate_file(cfg: RunConfig, out: Any = None, parameters: dict | None = None) -> Path:
    """Render the animation ``animate --config`` renders (to ``out``, else the file's
    ``[animate] out``, else ``output/impact.gif``; with a string bed, the bed beside the
    frame); return its path. Existing files are refused before the impact is computed, as the
    command refuses them: replaced with ``overwrite`` in the file, or at the default when they
    are an earlier animation."""
    from fem_racket.io.animate import AnimationOptions, animation_targets, render_animation
    from fem_racket.io.config_run import run_file
    from fem_racket.outputs import check_targets

    o = _drawing(cfg, "animate", ANIMATE_DEFAULTS, ("hand", "oblique"))
    strung = _strung(cfg, "animate", o)
    out = Path(out or o["out"])
    targets = animation_targets(out)
    o["overwrite"] = _replace_own(out, o, ANIMATE_DEFAULTS["out"], [t.path for t in targets])
    check_targets(targets, overwrite=o["overwrite"])
    model, result = run_file(cfg, histories=True, table="animate")
    return render_animation(
        result,
        out,
        AnimationOptions.of(o),
        model=model if strung else None,
        overwrite=o["overwrite"],
        parameters=parameters,
        progress=False,
    )
