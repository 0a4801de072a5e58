"""The options of a mesh-refinement study (:func:`fem_racket.studies.refine.refinement_study`):
its defaults and :class:`RefineOptions`."""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from fem_racket.frame.constants import DEFAULT_MODES

__all__ = [
    "DEFAULT_ELEMENTS",
    "DEFAULT_GRADING",
    "DEFAULT_POSITIONS",
    "FAMILIES",
    "RefineOptions",
    "graded",
]

#: Element counts of the meshes compared.
DEFAULT_ELEMENTS = (5, 10, 20, 40, 80, 160, 320)
#: The paper's three impact points (Figs 5-7): grip side, middle (near the node), top side.
DEFAULT_POSITIONS = (0.6, 0.75, 0.9)
FAMILIES = ("uniform", "graded")
#: Cell-size ratio of graded meshes (largest / smallest in a segment).
DEFAULT_GRADING = 4.0


@dataclass(frozen=True)
class RefineOptions:
    """The options of :func:`refinement_study` besides the frame and the element counts (see
    there). ``grading`` None is not given (:data:`DEFAULT_GRADING` for the graded family; given
    at any value, the uniform family refuses it)."""

    family: str = "uniform"
    n_modes: int = 4
    positions: Sequence[float] = DEFAULT_POSITIONS
    speed: float = 20.0
    grading: float | None = None
    impact_nodes: bool = False
    impact_modes: int = DEFAULT_MODES
    progress: bool | None = None
    ball_mass: float | None = None
    kcb: float | None = None
    zeta: float | None = None
    separation: str | None = None


def graded(options: dict[str, Any], family: str, chosen: str) -> dict[str, Any]:
    """The keywords of one ``family``'s study from those of a run of the ``chosen`` family
    ("uniform", "graded" or "both"): ``options`` with ``family``, without ``grading`` for the
    uniform study of a run of both (the graded one uses it; the uniform family alone refuses
    it)."""
    out = options | {"family": family}
    if family == "uniform" and chosen == "both":
        out.pop("grading", None)
    return out
