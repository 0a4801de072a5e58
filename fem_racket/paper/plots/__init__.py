"""Matplotlib figures of the paper's analyses, drawn from
:class:`~fem_racket.paper.figures.data.FigureData`.

Each function takes the figure's data, only draws (the numbers come from
:mod:`fem_racket.paper.figures`) and returns the matplotlib figure, which
:func:`fem_racket.paper.figures.base.write_figure` saves as PNG, SVG or PDF. matplotlib is
imported inside the functions (Agg backend), so ``import fem_racket`` stays light. Axes carry
units; titles carry the paper's figure number. One module per group of figures, named as in
:mod:`fem_racket.paper.figures`.
"""

from fem_racket.paper.plots.histories import impact_behaviour
from fem_racket.paper.plots.inputs import ball_string, frame_modes
from fem_racket.paper.plots.modal import modal_terms, system_modes
from fem_racket.paper.plots.positions import contact_time_position, cor_position
from fem_racket.paper.plots.rigidity import cor_rigidity

__all__ = [
    "ball_string",
    "contact_time_position",
    "cor_position",
    "cor_rigidity",
    "frame_modes",
    "impact_behaviour",
    "modal_terms",
    "system_modes",
]
