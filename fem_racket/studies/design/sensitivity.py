"""Variance-based (Sobol) sensitivity of a design output to each design variable (SALib).

Saltelli's scheme (Saltelli 2002; Saltelli et al. 2010) as SALib implements it: a scrambled Sobol
sample of N base designs in the unit box gives N (D + 2) designs (D variables, no second-order
terms); their outputs give the first-order index S1_i (the share of the output's variance due to
variable i alone) and the total index ST_i (including its interactions), each with a bootstrap
95 % confidence half-width. The designs run as one batch through the
:class:`~.evaluate.Evaluator` (executors, history).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.extras import require
from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.limits import check_sobol_size
from fem_racket.studies.design.options import check_seed
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.scaling import progress_bar
from fem_racket.studies.design.unused import refuse_unused_sensitivity
from fem_racket.studies.views import SobolView
from fem_racket.validation import InputError, check_choice

__all__ = ["SobolIndices", "sobol_indices"]

#: The sample is evaluated in up to this many batches (progress between them).
SLICES = 20


@dataclass(frozen=True, repr=False)
class SobolIndices(SobolView):
    """Sobol indices of one output.

    Attributes
    ----------
    output : str
    names : list of str
        Design variables.
    s1, s1_conf, st, st_conf : ndarray
        First-order and total indices and their 95 % confidence half-widths.
    designs : int
        Designs evaluated.
    mean, std : float
        Mean and standard deviation of the output over the sample.
    """

    output: str
    names: list[str]
    s1: np.ndarray
    s1_conf: np.ndarray
    st: np.ndarray
    st_conf: np.ndarray
    designs: int
    mean: float
    std: float

    def table(self) -> str:
        """A text table, one row per variable."""
        lines = [f"{'variable':<12} {'S1':>8} {'+-':>7} {'ST':>8} {'+-':>7}"]
        for i, name in enumerate(self.names):
            lines.append(
                f"{name:<12} {self.s1[i]:>8.4f} {self.s1_conf[i]:>7.4f} "
                f"{self.st[i]:>8.4f} {self.st_conf[i]:>7.4f}"
            )
        return "\n".join(lines)


def sobol_indices(
    problem: DesignProblem,
    *,
    output: str | None = None,
    designs: int = 10_000,
    seed: int = 1,
    evaluator: Evaluator | None = None,
    progress: bool | None = None,
) -> SobolIndices:
    """First-order and total Sobol indices of ``output`` over the problem's variable bounds.

    Parameters
    ----------
    problem : DesignProblem
    output : str, optional
        An objective or quantity (default: the first objective).
    designs : int
        About this many designs: N = designs / (D + 2) base samples, rounded up to a power of
        two (Sobol sequences balance at powers of two).
    seed : int
        Scrambling seed of the Sobol sequence and of the bootstrap of the confidence intervals
        (0 to :data:`~.options.MAX_SEED`).
    evaluator : Evaluator, optional
        Where designs run; serial in memory when None.
    progress : bool, optional
        Progress bar (designs) on stderr; None: only when stderr is a terminal.
    """
    require("SALib", "Sobol indices (sensitivity)")
    from SALib.analyze import sobol as analyze
    from SALib.sample import sobol as sample

    evaluator = Evaluator(problem) if evaluator is None else evaluator
    output = problem.objectives[0] if output is None else output
    check_choice("output", output, tuple(evaluator.names))
    refuse_unused_sensitivity(problem, output)
    check_seed(seed)
    d = problem.n_var
    n = check_sobol_size(problem, designs)
    spec = {"num_vars": d, "names": problem.names, "bounds": [[0.0, 1.0]] * d}
    u = sample.sample(spec, n, calc_second_order=False, seed=seed)
    x = problem.from_unit(u)
    y = np.empty(len(x))
    with progress_bar(progress, "Sobol", len(x), unit="design") as bar:
        for part in np.array_split(np.arange(len(x)), max(1, min(SLICES, len(x) // 64))):
            y[part] = evaluator(x[part])[:, evaluator.column(output)]
            bar.update(len(part))
    if not np.all(np.isfinite(y)):
        raise InputError(f"output = {output!r} is not finite on every sampled design")
    # a generator, not the int: SALib leaves the bootstrap unseeded for seed 0 (``if seed:``);
    # for any other seed it makes this same generator, so the intervals are unchanged
    rng = np.random.default_rng(seed)
    si = analyze.analyze(spec, y, calc_second_order=False, seed=rng, print_to_console=False)
    return SobolIndices(
        output=output,
        names=problem.names,
        s1=np.asarray(si["S1"]),
        s1_conf=np.asarray(si["S1_conf"]),
        st=np.asarray(si["ST"]),
        st_conf=np.asarray(si["ST_conf"]),
        designs=len(u),
        mean=float(np.mean(y)),
        std=float(np.std(y)),
    )
