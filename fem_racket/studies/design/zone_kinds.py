"""The kinds of impact zone a design study names: a plain tuple importing nothing, so the
command line shows it (``fem-racket COMMAND --help``) without numpy;
:mod:`fem_racket.studies.design.zone` builds the zones (and keeps the name among its own).
"""

from __future__ import annotations

__all__ = ["ZONES"]

#: The zones a design study names: uniform over a range, or a Gaussian about mode 1's node.
ZONES = ("uniform", "node")
