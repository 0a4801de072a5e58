"""The sub-commands of ``fem-racket``, one module each (``vtk`` holds export-vtk and animate).

Each module exposes ``register(subparsers)``, which adds its command with
:func:`fem_racket.cli.parser.add_command` (a description, if any, is the second paragraph of the
module's docstring) and sets ``func(args) -> int`` (see :data:`fem_racket.cli.COMMANDS`); a
command parses, calls one library function and prints.
"""
