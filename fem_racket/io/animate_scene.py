"""The animation's scene and its frames (pyvista, offscreen): the racket's side view and, with a
string bed, the bed's deforming surface beside it.

Side view of the racket (x along the frame to the right, deflection z upwards), the frame drawn
as a thick line coloured by one of :data:`~fem_racket.io.vtk_series.FRAME_FIELDS` on its true
values, the undeformed frame as a thin grey reference line, on a dark background, and the ball as
a sphere. With a bed (:class:`~fem_racket.io.strung_series.BedSeries`) the image is split: the
side view on the left, and on the right the bed's triangles seen obliquely from the ball's side,
coloured by their deflection [m] on a symmetric scale, with the ball; the bed's deflection is
drawn exaggerated ``bed_scale`` times (at most the frame's, so that its largest deflection is a
quarter of the head's width), written on every image. The cameras are fixed over the whole
animation and frame the motion of every step.

Rendering uses VTK's EGL window when ``VTK_DEFAULT_OPENGL_WINDOW`` is not set (offscreen, no X
server; Mesa's software EGL is enough).
"""

from __future__ import annotations

import io
import os
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.extras import require
from fem_racket.io.vtk_series import ImpactSeries
from fem_racket.outputs import deferred_interrupts
from fem_racket.progress import progress_bar

__all__ = ["render_frames", "renderer"]

#: Tennis-ball "optic yellow"; a dark background so that coolwarm's light-grey zero stays visible.
BALL_COLOUR = "#cfdc2a"
BACKGROUND = "#333333"
TEXT_COLOUR = "#f0f0f0"
REFERENCE_COLOUR = "#8a8a8a"
#: Share of the image's width the side view takes when the bed is drawn beside it.
SIDE_SHARE = 0.62


def renderer() -> tuple[Any, Any]:
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


def _why(i: int, force: np.ndarray, dashpot: str) -> str:
    """Why the contact force is not zero at t = 0 and negative at the end (README, model)."""
    if i == 0 and force[0] > 0:
        return f" (the dashpot, {dashpot}, acts at once)"
    if force[i] < 0:
        return " (the dashpot pulls while the spring relaxes)"
    return ""


def _text(pl: Any, text: str, font_size: int, x: int, y: int) -> Any:
    """A 2-D text actor at pixel (x, y) (its top-left corner unless re-justified)."""
    actor = pl.add_text(text, position=(x, y), font_size=font_size, color=TEXT_COLOUR)
    actor.GetTextProperty().SetVerticalJustificationToTop()
    return actor


def _bar(title: str, x: float, width: float) -> dict[str, Any]:
    return {
        "title": title, "color": TEXT_COLOUR, "fmt": "%.3g", "n_labels": 5, "vertical": True,
        "position_x": x, "position_y": 0.14, "width": width, "height": 0.62,
        "title_font_size": 14, "label_font_size": 12,
    }  # fmt: skip


class _Bed:
    """The bed's viewport: its surface and the ball, updated per step."""

    def __init__(self, pl: Any, pv: Any, series: ImpactSeries, bed: Any, size: tuple[int, int]):
        self.bed = bed
        w = bed.deflection
        vmax = float(np.abs(w).max()) or 1.0
        span = float(np.ptp(bed.xy[:, 1]))
        self.scale = min(series.scale, 0.25 * span / vmax)
        cells = np.column_stack([np.full(len(bed.triangles), 3), bed.triangles]).ravel()
        pts = np.column_stack([bed.xy, self.scale * w[0]])
        tri = np.full(len(bed.triangles), pv.CellType.TRIANGLE)
        self.surface = pv.UnstructuredGrid(cells, tri, pts)
        self.surface.point_data["bed deflection [m]"] = w[0]
        pl.add_mesh(
            self.surface, scalars="bed deflection [m]", cmap="coolwarm", clim=(-vmax, vmax),
            show_edges=True, edge_color="#555555", line_width=0.5,
            scalar_bar_args=_bar("bed deflection [m]", 0.80, 0.07),
        )  # fmt: skip
        self.radius = series.ball_radius
        self.ball = pv.Sphere(radius=self.radius, center=(series.x_impact, series.ball_y, 0.0))
        self.ball_points0 = np.array(self.ball.points)
        pl.add_mesh(self.ball, color=BALL_COLOUR, smooth_shading=True, specular=0.3)
        self.step(0)
        centre = np.append(bed.xy.mean(axis=0), 0.0)
        extent = float(np.ptp(bed.xy[:, 0]))
        pl.camera.focal_point = tuple(centre)
        pl.camera.position = tuple(centre + extent * np.array([-1.2, -1.6, -1.1]))
        pl.camera.up = (0.0, 0.0, -1.0)
        pl.camera.zoom(1.1)
        margin = max(8, int(0.015 * size[0]))
        _text(pl, f"string bed, deflection \u00d7 {self.scale:.3g}", 12, margin, size[1] - margin)

    def step(self, i: int) -> None:
        w = self.bed.deflection[i]
        self.surface.points[:, 2] = self.scale * w
        self.surface.point_data["bed deflection [m]"] = w
        # the ball rests on the drawn bed at the contact point (its compression not drawn)
        z = self.scale * self.bed.contact[i] - self.radius
        self.ball.points = self.ball_points0 + (0.0, 0.0, z)


def render_frames(
    series: ImpactSeries,
    path: Path,
    *,
    field: str,
    settings: Any,
    caption: str,
    bed: Any = None,
    dashpot: str = "C_CB V_B0",
    progress: bool | None = None,
) -> None:
    """Render every step of ``series`` (and ``bed``) into ``path`` (.gif or .mp4), the frame
    coloured by ``field``; ``settings``: fps and size (:class:`~fem_racket.io.animate.
    AnimationOptions`); ``dashpot``: the damper named when the force starts above zero."""
    imageio, pv = renderer()  # imported already (render_animation)
    fps, size = settings.fps, settings.size
    cell = field in series.cell_fields
    values = (series.cell_fields if cell else series.point_fields)[field]
    vmax = float(np.abs(values).max()) or 1.0
    length = float(series.x[-1])

    gif = io.BytesIO() if path.suffix == ".gif" else None
    with deferred_interrupts():  # VTK calls back into Python: a signal waits for a frame's end
        if bed is None:
            pl = pv.Plotter(off_screen=True, window_size=list(size))
        else:
            pl = pv.Plotter(off_screen=True, window_size=list(size), shape=(1, 2),
                            col_weights=[SIDE_SHARE, 1.0 - SIDE_SHARE], border=False)  # fmt: skip
    try:
        with deferred_interrupts():
            side = size if bed is None else (int(SIDE_SHARE * size[0]), size[1])
            pl.set_background(BACKGROUND)
            if bed is not None:
                pl.subplot(0, 1)
                pl.set_background(BACKGROUND)
                bed_view = _Bed(pl, pv, series, bed, (size[0] - side[0], size[1]))
                pl.subplot(0, 0)
            pl.add_mesh(
                pv.Line((0.0, 0.0, 0.0), (length, 0.0, 0.0)), color=REFERENCE_COLOUR, line_width=2
            )
            frame = series.frame_grid(0)
            pl.add_mesh(
                frame, scalars=field, preference="cell" if cell else "point", cmap="coolwarm",
                clim=(-vmax, vmax), line_width=9, render_lines_as_tubes=True,
                scalar_bar_args=_bar(field, 0.86, 0.05),
            )  # fmt: skip
            # The title sits above the bar; keep it clear of the top tick label.
            pl.scalar_bars[field].SetVerticalTitleSeparation(int(0.04 * size[1]))
            ball = series.ball_grid(0)
            ball_points0 = np.array(ball.points)
            pl.add_mesh(ball, color=BALL_COLOUR, smooth_shading=True, specular=0.3, scalars=None)
            pl.add_point_labels(
                np.array([[0.0, 0.0, 0.0], [length, 0.0, 0.0]]), ["grip end", "tip"],
                font_size=14, text_color=TEXT_COLOUR, shape=None, show_points=False,
                always_visible=True,
            )  # fmt: skip
            width, height = side
            margin = max(8, int(0.015 * width))  # texts stand off the image's edges
            scale_text = _text(pl, f"deflection \u00d7 {series.scale:g}", 12, margin, height)
            scale_text.SetPosition(width - margin, height - margin)
            scale_text.GetTextProperty().SetJustificationToRight()
            _camera(pl, series, side)
            if gif is not None:  # pyvista's open_gif settings, into memory (animate's docstring)
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
                if bed is not None:
                    bed_view.step(i)
                time_text.SetInput(f"t = {series.t[i] * 1e3:5.3f} ms")
                why = _why(i, force, dashpot)
                caption_text.SetInput(f"{caption}\ncontact force {force[i]:5.0f} N{why}")
                pl.write_frame()
    finally:
        pl.close()
    if gif is not None:
        path.write_bytes(gif.getvalue())
