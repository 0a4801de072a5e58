"""One way to solve an impact: the :class:`Solver` protocol and the registry of solvers.

A solver is made once with its options bound (``make_solver("cvode", rtol=1e-9)``, as
scikit-fem's ``solver_iter_*`` factories); ``check(problem)`` refuses in one line what it cannot
do, ``solve(problem)`` returns the outcome of one :class:`~fem_racket.impact.problem.ImpactProblem`
and ``solve_many(problems)`` of several. The methods:

===========  ==============================================================================
``exact``    the paper's linear law: the batched engine's roots, with the modes a COR
             ``tolerance`` needs; with histories and no tolerance given, every mode by the
             closed-form eigen-solution in modal coordinates (:mod:`fem_racket.impact.exact`)
``general``  any contact law and any initial racket motion: the general integrator on the
             impact-point receptance (:mod:`fem_racket.impact.general`)
``cvode``    SUNDIALS CVODE BDF on the coupled ODE, for any law (:mod:`fem_racket.impact.ode`)
``bdf``      scipy's BDF on the coupled ODE, for the paper's linear law
``auto``     ``exact`` for the paper's law on a racket at rest or swinging (held or free),
             ``cvode`` on a stretching string bed, ``general`` otherwise
===========  ==============================================================================

A hand-held racket (:class:`~fem_racket.impact.problem.HeldRacket`) is a structure like the free
frame; ``exact``, ``cvode`` and ``bdf`` solve it (:mod:`fem_racket.impact.held`) and return a
:class:`~fem_racket.impact.held.run.HeldRun`. An option a solver does not use, for the problem
it is given, is refused naming the option and why; none is ever ignored.

Studies (sweeps, maps) state their impacts as one
:class:`~fem_racket.impact.problem_batch.ProblemBatch` and ask ``solve_many``; each solver
answers it its own way (:mod:`fem_racket.impact.batch_solve`): ``exact`` by the batched engine,
``general`` by one call of the general integrator over every case (whatever their frames),
``cvode`` and ``bdf`` case by case. The protocol itself is :mod:`fem_racket.impact.solver_base`.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from fem_racket.impact.batch_solve import each_batch, engine_batch, law_batch
from fem_racket.impact.constants import SOLVER_NAMES
from fem_racket.impact.general.integrator import settings as general_settings
from fem_racket.impact.general.vouch import first_steps
from fem_racket.impact.held.batch import held_batch
from fem_racket.impact.ode import integrators, law_cvode
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.problem_batch import BatchOutcome, ProblemBatch
from fem_racket.impact.settings import SolverOptions
from fem_racket.impact.simulate_law import simulate_law
from fem_racket.impact.simulate_linear import simulate_linear
from fem_racket.impact.solver_base import Solver
from fem_racket.impact.strung.solve import check_strung
from fem_racket.validation import InputError, check_choice

__all__ = ["SOLVERS", "SOLVER_NAMES", "Solver", "auto_method", "auto_pick", "make_solver"]


class ExactSolver(Solver):
    """The paper's linear law solved exactly: the batched engine's roots, with the modes kept
    by the COR ``tolerance``; with histories (``output_step``) every mode by the
    eigen-solution unless a ``tolerance`` is given (as the hand-held racket)."""

    name = "exact"
    takes = ("tolerance", "modes", "output_step", "t_max")
    clamps = True
    hints = {"basis": "it solves in the free-free modes ('modal'); basis is cvode's and bdf's"}

    def check(self, problem: ImpactProblem) -> None:
        super().check(problem)
        if problem.strings is None:
            self._refuse_law(problem)

    def _check_batch(self, batch: ProblemBatch) -> None:
        super()._check_batch(batch)
        if not batch.per_case:  # a string bed's ball law: checked case by case
            self._refuse_law(batch)

    def _batch(self, batch: ProblemBatch) -> BatchOutcome:
        if batch.per_case:
            return each_batch(self, batch)
        if batch.held:  # every mode unless a tolerance is asked, as a single held run
            return held_batch(batch, self.options.given().get("tolerance"))
        return engine_batch(batch, self.options.settings())

    def _free(self, problem: ImpactProblem) -> Any:
        s = self.options.settings()
        if s.output_step is not None and "tolerance" not in self.options.given():
            s = replace(s, tolerance=None)  # histories keep every mode unless a tolerance is asked
        return simulate_linear(problem, "exact", s)


class GeneralSolver(Solver):
    """Any contact law and any initial racket motion: the general integrator."""

    name = "general"
    takes = ("tolerance", "output_step", "t_max")
    clamps = True
    clamped_refuses = ("output_step",)  # its histories are at the integrator's steps

    def check(self, problem: ImpactProblem) -> None:
        if problem.clamped:
            super().check(problem)
        elif problem.strings is not None:
            check_strung(problem, self.name, self.options)
        elif problem.held:
            raise InputError(
                "solver = 'general' is not allowed with a hand: must be one of exact, cvode, bdf"
            )
        else:
            self._check_time_limit(problem)

    def _grid(self, problem: ImpactProblem) -> int | None:
        steps = general_settings(self.options.settings().tolerance)[0]
        return int(first_steps(steps, getattr(problem.law, "exponent", 1.0), 1)[0])

    def _check_batch(self, batch: ProblemBatch) -> None:
        super()._check_batch(batch)
        if batch.law is None and not batch.per_case:
            raise InputError(
                "solver = 'general' is not allowed with a ProblemBatch under the paper's law: "
                "use 'exact' (its batched engine)"
            )

    def _batch(self, batch: ProblemBatch) -> BatchOutcome:
        if batch.per_case:
            return each_batch(self, batch)
        return law_batch(batch, self.options.settings())

    def _free(self, problem: ImpactProblem) -> Any:
        return simulate_law(problem, "general", self.options.settings())


class _OdeSolver(Solver):
    """The coupled ODE by a BDF integrator."""

    takes = ("rtol", "atol", "basis", "modes", "output_step", "t_max")

    def __init__(self, **options: Any) -> None:
        super().__init__(**options)
        if self.options.given().get("basis") == "physical":
            self._refuse_options(("modes",), "with basis 'physical': it integrates every FE DOF")

    def check(self, problem: ImpactProblem) -> None:
        super().check(problem)
        if problem.strings is not None:
            return
        if problem.held:
            self._refuse_options(("tolerance",), "with a hand: it integrates every DOF")
        elif not problem.linear or problem.frame_velocity is not None:
            self._refuse_options(
                ("basis", "modes"),
                "under a contact law other than the paper's or a racket moving as given: it "
                "integrates every frame mode",
            )

    def _check_batch(self, batch: ProblemBatch) -> None:
        """Each case is checked as its problem (:func:`.batch_solve.each_batch`); a t_max
        before any, on the case with the finest time grid (:meth:`_check_time_limits`)."""
        self._check_time_limits(batch)

    def _grid(self, problem: ImpactProblem) -> int | None:
        if self.options.settings().output_step is not None:
            return None  # the output times are its grid
        if problem.linear and problem.frame_velocity is None:
            return integrators.GRID_STEPS
        return law_cvode.GRID_STEPS

    def _batch(self, batch: ProblemBatch) -> BatchOutcome:
        return each_batch(self, batch)

    def _free(self, problem: ImpactProblem) -> Any:
        s = self.options.settings()
        if problem.linear and problem.frame_velocity is None:
            return simulate_linear(problem, self.name, s)
        return simulate_law(problem, self.name, s)


class CvodeSolver(_OdeSolver):
    """SUNDIALS CVODE (scikit-sundae), any contact law."""

    name = "cvode"


class BdfSolver(_OdeSolver):
    """scipy's BDF, the paper's linear law."""

    name = "bdf"

    def check(self, problem: ImpactProblem) -> None:
        super().check(problem)
        self._refuse_law(problem)  # (a string bed is refused by check_strung)


#: The solvers by name.
SOLVERS: dict[str, type[Solver]] = {
    s.name: s for s in (ExactSolver, GeneralSolver, CvodeSolver, BdfSolver)
}


def auto_method(linear: bool) -> str:
    """The method ``auto`` picks: ``exact`` when the problem is ``linear`` (the paper's law on
    a racket at rest or swinging), ``general`` otherwise."""
    return "exact" if linear else "general"


def auto_pick(law: Any, strings: Any = None, *, moving: bool = False) -> str:
    """The method ``auto`` picks for an impact under ``law`` (a ContactLaw; None: the paper's)
    on ``strings`` (a StringBed; None: no bed), the racket moving as given (``moving``: a
    frame_velocity) or not (at rest or swinging): on the bed ``cvode`` when it stretches,
    else ``exact`` for a linear ball law (``law``, or the ``kawazoe-1997-ball`` when None),
    ``general`` otherwise; off it ``exact`` for the paper's law on a racket not moving as
    given, ``general`` otherwise."""
    if strings is not None:
        if strings.stretch:  # CVODE alone integrates the stretching bed
            return "cvode"
        return auto_method(law is None or law.name == "linear")  # the default ball's is
    return auto_method(law is None and not moving)


class AutoSolver(Solver):
    """``exact`` for the paper's law on a racket at rest or swinging, ``cvode`` on a stretching
    string bed (``strings.stretch``), ``general`` otherwise."""

    name = "auto"
    takes = SolverOptions.names()

    def pick(self, problem: ImpactProblem | ProblemBatch) -> Solver:
        """The solver this one stands for on ``problem`` (or a batch)."""
        if isinstance(problem, ProblemBatch):
            stretch = any(s is not None and s.stretch for s in problem.strings or ())
            name = "cvode" if stretch else auto_method(problem.linear)
        else:
            name = auto_pick(
                problem.law, problem.strings, moving=problem.frame_velocity is not None
            )
        try:
            return SOLVERS[name](**self.options.given())
        except InputError as err:
            why = f"{err} (solver 'auto' picked {name!r} for this impact)"
            raise InputError(why, parameter=err.parameter, value=err.value) from None

    def check(self, problem: ImpactProblem) -> None:
        self.pick(problem).check(problem)

    def _check_batch(self, batch: ProblemBatch) -> None:
        self.pick(batch)._check_batch(batch)

    def _batch(self, batch: ProblemBatch) -> BatchOutcome:
        return self.pick(batch)._batch(batch)

    def _many(self, problems: list[ImpactProblem]) -> list:
        if problems and all(p.clamped for p in problems):  # one call per head and method
            if len({self.pick(p).name for p in problems}) == 1:
                return self.pick(problems[0])._many(problems)
        return super()._many(problems)

    def _solve(self, problem: ImpactProblem) -> Any:
        return self.pick(problem)._solve(problem)


def make_solver(name: str = "auto", **options: Any) -> Solver:
    """The solver called ``name`` (:data:`SOLVER_NAMES`) with ``options`` bound.

    Parameters
    ----------
    name : {"auto", "exact", "general", "cvode", "bdf"}
    **options
        tolerance, modes, basis, rtol, atol, output_step, t_max
        (:class:`~fem_racket.impact.settings.Settings`); each solver takes its own.
    """
    check_choice("solver", name, SOLVER_NAMES)
    return AutoSolver(**options) if name == "auto" else SOLVERS[name](**options)
