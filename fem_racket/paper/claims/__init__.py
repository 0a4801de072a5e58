"""The statements of Kawazoe & Kanda (1997), sections 2-6, beside the values this project computes.

:func:`build_claims` takes the scalar values of every figure (``{"fig08": {...}, ...}``, see
:mod:`fem_racket.paper.figures`) and returns one :class:`Claim` per statement, with a verdict
decided by a check written beside it: the tolerance is the precision the paper prints (one unit of
its last digit), or the paper's own word read as a number ("almost no difference": within 5 %).
"""

from __future__ import annotations

from fem_racket.paper.claims.base import AGREES, DIFFERS, NOT_CHECKABLE, Claim
from fem_racket.paper.claims.model import model_claims
from fem_racket.paper.claims.results import result_claims

__all__ = ["AGREES", "DIFFERS", "NOT_CHECKABLE", "Claim", "build_claims"]


def build_claims(values: dict[str, dict[str, float]]) -> list[Claim]:
    """Every checked statement of the paper, in its order.

    Parameters
    ----------
    values : dict
        Figure key (``"fig08"``) -> that figure's scalar values; every figure of
        :data:`fem_racket.paper.figures.FIGURES` is needed.
    """
    return model_claims(values) + result_claims(values)
