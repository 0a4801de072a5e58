"""Offscreen GIF / MP4 animation of an impact, rendered with pyvista (no display needed).

The scene (:mod:`fem_racket.io.animate_scene`): a side view of the racket, the frame coloured by
one of :data:`~fem_racket.io.vtk_series.FRAME_FIELDS`, the ball as a sphere (see
:func:`~fem_racket.io.vtk_series.impact_series` for how it is placed when the deflection is
exaggerated) and, for an impact on the string bed
(:class:`~fem_racket.impact.strung.impact.StrungImpact`), the bed as a deforming surface beside
it (:mod:`fem_racket.io.strung_series`). Each image carries the time in ms, the exaggeration
factors, the contact force and the impact settings. GIFs are written by imageio (Pillow), MP4
(H.264) by imageio-ffmpeg (through pyvista's ``open_movie``, ffmpeg's own messages silenced: a
failure comes back as an exception). A GIF is assembled in memory (pyvista's ``open_gif``
settings, the same bytes) and written by Python, so a full disk is one ``OSError`` at that write
rather than an error Pillow raises again while its writer is garbage-collected.
"""

from __future__ import annotations

import json
import logging
import os
from collections.abc import Mapping
from dataclasses import dataclass, fields
from pathlib import Path
from typing import TYPE_CHECKING, Any

from fem_racket.io.animate_scene import render_frames, renderer
from fem_racket.io.impact_provenance import impact_provenance
from fem_racket.io.vtk_series import check_scale, field_name, impact_series
from fem_racket.outputs import Target, atomic_outputs, check_targets, provenance, sidecar_path
from fem_racket.validation import InputError, check_range, show

if TYPE_CHECKING:
    from fem_racket.frame.model import FrameModel
    from fem_racket.impact.simulate import ImpactResult
    from fem_racket.impact.strung.impact import StrungImpact

__all__ = [
    "ANIMATION_SUFFIXES",
    "FPS_RANGE",
    "AnimationOptions",
    "animation_targets",
    "check_fps",
    "render_animation",
]

log = logging.getLogger(__name__)

ANIMATION_SUFFIXES = (".gif", ".mp4")

#: Playback rates accepted [frames/s]: GIF delays are whole 10 ms (so at most 100 frames/s) in a
#: 16-bit field (a frame lasts at most 655.35 s; below 0.0016 frames/s Pillow fails and leaves an
#: unreadable file); at most 100 s per frame keeps both formats well inside their limits.
FPS_RANGE = (0.01, 100.0)


def check_fps(fps: object) -> float:
    """``fps`` as a float if it lies in :data:`FPS_RANGE`."""
    return check_range("fps", fps, *FPS_RANGE, unit="frames/s")


def animation_targets(path: str | os.PathLike) -> list[Target]:
    """The files an animation writes (the image file, suffix in lower case, and its provenance
    sidecar), after checking the suffix; see :func:`fem_racket.outputs.atomic_outputs`."""
    path = Path(path)
    if path.suffix.lower() not in ANIMATION_SUFFIXES:
        raise InputError(
            f"out = {show(str(path))} is not allowed: must end in {' or '.join(ANIMATION_SUFFIXES)}"
        )
    path = path.with_suffix(path.suffix.lower())
    return [Target(path), Target(sidecar_path(path))]


def check_size(size: tuple[int, int]) -> tuple[int, int]:
    """Validate an image size (width, height) [px]: multiples of 16 (H.264 macro-blocks)."""
    try:
        w, h = (int(v) for v in size)
    except (TypeError, ValueError):
        w = h = -1
    if not all(160 <= v <= 3840 and v % 16 == 0 for v in (w, h)):
        raise InputError(
            f"size = {show(size)} is not allowed: must be WIDTH x HEIGHT in pixels, "
            "each a multiple of 16 in [160, 3840]"
        )
    return w, h


@dataclass(frozen=True)
class AnimationOptions:
    """What the animation draws and how (checked on construction).

    Parameters
    ----------
    field : str
        Frame colouring: a :data:`~fem_racket.io.vtk_series.FRAME_FIELDS` name or its short alias
        (``deflection``, ``slope``, ``velocity``, ``curvature``, ``moment``).
    frames : int
        Images, evenly spread over the output times, first and last included (>= 2).
    fps : float
        Playback rate [frames/s], in :data:`FPS_RANGE`.
    scale : float
        Deflection exaggeration (> 0), written on every image.
    subdivide : int
        Straight segments per finite element.
    size : (int, int)
        Image width and height [px], multiples of 16.
    """

    field: str = "deflection [m]"
    frames: int = 100
    fps: float = 25.0
    scale: float = 10.0
    subdivide: int = 8
    size: tuple[int, int] = (960, 400)

    @classmethod
    def of(cls, options: Mapping[str, Any]) -> AnimationOptions:
        """The options named by its fields in ``options`` (``fem-racket animate``'s argparse
        dests, or a run file's ``[animate]`` table with its defaults), each one required."""
        return cls(**{f.name: options[f.name] for f in fields(cls)})

    def __post_init__(self) -> None:
        object.__setattr__(self, "field", field_name(self.field))
        object.__setattr__(self, "fps", check_fps(self.fps))
        object.__setattr__(self, "size", check_size(self.size))
        object.__setattr__(self, "scale", check_scale(self.scale))


def _strung(result: StrungImpact, model: Any, opts: AnimationOptions) -> tuple[Any, Any, str]:
    from fem_racket.io.strung_series import strung_series

    if model is None:
        raise InputError("model is required with an impact on the string bed: give its frame")
    series, bed = strung_series(
        result, model, subdivide=opts.subdivide, frames=opts.frames, scale=opts.scale
    )
    p = result.point
    caption = (
        f"ball {result.speed:g} m/s at x/L = {p.position:.3f}, y = {p.lateral_m:g} m\n"
        f"{p.strings.pattern} at {p.strings.tension_n:g} N: COR {result.cor:.3f}, "
        f"contact {result.contact_time * 1e3:.2f} ms"
    )
    return series, bed, caption


def render_animation(
    result: ImpactResult | StrungImpact,
    path: str | os.PathLike,
    options: AnimationOptions | None = None,
    *,
    model: FrameModel | None = None,
    overwrite: bool = False,
    parameters: dict[str, Any] | None = None,
    progress: bool | None = None,
) -> Path:
    """Render an impact as a GIF or MP4 offscreen; return the path written.

    A sidecar ``<path>.json`` holds the provenance (software, version, date, the impact's
    settings and results, the animation's settings and its times [s]). Both files are checked
    before the work and written as a set (both or neither); existing ones are replaced only with
    ``overwrite``.

    Parameters
    ----------
    result : ImpactResult or StrungImpact
        A simulation with histories; on the string bed
        (:func:`fem_racket.impact.strung.impact.strung_impact`) the bed is drawn beside the frame.
    path : path
        Output file, ``.gif`` or ``.mp4``.
    options : AnimationOptions, optional
        What is drawn and how (the defaults when None).
    model : FrameModel, optional
        The frame of a strung ``result`` (required with it, refused otherwise: an ImpactResult
        carries its own).
    overwrite : bool
        Replace existing files.
    parameters : dict, optional
        Extra provenance entries.
    progress : bool or None
        A progress bar over the frames on stderr (None: when stderr is a terminal).
    """
    from fem_racket.impact.strung.impact import StrungImpact

    opts = AnimationOptions() if options is None else options
    if not isinstance(opts, AnimationOptions):
        raise InputError(f"options = {opts!r} is not allowed: must be an AnimationOptions")
    targets = check_targets(animation_targets(path), overwrite=overwrite)
    path = targets[0].path
    bed, dashpot = None, "C_CB V_B0"
    if isinstance(result, StrungImpact):
        series, bed, caption = _strung(result, model, opts)
        dashpot = "c_b V"
    else:
        if model is not None:
            raise InputError("model is not allowed with an ImpactResult: it carries its own frame")
        series = impact_series(
            result, subdivide=opts.subdivide, frames=opts.frames, scale=opts.scale
        )
        caption = (
            f"ball {result.impact.speed:g} m/s at x/L = {result.impact.position:.3f}, "
            f"COR {result.cor:.3f}, contact {result.contact_time * 1e3:.2f} ms"
        )
    settings = {
        "field": opts.field,
        "frames": series.n_steps,
        "fps": opts.fps,
        "deflection_scale": series.scale,
        "subdivide": opts.subdivide,
        "size_px": list(opts.size),
        "time_s": series.t.tolist(),
    }
    extra = {**settings, **(parameters or {})}
    if bed is None:
        meta = impact_provenance(result, extra)
    else:
        meta = provenance({**result.summary(), **extra})
    renderer()  # before any temporary exists (see animate_scene.renderer)
    with atomic_outputs(targets, overwrite=overwrite) as (tmp, tmp_json):
        render_frames(series, tmp, field=opts.field, settings=opts, caption=caption, bed=bed,
                      dashpot=dashpot, progress=progress)  # fmt: skip
        tmp_json.write_text(json.dumps(meta, indent=2, default=str) + "\n")
    log.info("wrote %d frames to %s", series.n_steps, path)
    return path
