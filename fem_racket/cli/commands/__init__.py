"""The sub-commands of ``fem-racket``, one module each (``vtk`` holds export-vtk and animate).

Each module has ``add_arguments(parser)``, adding its command's options, and ``run(args) -> int``
(``vtk``: one of each per command); :data:`fem_racket.cli.COMMANDS` names the command, its
summary and its module, and ``cli.build_parser`` adds them all in one loop (a description, if
any, is the second paragraph of the module's docstring). A command parses, calls one library
function and prints.
"""
