"""The :class:`Solver` protocol: options bound when made, ``check``, ``solve``, ``solve_many``.

The methods and their registry are in :mod:`fem_racket.impact.solvers`; this module holds what
every solver shares: the options it takes and refuses (:class:`~fem_racket.impact.settings.
SolverOptions`), the checks common to every method (a string bed, a hand), the oblique hook
(an incidence solved as its normal impact, then the tangential contact) and the batch
protocol (:class:`~fem_racket.impact.problem_batch.ProblemBatch` in, a
:class:`~fem_racket.impact.problem_batch.BatchOutcome` out).
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import replace
from typing import Any, ClassVar

from fem_racket.impact.clamped_solve import solve_clamped
from fem_racket.impact.held.run import HeldSettings, held_impact
from fem_racket.impact.oblique.solve import solve_oblique
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.problem_batch import BatchOutcome, ProblemBatch
from fem_racket.impact.settings import SolverOptions, check_time_limit
from fem_racket.impact.strung.solve import check_strung, solve_strung
from fem_racket.validation import InputError, show, work_begins

__all__ = ["Solver"]

#: Why a held racket refuses :attr:`Solver.held_refuses`.
_HELD_WHY = (
    "with a hand: the held racket keeps its modes by tolerance (exact) or all its DOFs (cvode, bdf)"
)


def _check_problem(name: str, problem: Any) -> None:
    """Refuse ``problem`` unless it is an ImpactProblem."""
    if not isinstance(problem, ImpactProblem):
        raise InputError(
            f"{name} = {show(problem)} is not allowed: must be an ImpactProblem "
            "(ImpactProblem.build(frame, position=..., speed=...))"
        )


class Solver:
    """Base of the solvers (module docstring): options bound at construction.

    Parameters
    ----------
    **options
        The options of :class:`~fem_racket.impact.settings.SolverOptions` this solver takes
        (:attr:`takes`); another one given is refused at any value (its default too): an
        option left out is never refused, one given is never ignored.
    """

    #: Registry name.
    name: ClassVar[str] = ""
    #: Options this solver uses (on some problem).
    takes: ClassVar[tuple[str, ...]] = ()
    #: Why an option this solver does not take is refused, where more than its list helps.
    hints: ClassVar[dict[str, str]] = {}
    #: Options it does not use on a hand-held racket, and why.
    held_refuses: ClassVar[tuple[str, ...]] = ("modes", "basis", "t_max")
    #: Whether it solves impacts on a clamped head (:mod:`fem_racket.impact.clamped_solve`).
    clamps: ClassVar[bool] = False
    #: Options it does not use on a clamped head (whose modes are all kept).
    clamped_refuses: ClassVar[tuple[str, ...]] = ("modes", "output_step", "t_max")

    def __init__(self, **options: Any) -> None:
        unknown = sorted(set(options) - set(SolverOptions.names()))
        if unknown:
            raise InputError(
                f"solver option {unknown[0]!r} is not known: must be one of "
                f"{', '.join(SolverOptions.names())}"
            )
        checked = SolverOptions(**options).given()
        for key in checked:
            if key not in self.takes:  # given, at any value (its default too), as it was given
                why = self.hints.get(key, f"it takes {', '.join(self.takes)}")
                raise InputError(
                    f"{key} = {show(options[key])} is not allowed with solver {self.name!r}: {why}",
                    parameter=key,
                    value=options[key],
                )
        self.options = SolverOptions(**{k: v for k, v in checked.items() if k in self.takes})

    def __repr__(self) -> str:
        given = ", ".join(f"{k}={v!r}" for k, v in self.options.given().items())
        return f"{type(self).__name__}({given})"

    # -- the protocol -------------------------------------------------------------------------

    def check(self, problem: ImpactProblem) -> None:
        """Refuse, in one line, a problem (or an option for it) this solver cannot do."""
        if problem.clamped:
            if not self.clamps:
                raise InputError(
                    f"solver = {self.name!r} is not allowed with a clamped head: use 'exact' "
                    "(the paper's law) or 'general'"
                )
            self._refuse_options(
                self.clamped_refuses,
                "on a clamped head: every mode of the head is kept, and histories come only "
                "from 'general', at its steps",
            )
            self._check_time_limit(problem)
            return
        if problem.strings is not None:
            check_strung(problem, self.name, self.options)
            return
        if problem.held:
            self._refuse_options(self.held_refuses, _HELD_WHY)
        self._check_time_limit(problem)

    def solve(self, problem: ImpactProblem) -> Any:
        """The outcome of ``problem``: an ImpactResult (a HeldRun for a hand-held racket, a
        StrungImpact with a string bed, a ClampedImpact on a clamped head)."""
        _check_problem("problem", problem)
        self.check(problem)
        work_begins()  # fem-racket config --check stops here: every check has passed
        return self._outcome(problem)

    def solve_many(self, problems: Iterable[ImpactProblem] | ProblemBatch) -> Any:
        """The outcomes of ``problems``, in order (each checked before any is solved); of a
        :class:`~fem_racket.impact.problem_batch.ProblemBatch`, its
        :class:`~fem_racket.impact.problem_batch.BatchOutcome` (:mod:`.batch_solve`: the
        exact solver's batched engine, the general solver's one integrator call)."""
        if isinstance(problems, ProblemBatch):
            self._check_batch(problems)
            work_begins()
            return self._batch(problems)
        if isinstance(problems, ImpactProblem) or not isinstance(problems, Iterable):
            raise InputError(
                f"problems = {show(problems)} is not allowed: must be ImpactProblems or a "
                "ProblemBatch (solve one problem with solve)"
            )
        problems = list(problems)
        for p in problems:
            _check_problem("problems", p)
            self.check(p)
        work_begins()
        return self._many(problems)

    def check_batch(self, batch: ProblemBatch) -> None:
        """Refuse, in one line and before any work, what :meth:`solve_many` would refuse of
        ``batch``: the batch itself, then its first case as a problem (:meth:`check`; the
        cases of a batch share its law, its solver options and its kind of structure; a t_max
        is checked on the case it binds, :meth:`_check_time_limits`)."""
        self._check_batch(batch)
        if len(batch):
            self.check(batch.problem(0))

    def _many(self, problems: list[ImpactProblem]) -> list:
        """Solve checked problems; on clamped heads all in one call per head."""
        if problems and self.clamps and all(p.clamped for p in problems):
            return solve_clamped(self.name, problems, self.options.settings())
        return [self._outcome(p) for p in problems]

    def _outcome(self, problem: ImpactProblem) -> Any:
        """Solve a checked problem; an oblique one (an incidence) as its normal impact, then
        the tangential contact over it (:func:`fem_racket.impact.oblique.solve.solve_oblique`)."""
        if problem.clamped:
            return self._many([problem])[0]
        if problem.incidence is not None:
            return solve_oblique(self, problem)
        return self._solve(problem)

    # -- helpers ------------------------------------------------------------------------------

    def _check_batch(self, batch: ProblemBatch) -> None:
        """Refuse, in one line, a batch (or an option for it) this solver cannot do: output
        times or a time limit (None, no histories, is what a batch does), and with a hand the
        options a held racket does not use."""
        given = self.options.given()
        for key in ("output_step", "t_max"):
            if given.get(key) is not None:
                self._refuse_options((key,), "on a ProblemBatch: it returns no histories")
        if batch.held:
            self._refuse_options(self.held_refuses, _HELD_WHY)

    def _batch(self, batch: ProblemBatch) -> BatchOutcome:
        raise NotImplementedError

    def _grid(self, problem: ImpactProblem) -> int | None:
        """Time steps per estimated contact time this solver lays out up to t_max for
        ``problem`` besides the output times (None: none, its work does not grow with t_max)."""
        return None

    def _check_time_limit(self, problem: ImpactProblem) -> None:
        """Refuse a t_max whose times would be too many to allocate (the one size check of
        every path: :func:`~fem_racket.impact.settings.check_time_limit`)."""
        s = self.options.settings()
        if s.t_max is None:
            return
        if problem.clamped:  # no output times: histories at the integrator's steps
            s = replace(s, output_step=None)
        check_time_limit(s, self._contact_time(problem), self._grid(problem), self.name)

    def _check_time_limits(self, batch: ProblemBatch) -> None:
        """Refuse, before any case is solved, a t_max too long for a case of ``batch``: the
        case with the finest time grid (its contact time estimate over its steps per contact
        time) checked as its problem is (:meth:`_check_time_limit`), named in the refusal. A
        hand or a string bed refuses t_max itself (:meth:`check`)."""
        if self.options.settings().t_max is None or batch.held or batch.strings is not None:
            return
        finest, grid, binding = 0, math.inf, None
        for i in range(len(batch)):  # each case on its frame unscaled: t_est needs no EI
            problem = batch.problem(i, batch.models[batch.frame[i]])
            steps = self._grid(problem)
            step = math.inf if steps is None else self._contact_time(problem) / steps
            if binding is None or step < grid:
                finest, grid, binding = i, step, problem
        try:
            self._check_time_limit(binding)
        except InputError as err:
            raise InputError(
                f"{err} (case {finest} of the batch)", parameter=err.parameter, value=err.value
            ) from None

    @staticmethod
    def _contact_time(problem: ImpactProblem) -> float:
        """The contact time [s] ``problem``'s law estimates at its closing speed (eq 11 for
        the paper's law)."""
        law = problem.contact() if problem.law is None else problem.law
        return float(law.contact_time_estimate(problem.ball.mass, problem.closing_speed))

    def _solve(self, problem: ImpactProblem) -> Any:
        """Solve a checked problem on its structure: a string bed by the strung racket's paths
        (:func:`fem_racket.impact.strung.solve.solve_strung`), a hand by :meth:`_held`, a free
        racket by the method's own :meth:`_free`."""
        if problem.strings is not None:
            return solve_strung(problem, self.name, self.options)
        if problem.held:
            return self._held(problem)
        return self._free(problem)

    def _free(self, problem: ImpactProblem) -> Any:
        """Solve a checked problem on the free racket (no string bed, no hand)."""
        raise NotImplementedError

    def _refuse_options(self, names: Iterable[str], why: str) -> None:
        given = self.options.given()
        for key in names:
            if key in given:
                raise InputError(
                    f"{key} = {show(given[key])} is not allowed with solver {self.name!r} {why}",
                    parameter=key,
                    value=given[key],
                )

    def _refuse_law(self, problem: ImpactProblem | ProblemBatch) -> None:
        if problem.law is not None:
            raise InputError(
                f"solver = {self.name!r} is not allowed with contact law {problem.law.name!r}: "
                "it solves the paper's linear law; use 'general' or 'cvode'"
            )
        if getattr(problem, "frame_velocity", None) is not None:
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
