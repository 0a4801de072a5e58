"""The sub-commands of ``fem-racket``, one module each (``vtk`` holds export-vtk and animate).

Each module declares ``COMMANDS``, its :class:`fem_racket.cli.parser.Command` (name, summary,
the function adding its options, the function running it, and the module's docstring when its
second paragraph is the ``--help`` description), which ``cli.build_parser`` adds in one loop
(see :data:`fem_racket.cli.COMMANDS`); a command parses, calls one library function and prints.
"""
