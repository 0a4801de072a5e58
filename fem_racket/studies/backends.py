"""Where a sweep's chunks run, by name: a plain tuple importing nothing, so the command line
shows it (``fem-racket COMMAND --help``) without numpy; :mod:`fem_racket.studies.executors`
runs them (and keeps the name among its own).
"""

from __future__ import annotations

__all__ = ["BACKENDS"]

#: Where sweep chunks run (:mod:`fem_racket.studies.executors`).
BACKENDS = ("serial", "processes", "dask")
