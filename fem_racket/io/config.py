"""TOML run configuration: a whole run (frame, ball, ball/string law, impact, solver, output).

A run file has fixed *core* tables, each key with its unit in its name::

    [frame]    preset | ei1_n_m2, ei2_n_m2 | [[frame.segments]] | mesh ; elements ; [[frame.lead]]
    [ball]     mass_kg
    [contact]  kcb_n_m, zeta | clamped_cor      (the compound ball/string law, eqs 1-4)
               law, and that law's parameters (hc_alpha_s_m, k1_n_m_n, ... as in JSON outputs)
    [impact]   position_x_over_l, offset_m, speed_m_s, racket_speed_m_s, reference_x_over_l,
               pivot_m
    [hand]     grip, mass_kg, grip_start_m, grip_end_m, stiffness_n_m2, damping_n_s_m2,
               inertia_kg_m2, shock_window_s   (any key: the racket held in a hand; simulate)
    [strings]  tension_n, pattern, head_area_cm2 | head_length_m, head_width_m, string, edge,
               stretch
               (any key: the string bed replaces the lumped K_CB; simulate, export-vtk, animate)
    [oblique]  angle_deg, spin_rpm, friction, ball_inertia, ball_radius_m, compliance_ratio,
               side_angle_deg, side_spin_rpm, clamped, face_angle_deg, path_angle_deg
               (any key: the oblique, spinning ball; simulate, held too; the axes of sweep, map)
    [solver]   name (auto, exact, general, cvode, bdf, as --solver), separation, basis, modes,
               tolerance, rtol, atol, t_max_s
    [output]   out, overwrite

and optional *command* tables (``[simulate]``, ``[modes]``, ``[sweep]``, ``[refine]``, ``[vtk]``
for ``export-vtk``, ``[animate]``, ``[reproduce]`` ...) whose keys are the long options of that
command (``--power-fraction`` -> ``power_fraction``); the command checks them when it reads the
file (see :func:`fem_racket.cli.common.apply_config`). Every key is optional: a missing key keeps
the built-in default. Unknown tables and keys are errors with a "did you mean"; a wrong type or an
out-of-range value is a one-line :class:`~fem_racket.validation.InputError` naming the dotted key,
e.g. ``run.toml: impact.speed_m_s = -3 m/s is not allowed: must be a finite number > 0``.

Relative paths in the file (``frame.mesh``) are relative to the file's folder; ``output.out`` is
relative to the working directory, like the command line's ``--out``.

:func:`load_config` gives a :class:`RunConfig`: the checked file
(:class:`~fem_racket.io.config_file.RunFile`) with a method per command that takes ``--config``
(:class:`~fem_racket.io.config_commands.CommandMethods`).
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any

from fem_racket.io.config_commands import CommandMethods
from fem_racket.io.config_example import example_config
from fem_racket.io.config_file import RunFile, load_run_file, parse_run_file, toml_value

__all__ = [
    "RunConfig",
    "example_config",
    "load_config",
    "parse_config",
    "toml_value",
]


@dataclass(frozen=True)
class RunConfig(RunFile, CommandMethods):
    """A checked run configuration (:class:`~fem_racket.io.config_file.RunFile`: ``values``,
    ``tables``, ``source``) with a method per command that takes ``--config``:
    ``load_config(f).simulate()`` is ``fem-racket simulate --config f``, likewise ``sweep``,
    ``map``, ``refine``, ``export_vtk``, ``animate``, ``optimize``, ``sensitivity``, ``modes``,
    ``fit``, ``customise``, ``closest``, ``compare`` and ``calibrate``
    (:class:`~fem_racket.io.config_commands.CommandMethods`)."""


def _config(checked: RunFile) -> RunConfig:
    return RunConfig(checked.values, checked.tables, checked.source)


def parse_config(
    text: str, source: str | os.PathLike | None = None, *, command_tables: Any = None
) -> RunConfig:
    """The :class:`RunConfig` of the TOML ``text`` of a run file, checked (``source`` names it
    in errors and anchors paths); see :func:`~fem_racket.io.config_file.parse_run_file`."""
    return _config(parse_run_file(text, source, command_tables=command_tables))


def load_config(path: str | os.PathLike, *, command_tables: Any = None) -> RunConfig:
    """Read and check the run file ``path``; see :func:`parse_config`."""
    return _config(load_run_file(path, command_tables=command_tables))
