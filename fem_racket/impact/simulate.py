"""``simulate(frame, **options) -> ImpactResult``: one impact in one call.

A thin shim over :class:`~fem_racket.impact.problem.ImpactProblem` and the solvers of
:mod:`fem_racket.impact.solvers`, for scripts and the command line: the options are split into
the problem's (where, how fast, which ball and law, how the racket moves) and the solver's (how
to solve it), and an option that is not known, or not used by the chosen solver for this
problem, is refused in one line.

COR = -v_B(t_c) / V_B0, the ratio of rebound to incident speed on a free racket (Kawazoe &
Kanda 1997, section 3.2).
"""

from __future__ import annotations

import difflib
from typing import Any

from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.result import ImpactResult
from fem_racket.impact.settings import SolverOptions
from fem_racket.impact.solvers import make_solver
from fem_racket.validation import InputError

__all__ = ["PROBLEM_OPTIONS", "ImpactResult", "simulate"]

#: The options stating the problem (:meth:`ImpactProblem.build`).
PROBLEM_OPTIONS = (
    "position",
    "speed",
    "ball_mass",
    "law",
    "kcb",
    "zeta",
    "separation",
    "swing",
    "frame_velocity",
    "offset",
    "hand",
    "shock_window",
    "strings",
    "elements",
    "incidence",
)


def simulate(frame: Any = None, **options: Any) -> ImpactResult:
    """Simulate a ball striking the racket ``frame``.

    Parameters
    ----------
    frame : Frame, FrameMesh or FrameModel, optional
        The racket; the paper's standard racket (EI1 = 146 N m^2) when None. A Frame or
        FrameMesh is assembled once per process (:mod:`fem_racket.impact.model_cache`) and its
        modes reused by the next calls; a FrameModel keeps its own.
    **options
        The problem: ``position`` (x/L, default 0.75), ``speed`` (V_B0 [m/s], default 20),
        ``ball_mass`` [kg] (0.057), ``law`` (a ContactLaw or a law's name; the paper's linear
        spring-dashpot when None), ``kcb`` [N/m] and ``zeta`` (the paper's law only; K_CB from
        the closing speed and zeta 0.0592 by default), ``separation`` ("displacement", the
        paper's, or "force"; the paper's law only), ``swing`` (a Swing) or ``frame_velocity``
        ((v [m/s], omega [rad/s]) of the centre of gravity, or the modes' velocities),
        ``offset`` (lateral offset of the impact point from the long axis [m], on the head; the
        frame then also twists; 0 by default), ``hand``
        (a Hand: the racket held on its grip; returns a HeldRun) and ``shock_window`` [s],
        ``strings`` (a StringBed: the string bed replaces the lumped K_CB, ``law`` is the
        ball's own; returns a StrungImpact), ``elements`` (cells when meshing a Frame; 20),
        ``incidence`` (an Incidence: an oblique, spinning ball at ``speed``; returns an
        ObliqueResult, :mod:`fem_racket.impact.oblique.solve`).
        The solver: ``solver`` ("auto" (default), "exact", "general", "cvode", "bdf") and its
        options ``tolerance`` (COR tolerance choosing modes and steps; 1e-6, but
        with histories the exact solver keeps every mode unless one is given), ``modes``
        (flexible modes kept; 80), ``basis`` ("modal" or "physical", BDF only),
        ``rtol``/``atol`` (BDF), ``output_step`` (spacing of the output times [s], 1e-5; None:
        only t = 0 and t_c, the exact solver's batched engine), ``t_max`` [s].
        See :mod:`fem_racket.impact.solvers` for which solver takes which.

    Returns
    -------
    ImpactResult
        (a :class:`~fem_racket.impact.held.run.HeldRun` for a hand-held racket, a
        :class:`~fem_racket.impact.strung.impact.StrungImpact` with a string bed)
    """
    known = (*PROBLEM_OPTIONS, "solver", *SolverOptions.names())
    for key in options:
        if key not in known:
            near = difflib.get_close_matches(key, known, n=1)
            hint = f"; did you mean {near[0]!r}?" if near else ""
            raise InputError(f"option {key!r} is not known to simulate{hint}")
    solver_options = {k: options.pop(k) for k in SolverOptions.names() if k in options}
    solver = make_solver(options.pop("solver", "auto"), **solver_options)
    problem = ImpactProblem.build(frame, **options)
    return solver.solve(problem)
