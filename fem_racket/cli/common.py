"""What the commands share, in one place to import from: options, run files, output and notes.

The options live by concept in :mod:`fem_racket.cli.options`: ``frame`` (the frame), ``impact``
(ball, swing, solver), ``laws``, ``output`` (``--out``, JSON), ``runfile`` (``--config``); the
notes and digits in :mod:`fem_racket.cli.text`, the parser in :mod:`fem_racket.cli.parser`.

Conventions every command follows (so a new command plugs in with a few lines):

- its module has ``add_arguments(parser)`` and ``run(args) -> int``, and one line of
  :data:`fem_racket.cli.commands.COMMANDS` (:class:`fem_racket.cli.parser.Command`) names it,
  with its summary; with ``described=True`` the second paragraph of the module's docstring is
  its ``--help`` description, one text for readers of the code and of ``--help``.
- ``add_config_option(p)`` gives it ``--config run.toml`` (a TOML run file, see
  :mod:`fem_racket.io.config`); :func:`apply_config`, called once by ``cli.main``, fills the options
  the command line did not give from the file. Precedence: command line > the command's own
  table (``[sweep]``, ``[vtk]`` ...) > the core tables (``[frame]``, ``[impact]`` ...) > built-in
  defaults. The command's table takes its long options as keys (``--power-fraction`` ->
  ``power_fraction``), checked and converted as on the command line.
- ``add_output_options(p, default)`` gives it ``--out FILE`` and ``--overwrite``; write through
  :func:`fem_racket.outputs.atomic_output` (check the path with ``check_output_path`` *before* the
  work) and put :func:`run_parameters` into the file's :func:`fem_racket.outputs.provenance`.
"""

from __future__ import annotations

from fem_racket.cli.options.frame import (
    MESH_EXCLUSIVE,
    add_ei_options,
    add_elements_option,
    add_frame_options,
    add_mesh_option,
    build_model,
    frame_from_args,
)
from fem_racket.cli.options.impact import (
    DEFAULT_OUTPUT_STEP,
    add_impact_options,
    add_output_step_option,
    add_solver_options,
    add_speed_option,
    add_swing_options,
    check_output_step,
    impact_kwargs,
    swing_from_args,
    swing_kwargs,
)
from fem_racket.cli.options.lists import number_list
from fem_racket.cli.options.output import (
    add_output_options,
    print_json,
    print_written,
    run_parameters,
    write_json,
    write_text,
)
from fem_racket.cli.options.runfile import add_config_option, apply_config
from fem_racket.cli.parser import OneLineErrorParser
from fem_racket.cli.text import note, note_modes, significant

__all__ = [
    "DEFAULT_OUTPUT_STEP",
    "MESH_EXCLUSIVE",
    "OneLineErrorParser",
    "add_config_option",
    "add_ei_options",
    "add_elements_option",
    "add_frame_options",
    "add_impact_options",
    "add_mesh_option",
    "add_output_options",
    "add_solver_options",
    "add_speed_option",
    "add_swing_options",
    "add_output_step_option",
    "apply_config",
    "build_model",
    "check_output_step",
    "frame_from_args",
    "impact_kwargs",
    "note",
    "note_modes",
    "number_list",
    "print_json",
    "print_written",
    "run_parameters",
    "significant",
    "swing_from_args",
    "swing_kwargs",
    "write_json",
    "write_text",
]
