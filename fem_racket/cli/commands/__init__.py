"""The sub-commands of ``fem-racket``, one module each (``vtk`` holds export-vtk and animate).

Each module has ``add_arguments(parser)``, adding its command's options, and ``run(args) -> int``
(``vtk``: one of each per command); :data:`COMMANDS` names each command, its summary and its
module, and ``cli.build_parser`` adds them all in one loop (a description, if any, is the
second paragraph of the module's docstring). ``fem-racket --help`` reads this table alone,
importing no command's module. A command parses, calls one library function and prints.
"""

from __future__ import annotations

from fem_racket.cli.parser import Command

__all__ = ["COMMANDS"]

#: Sub-command -> its :class:`~fem_racket.cli.parser.Command`, in the order ``--help`` lists
#: them; a command's options and run are in its module of this package.
COMMANDS = {
    command.name: command
    for command in (
        Command("simulate", "simulate one ball impact on the racket"),
        Command("modes", "free-free modal analysis of the frame"),
        Command("sweep", "simulate a grid of impacts and save one netCDF dataset", described=True),
        Command(
            "map", "apparent COR and ball speed along the frame, with sweet spots", described=True
        ),
        Command(
            "fit",
            "a racket frame from length, mass, balance, swing weight (and f1) -> mesh file",
            described=True,
        ),
        Command(
            "customise",
            "least lead tape reaching swing weight, balance, twistweight, mass targets",
            described=True,
        ),
        Command(
            "closest",
            "rackets of a CSV list nearest a target, each with its least lead",
            described=True,
        ),
        Command(
            "compare",
            "rackets side by side: specs, maps, sweet spots, shock, contact time, B - A",
            described=True,
        ),
        Command(
            "export-vtk",
            "write the impact as a VTK time series (.pvd + .vtu) for ParaView",
            "vtk",
            options="add_export_arguments",
            run="run_export",
        ),
        Command(
            "animate",
            "render the impact offscreen as a GIF or MP4",
            "vtk",
            options="add_animate_arguments",
            run="run_animate",
        ),
        Command(
            "refine", "mesh-refinement study: frequencies vs the exact beam, COR and contact time"
        ),
        Command(
            "reproduce",
            "reproduce every figure of Kawazoe & Kanda (1997) and write REPRODUCTION.md",
            described=True,
        ),
        Command("calibrate", "fit a ball/string law to published targets"),
        Command("optimize", "optimum racket design (scipy, pymoo NSGA-II)"),
        Command("sensitivity", "Sobol sensitivity of a design objective (SALib)"),
        Command("config", "print an example run file (TOML) or check one"),
    )
}
