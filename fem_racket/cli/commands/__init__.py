"""The sub-commands of ``fem-racket``, one module each (``vtk`` holds export-vtk and animate).

Each module exposes ``register(subparsers)``, which adds its command and sets ``func(args) -> int``
(see :data:`fem_racket.cli.COMMANDS`); a command parses, calls one library function and prints.
"""
