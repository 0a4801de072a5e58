"""The reproduction's named values that ``fem-racket reproduce --help`` shows before any work:
plain names, importing nothing (each has this one home;
:mod:`fem_racket.paper.config_reproduce` imports them from here).
"""

from __future__ import annotations

__all__ = ["DEFAULT_OUT", "DEFAULT_REPORT"]

#: Where the figures and the report go by default.
DEFAULT_OUT = "output/paper"
DEFAULT_REPORT = "REPRODUCTION.md"
