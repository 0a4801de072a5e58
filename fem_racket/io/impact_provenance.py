"""The provenance of every file written from one impact: the request and what was used.

``parameters`` (the options as given, a command line after its run file was applied) can differ
from what the run used: ``--modes 80`` keeps the 40 flexible modes a 20-element mesh has, and
``zeta`` / ``K_CB`` left unset are derived from the clamped COR and the speed. So the provenance
records both: ``"parameters"`` the request, ``"used"`` :meth:`ImpactResult.settings` (the solver
that ran and its tolerances, modes kept, K_CB, zeta, C_CB, ...: the same keys and values as
``fem-racket simulate --json``, numbers as :func:`fem_racket.outputs.json_ready` writes them)
and ``"results"`` the outcome (COR, contact time, ...).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

from fem_racket.outputs import json_ready, provenance

if TYPE_CHECKING:
    from fem_racket.impact.simulate import ImpactResult

__all__ = ["impact_provenance"]


def impact_provenance(
    result: ImpactResult, parameters: Mapping[str, Any] | None = None
) -> dict[str, Any]:
    """:func:`fem_racket.outputs.provenance` of ``parameters`` plus ``"used"`` and ``"results"``
    of the impact ``result``."""
    meta = provenance(parameters)
    used = result.settings()
    meta["used"] = json_ready(used)
    meta["results"] = json_ready({k: v for k, v in result.summary().items() if k not in used})
    return meta
