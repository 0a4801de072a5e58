"""How large a design study may be: its counts checked before anything is allocated or run.

A study evaluates designs in batches (:mod:`.evaluate`) and keeps every one in its history
(:mod:`.history`): about :data:`BYTES_PER_DESIGN` bytes each (the row of variables and outputs,
its lookup key and the list's references; measured below it for 20 variables and 20 outputs).
Each count the user gives is refused, named as given, when the designs it implies exceed
:data:`MAX_DESIGNS` or half the memory available now (as a sweep's grid,
:mod:`fem_racket.studies.limits`):

- ``nsga2``: ``pop_size`` x (``generations`` + 1) designs;
- ``differential-evolution``: ``popsize`` x variables x (``maxiter`` + 1), then the polish;
- ``SLSQP``/``trust-constr``: (variables + 1) per iteration, ``maxiter`` iterations;
- ``sensitivity``: N (D + 2) designs, N = ``designs`` / (D + 2) rounded up to a power of two.

The number of objectives fits the method: one for the local and global methods (they maximise
a single objective), 2 or 3 for NSGA-II (pymoo's NSGA-II is a 2-3 objective method; many
objectives need NSGA-III).
"""

from __future__ import annotations

import math

from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.limits import available_memory
from fem_racket.validation import InputError, check_integer

__all__ = [
    "BYTES_PER_DESIGN",
    "MAX_DESIGNS",
    "NSGA2_OBJECTIVES",
    "check_sobol_size",
    "check_study_size",
    "sobol_base_samples",
]

#: Most designs one study may evaluate (~1 GB of history by the estimate below).
MAX_DESIGNS = 1_000_000
#: Estimated memory per design kept in a study's history [bytes].
BYTES_PER_DESIGN = 1000
#: Objectives NSGA-II takes.
NSGA2_OBJECTIVES = (2, 3)


def _check_designs(name: str, value: int, designs: int, how: str) -> None:
    """Raise naming option ``name`` = ``value`` when ``designs`` (computed as ``how``) is too
    many for :data:`MAX_DESIGNS` or for the memory available."""
    if designs > MAX_DESIGNS:
        raise InputError(
            f"{name} = {value} is not allowed: the study would evaluate {designs:.3g} designs "
            f"({how}); at most {MAX_DESIGNS}"
        )
    avail = available_memory()
    need = designs * BYTES_PER_DESIGN
    if avail is not None and need > avail / 2:
        raise InputError(
            f"{name} = {value} is not allowed: {designs:.3g} designs ({how}) need about "
            f"{need / 1e9:.3g} GB, more than half the {avail / 1e9:.3g} GB of memory available"
        )


def check_study_size(
    problem: DesignProblem,
    method: str,
    *,
    maxiter: int,
    popsize: int,
    pop_size: int,
    generations: int,
) -> None:
    """Refuse counts and objectives that ``method`` cannot take, before any work."""
    n_obj, d = len(problem.objectives), problem.n_var
    if method == "nsga2":
        if n_obj not in NSGA2_OBJECTIVES:
            raise InputError(
                f"objectives = {list(problem.objectives)} is not allowed with nsga2: give 2 or "
                "3 (pymoo's NSGA-II; more objectives need a many-objective method)"
            )
        check_integer("pop_size", pop_size, minimum=4)
        check_integer("generations", generations)
        designs = pop_size * (generations + 1)
        how = f"pop_size {pop_size} x (generations {generations} + 1)"
        big = ("pop_size", pop_size) if pop_size >= generations else ("generations", generations)
        _check_designs(*big, designs, how)
        return
    if n_obj != 1:
        raise InputError(
            f"objectives = {list(problem.objectives)} is not allowed with {method}: it "
            "maximises one objective; give one, or --method nsga2 for a Pareto front of 2 or 3"
        )
    check_integer("maxiter", maxiter)
    if method == "differential-evolution":
        check_integer("popsize", popsize, minimum=4)
        designs = popsize * d * (maxiter + 1) + (d + 1) * maxiter  # then the SLSQP polish
        how = f"popsize {popsize} x {d} variables x (maxiter {maxiter} + 1), then the polish"
        name, value = ("popsize", popsize) if popsize * d >= maxiter else ("maxiter", maxiter)
        _check_designs(name, value, designs, how)
        return
    _check_designs("maxiter", maxiter, (d + 1) * maxiter, f"({d} variables + 1) x maxiter")


def sobol_base_samples(designs: int, n_var: int) -> int:
    """N of a Sobol analysis of about ``designs`` designs: a power of two, N (D + 2) designs."""
    return 1 << math.ceil(math.log2(max(designs / (n_var + 2), 2)))


def check_sobol_size(problem: DesignProblem, designs: int) -> int:
    """Refuse ``designs`` out of range for a Sobol analysis of ``problem``; return N."""
    d = problem.n_var
    check_integer("designs", designs, minimum=d + 2)
    if designs > MAX_DESIGNS:
        _check_designs("designs", designs, designs, "as asked")
    n = sobol_base_samples(designs, d)
    _check_designs("designs", designs, n * (d + 2), f"N {n} x ({d} variables + 2)")
    return n
