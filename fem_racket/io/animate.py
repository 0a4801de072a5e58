"""Offscreen GIF / MP4 animation of an impact, rendered with pyvista (no display needed).

Side view of the racket (x along the frame to the right, deflection z upwards), the frame drawn
as a thick line coloured by one of :data:`~fem_racket.io.vtk_series.FRAME_FIELDS` on its true
values, the undeformed frame as a thin grey reference line, on a dark background, and the ball as
a sphere (see :func:`~fem_racket.io.vtk_series.impact_series` for how it is placed when the
deflection is exaggerated).
Each image carries the time in ms, the exaggeration factor, the contact force and the impact
settings. The camera is fixed over the whole animation and frames the motion of every step.

Rendering uses VTK's EGL window when ``VTK_DEFAULT_OPENGL_WINDOW`` is not set (offscreen, no X
server; Mesa's software EGL is enough). GIFs are written by imageio (Pillow), MP4 (H.264) by
imageio-ffmpeg (through pyvista's ``open_movie``, ffmpeg's own messages silenced: a failure
comes back as an exception). A GIF is assembled in memory (pyvista's ``open_gif`` settings, the
same bytes) and written by Python, so a full disk is one ``OSError`` at that write rather than an
error Pillow raises again while its writer is garbage-collected.
"""

from __future__ import annotations

import io
import json
import logging
import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from fem_racket.extras import require
from fem_racket.io.impact_provenance import impact_provenance
from fem_racket.io.vtk_series import ImpactSeries, field_name, impact_series
from fem_racket.outputs import (
    Target,
    atomic_outputs,
    check_targets,
    deferred_interrupts,
    sidecar_path,
)
from fem_racket.progress import progress_bar
from fem_racket.validation import InputError, check_range, show

if TYPE_CHECKING:
    from fem_racket.impact.simulate import ImpactResult

__all__ = ["ANIMATION_SUFFIXES", "FPS_RANGE", "animation_targets", "check_fps", "render_animation"]

log = logging.getLogger(__name__)

ANIMATION_SUFFIXES = (".gif", ".mp4")

#: Playback rates accepted [frames/s]: GIF delays are whole 10 ms (so at most 100 frames/s) in a
#: 16-bit field (a frame lasts at most 655.35 s; below 0.0016 frames/s Pillow fails and leaves an
#: unreadable file); at most 100 s per frame keeps both formats well inside their limits.
FPS_RANGE = (0.01, 100.0)

#: Tennis-ball "optic yellow"; a dark background so that coolwarm's light-grey zero stays visible.
BALL_COLOUR = "#cfdc2a"
BACKGROUND = "#333333"
TEXT_COLOUR = "#f0f0f0"
REFERENCE_COLOUR = "#8a8a8a"


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


def _renderer() -> tuple[Any, Any]:
    """imageio and pyvista, VTK set to render offscreen with EGL.

    Imported with interruptions deferred, before any temporary output is made: a signal in the
    middle of VTK's import ended in an ImportError with a traceback, or a crash inside VTK that
    left the temporaries behind (13 of 30 runs interrupted within 50 ms of the temporaries
    appearing, before this).
    """
    # DESIGN.md section 7: EGL renders offscreen without an X server and avoids the X warning.
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    with deferred_interrupts():
        imageio = require("imageio", "render_animation (animate)")
        pyvista = require("pyvista", "render_animation (animate)")
        require("pyvista.plotting", "render_animation")  # pyvista imports it on first Plotter

    return imageio, pyvista


def _camera(pl: Any, series: ImpactSeries, size: tuple[int, int]) -> None:
    """Fixed side view framing every step (parallel projection, x right, z up)."""
    length = float(series.x[-1])
    zf = series.scale * series.point_fields["deflection [m]"]
    r = series.ball_radius
    z_lo = min(float(zf.min()), float(series.ball_z.min()) - r)
    z_hi = max(float(zf.max()), float(series.ball_z.max()) + r)
    centre = np.array([0.5 * length, 0.0, 0.5 * (z_lo + z_hi)])
    aspect = size[0] / size[1]
    # parallel_scale is half the view height [m]; 40 % margin for the texts and colour bar.
    half = 1.4 * max(0.5 * (z_hi - z_lo), 0.5 * length / (0.8 * aspect))
    centre[0] += 0.12 * half * aspect  # room for the colour bar on the right
    pl.camera.SetParallelProjection(True)
    pl.camera.focal_point = tuple(centre)
    pl.camera.position = tuple(centre - np.array([0.0, 10.0 * length, 0.0]))
    pl.camera.up = (0.0, 0.0, 1.0)
    pl.camera.parallel_scale = half
    pl.camera.clipping_range = (1.0 * length, 20.0 * length)


def _why(i: int, force: np.ndarray) -> str:
    """Why the contact force is not zero at t = 0 and negative at the end (README, model)."""
    if i == 0 and force[0] > 0:
        return " (the dashpot, C_CB V_B0, acts at once)"
    if force[i] < 0:
        return " (the dashpot pulls while the spring relaxes)"
    return ""


def _text(pl: Any, text: str, font_size: int, x: int, y: int) -> Any:
    """A 2-D text actor at pixel (x, y) (its top-left corner unless re-justified)."""
    actor = pl.add_text(text, position=(x, y), font_size=font_size, color=TEXT_COLOUR)
    actor.GetTextProperty().SetVerticalJustificationToTop()
    return actor


def _render(
    series: ImpactSeries,
    path: Path,
    *,
    field: str,
    fps: float,
    size: tuple[int, int],
    caption: str,
    progress: bool | None = None,
) -> None:
    imageio, pv = _renderer()  # imported already (render_animation)

    cell = field in series.cell_fields
    values = (series.cell_fields if cell else series.point_fields)[field]
    vmax = float(np.abs(values).max()) or 1.0
    length = float(series.x[-1])

    gif = io.BytesIO() if path.suffix == ".gif" else None
    with deferred_interrupts():  # VTK calls back into Python: a signal waits for a frame's end
        pl = pv.Plotter(off_screen=True, window_size=list(size))
    try:
        with deferred_interrupts():
            pl.set_background(BACKGROUND)
            pl.add_mesh(
                pv.Line((0.0, 0.0, 0.0), (length, 0.0, 0.0)), color=REFERENCE_COLOUR, line_width=2
            )
            frame = series.frame_grid(0)
            pl.add_mesh(
                frame,
                scalars=field,
                preference="cell" if cell else "point",
                cmap="coolwarm",
                clim=(-vmax, vmax),
                line_width=9,
                render_lines_as_tubes=True,
                scalar_bar_args={
                    "title": field,
                    "color": TEXT_COLOUR,
                    "fmt": "%.3g",
                    "n_labels": 5,
                    "vertical": True,
                    "position_x": 0.86,
                    "position_y": 0.14,
                    "width": 0.05,
                    "height": 0.62,
                    "title_font_size": 14,
                    "label_font_size": 12,
                },
            )
            # The title sits above the bar; keep it clear of the top tick label.
            pl.scalar_bars[field].SetVerticalTitleSeparation(int(0.04 * size[1]))
            ball = series.ball_grid(0)
            ball_points0 = np.array(ball.points)
            pl.add_mesh(ball, color=BALL_COLOUR, smooth_shading=True, specular=0.3, scalars=None)
            pl.add_point_labels(
                np.array([[0.0, 0.0, 0.0], [length, 0.0, 0.0]]),
                ["grip end", "tip"],
                font_size=14,
                text_color=TEXT_COLOUR,
                shape=None,
                show_points=False,
                always_visible=True,
            )
            width, height = size
            margin = max(8, int(0.015 * width))  # texts stand off the image's edges
            scale_text = _text(pl, f"deflection \u00d7 {series.scale:g}", 12, margin, height)
            scale_text.SetPosition(width - margin, height - margin)
            scale_text.GetTextProperty().SetJustificationToRight()
            _camera(pl, series, size)
            if gif is not None:  # pyvista's open_gif settings, into memory (see the docstring)
                pl.mwriter = imageio.get_writer(
                    gif, format=".gif", mode="I", loop=0, palettesize=256, subrectangles=False,
                    duration=1000.0 / fps,
                )  # fmt: skip
            else:
                pl.open_movie(str(path), framerate=fps, quality=7, ffmpeg_log_level="quiet")
            force = series.ball_fields["contact force [N]"]
            time_text = _text(pl, "", 14, margin, height - margin)
            caption_text = _text(pl, "", 10, margin, margin)
            caption_text.GetTextProperty().SetVerticalJustificationToBottom()
        steps = progress_bar(range(series.n_steps), desc="animate", unit="frame", enabled=progress)
        for i in steps:
            with deferred_interrupts():
                frame.points = series.frame_points(i)
                target = frame.cell_data if cell else frame.point_data
                target[field] = values[i]
                ball.points = ball_points0 + (0.0, 0.0, series.ball_z[i] - series.ball_z[0])
                time_text.SetInput(f"t = {series.t[i] * 1e3:5.3f} ms")
                caption_text.SetInput(f"{caption}\ncontact force {force[i]:5.0f} N{_why(i, force)}")
                pl.write_frame()
    finally:
        pl.close()
    if gif is not None:
        path.write_bytes(gif.getvalue())


def render_animation(
    result: ImpactResult,
    path: str | os.PathLike,
    *,
    field: str = "deflection [m]",
    frames: int = 100,
    fps: float = 25.0,
    scale: float = 10.0,
    subdivide: int = 8,
    size: tuple[int, int] = (960, 400),
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
    result : ImpactResult
        A simulation with histories.
    path : path
        Output file, ``.gif`` or ``.mp4``.
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
    overwrite : bool
        Replace existing files.
    parameters : dict, optional
        Extra provenance entries.
    progress : bool or None
        A progress bar over the frames on stderr (None: when stderr is a terminal).
    """
    targets = check_targets(animation_targets(path), overwrite=overwrite)
    path = targets[0].path
    field = field_name(field)
    fps = check_fps(fps)
    size = check_size(size)
    series = impact_series(result, subdivide=subdivide, frames=frames, scale=scale)
    caption = (
        f"ball {result.impact.speed:g} m/s at x/L = {result.impact.position:.3f}, "
        f"COR {result.cor:.3f}, contact {result.contact_time * 1e3:.2f} ms"
    )
    settings = {
        "field": field,
        "frames": series.n_steps,
        "fps": fps,
        "deflection_scale": series.scale,
        "subdivide": subdivide,
        "size_px": list(size),
        "time_s": series.t.tolist(),
    }
    meta = impact_provenance(result, {**settings, **(parameters or {})})
    _renderer()  # before any temporary exists (see _renderer)
    with atomic_outputs(targets, overwrite=overwrite) as (tmp, tmp_json):
        _render(series, tmp, field=field, fps=fps, size=size, caption=caption, progress=progress)
        tmp_json.write_text(json.dumps(meta, indent=2) + "\n")
    log.info("wrote %d frames to %s", series.n_steps, path)
    return path
