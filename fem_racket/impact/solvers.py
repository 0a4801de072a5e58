"""One way to solve an impact: the :class:`Solver` protocol and the registry of solvers.

A solver is made once with its options bound (``make_solver("cvode", rtol=1e-9)``, as
scikit-fem's ``solver_iter_*`` factories); ``check(problem)`` refuses in one line what it cannot
do, ``solve(problem)`` returns the outcome of one :class:`~fem_racket.impact.problem.ImpactProblem`
and ``solve_many(problems)`` of several. The methods:

===========  ==============================================================================
``exact``    the paper's linear law: closed-form eigen-solution in modal coordinates, or the
             batched engine when no histories are asked (:mod:`fem_racket.impact.exact`)
``general``  any contact law and any initial racket motion: the general integrator on the
             impact-point receptance (:mod:`fem_racket.impact.general`)
``cvode``    SUNDIALS CVODE BDF on the coupled ODE, for any law (:mod:`fem_racket.impact.ode`)
``bdf``      scipy's BDF on the coupled ODE, for the paper's linear law
``auto``     ``exact`` for the paper's law on a racket at rest or swinging (held or free),
             ``general`` otherwise
===========  ==============================================================================

A hand-held racket (:class:`~fem_racket.impact.problem.HeldRacket`) is a structure like the free
frame; ``exact``, ``cvode`` and ``bdf`` solve it (:mod:`fem_racket.impact.held`) and return a
:class:`~fem_racket.impact.held.run.HeldRun`. An option a solver does not use, for the problem
it is given, is refused naming the option and why; none is ever ignored.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any, ClassVar

from fem_racket.impact.held.run import HeldSettings, held_impact
from fem_racket.impact.oblique import solve_oblique
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.settings import DEFAULTS, SolverOptions
from fem_racket.impact.simulate_law import simulate_law
from fem_racket.impact.simulate_linear import simulate_linear
from fem_racket.impact.strung_solve import check_strung, solve_strung
from fem_racket.validation import InputError, check_choice, show, work_begins

__all__ = ["SOLVERS", "SOLVER_NAMES", "Solver", "auto_method", "make_solver"]


class Solver:
    """Base of the solvers (module docstring): options bound at construction.

    Parameters
    ----------
    **options
        The options of :class:`~fem_racket.impact.settings.SolverOptions` this solver takes
        (:attr:`takes`); others are refused.
    """

    #: Registry name.
    name: ClassVar[str] = ""
    #: Options this solver uses (on some problem).
    takes: ClassVar[tuple[str, ...]] = ()
    #: Values of options this solver does not take that ask for what it does anyway.
    neutral: ClassVar[dict[str, tuple]] = {}
    #: Why an option this solver does not take is refused, where more than its list helps.
    hints: ClassVar[dict[str, str]] = {}
    #: Options it does not use on a hand-held racket, and why.
    held_refuses: ClassVar[tuple[str, ...]] = ("modes", "basis", "t_max")

    def __init__(self, **options: Any) -> None:
        unknown = sorted(set(options) - set(SolverOptions.names()))
        if unknown:
            raise InputError(
                f"solver option {unknown[0]!r} is not known: must be one of "
                f"{', '.join(SolverOptions.names())}"
            )
        checked = SolverOptions(**options).given()
        for key, value in checked.items():
            if key not in self.takes and not self._neutral(key, value):
                why = self.hints.get(key, f"it takes {', '.join(self.takes)}")
                raise InputError(
                    f"{key} = {show(value)} is not allowed with solver {self.name!r}: {why}"
                )
        self.options = SolverOptions(**{k: v for k, v in checked.items() if k in self.takes})

    @classmethod
    def _neutral(cls, key: str, value: Any) -> bool:
        """True when ``value`` of an option this solver does not take asks for nothing it
        does not do anyway: the option's default, or a value in :attr:`neutral`."""
        return value == getattr(DEFAULTS, key) or value in cls.neutral.get(key, ())

    def __repr__(self) -> str:
        given = ", ".join(f"{k}={v!r}" for k, v in self.options.given().items())
        return f"{type(self).__name__}({given})"

    # -- the protocol -------------------------------------------------------------------------

    def check(self, problem: ImpactProblem) -> None:
        """Refuse, in one line, a problem (or an option for it) this solver cannot do."""
        if problem.strings is not None:
            check_strung(problem, self.name, self.options)
            return
        if problem.held:
            self._refuse_options(
                self.held_refuses,
                "with a hand: the held racket keeps its "
                "modes by tolerance (exact) or all its DOFs (cvode, bdf)",
            )

    def solve(self, problem: ImpactProblem) -> Any:
        """The outcome of ``problem``: an ImpactResult (a HeldRun for a hand-held racket, a
        StrungImpact with a string bed)."""
        self.check(problem)
        work_begins()  # fem-racket config --check stops here: every check has passed
        return self._outcome(problem)

    def solve_many(self, problems: Iterable[ImpactProblem]) -> list[Any]:
        """The outcomes of ``problems``, in order (each checked before any is solved)."""
        problems = list(problems)
        for p in problems:
            self.check(p)
        work_begins()
        return [self._outcome(p) for p in problems]

    def _outcome(self, problem: ImpactProblem) -> Any:
        """Solve a checked problem; an oblique one (an incidence) as its normal impact, then
        the tangential contact over it (:func:`fem_racket.impact.oblique.solve_oblique`)."""
        if problem.incidence is not None:
            return solve_oblique(self, problem)
        return self._solve(problem)

    # -- helpers ------------------------------------------------------------------------------

    def _solve(self, problem: ImpactProblem) -> Any:
        raise NotImplementedError

    def _refuse_options(self, names: Iterable[str], why: str) -> None:
        given = self.options.given()
        for key in names:
            if key in given:
                raise InputError(
                    f"{key} = {show(given[key])} is not allowed with solver {self.name!r} {why}"
                )

    def _refuse_law(self, problem: ImpactProblem) -> None:
        if problem.law is not None:
            raise InputError(
                f"solver = {self.name!r} is not allowed with contact law {problem.law.name!r}: "
                "it solves the paper's linear law; use 'general' or 'cvode'"
            )
        if problem.frame_velocity is not None:
            raise InputError(
                f"solver = {self.name!r} is not allowed with a frame_velocity: use 'general' "
                "or 'cvode' (or give the racket's motion as a swing)"
            )

    def _held(self, problem: ImpactProblem) -> Any:
        """The hand-held racket by this solver (:func:`fem_racket.impact.held.run.held_impact`):
        every mode unless a tolerance is asked (the modes the COR tolerance drops still move
        the hand, and the held racket has few DOFs); histories when output times are asked."""
        given = self.options.given()
        s = self.options.settings()
        step = given.get("output_step", s.output_step)
        settings = HeldSettings(
            solver=self.name,
            output_step=1e-5 if step is None else step,
            histories=step is not None,
            tolerance=given.get("tolerance"),
            rtol=s.rtol,
            atol=s.atol,
        )
        return held_impact(problem, settings)


class ExactSolver(Solver):
    """The paper's linear law solved exactly (eigen-solution, or the batched engine without
    histories)."""

    name = "exact"
    takes = ("tolerance", "modes", "output_step", "t_max")
    hints = {"basis": "must be 'modal' (the exact solution is in free-free modes)"}

    def check(self, problem: ImpactProblem) -> None:
        super().check(problem)
        if problem.strings is None:
            self._refuse_law(problem)

    def _solve(self, problem: ImpactProblem) -> Any:
        if problem.strings is not None:
            return solve_strung(problem, self.name, self.options)
        if problem.held:
            return self._held(problem)
        return simulate_linear(problem, "exact", self.options.settings())


class GeneralSolver(Solver):
    """Any contact law and any initial racket motion: the general integrator."""

    name = "general"
    takes = ("tolerance", "output_step", "t_max")

    def check(self, problem: ImpactProblem) -> None:
        if problem.strings is not None:
            check_strung(problem, self.name, self.options)
        elif problem.held:
            raise InputError(
                "solver = 'general' is not allowed with a hand: must be one of exact, cvode, bdf"
            )

    def _solve(self, problem: ImpactProblem) -> Any:
        if problem.strings is not None:
            return solve_strung(problem, self.name, self.options)
        return simulate_law(problem, "general", self.options.settings())


class _OdeSolver(Solver):
    """The coupled ODE by a BDF integrator."""

    takes = ("rtol", "atol", "basis", "modes", "output_step", "t_max")
    #: tolerance None: every mode (of ``modes``), which the ODE solvers keep anyway
    neutral = {"tolerance": (None, 0, 0.0)}

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

    def _solve(self, problem: ImpactProblem) -> Any:
        if problem.strings is not None:
            return solve_strung(problem, self.name, self.options)
        if problem.held:
            return self._held(problem)
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


class AutoSolver(Solver):
    """``exact`` for the paper's law on a racket at rest or swinging, ``general`` otherwise."""

    name = "auto"
    takes = SolverOptions.names()

    def pick(self, problem: ImpactProblem) -> Solver:
        """The solver this one stands for on ``problem``."""
        linear = problem.linear
        if problem.strings is not None:  # the ball's own law on the bed
            linear = problem.ball_law().name == "linear"
        name = auto_method(linear and problem.frame_velocity is None)
        try:
            return SOLVERS[name](**self.options.given())
        except InputError as err:
            raise InputError(f"{err} (solver 'auto' picked {name!r} for this impact)") from None

    def check(self, problem: ImpactProblem) -> None:
        self.pick(problem).check(problem)

    def _solve(self, problem: ImpactProblem) -> Any:
        return self.pick(problem)._solve(problem)


#: Every name :func:`make_solver` takes.
SOLVER_NAMES = ("auto", *SOLVERS)


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
