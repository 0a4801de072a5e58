"""The settings of a design study in small frozen groups: the variables, the impact zone (with
the ball and the swing), the objectives and constraints, and where the designs run.

:func:`.build.design_problem` takes them as flat keywords (a name of any group), checked here
(:meth:`DesignOptions.from_keywords`: an unknown name is refused with the nearest known one);
the CLI and run files fill the same fields (``--ei-bounds`` -> ``ei_bounds``). An option the
settings would not use is refused when they are made (:mod:`.unused`).
"""

from __future__ import annotations

import difflib
from collections.abc import Sequence
from dataclasses import dataclass, field, fields
from typing import Any

from fem_racket.contact.law import ContactLaw
from fem_racket.frame.masses import DEFAULT_WIDTH
from fem_racket.impact.held.shock import DEFAULT_WINDOW
from fem_racket.studies.design.swing import SWING_EXPONENT, SWING_WEIGHT_AXIS
from fem_racket.studies.design.unused import refuse_unused, refuse_unused_search
from fem_racket.validation import InputError, check_integer

__all__ = [
    "MAX_SEED",
    "DesignOptions",
    "ExecutionOptions",
    "ObjectiveOptions",
    "SearchOptions",
    "VariableOptions",
    "ZoneOptions",
    "check_seed",
]

#: The default interior segment boundaries x/L: the paper's step at 0.3 L and the top side in
#: three equal parts (4 segments).
BOUNDARIES = (0.3, 0.5333333333333333, 0.7666666666666667)

#: Largest random seed: numpy's legacy generator (``RandomState``, what differential evolution
#: and pymoo's NSGA-II seed) takes 0 to 2**32 - 1; the Sobol sample's (``default_rng``) is held
#: to the same, one ``--seed`` for every study.
MAX_SEED = 2**32 - 1


@dataclass(frozen=True)
class VariableOptions:
    """What a design varies (:mod:`.variable_groups`, :func:`.paper_problem.paper_problem`).

    Attributes
    ----------
    boundaries : sequence of float
        Interior segment boundaries x/L.
    vary : sequence of str
        Free groups: "ei", "rhoa", "mass", "position", "string", "string_cubic".
    link_ei, link_rhoa : bool
        One EI (rhoA) variable, EI_1 (rhoA_1), the others keeping their starting ratios.
    ei_bounds, rhoa_bounds, mass_bounds, position_bounds : (float, float)
        Bounds of every EI [N m^2] (Fig 13's 50-3000), rhoA [kg/m], added mass [kg] and
        added mass's centre [x/L].
    mass_positions : sequence of float
        Centres x/L of added masses.
    mass_start : float
        Starting value of every added mass [kg].
    mass_width : float
        Width of each added mass's strip [m].
    ei_points, rhoa_points : sequence of float
        Control stations x/L of smooth EI(x), rhoA(x) profiles (first 0, last 1); empty: one
        value per segment.
    interpolation : {"pchip", "linear"}
        The profiles' interpolant.
    string_bounds, cubic_bounds : (float, float) or None
        Bounds of the string-bed stiffness (factor on K_CB [-] for the paper's law, k_s [N/m]
        for the series law) and of the series law's k_3 [N/m^3]; None: 0.5-2 and 0-2 times
        the start.
    """

    boundaries: Sequence[float] = BOUNDARIES
    vary: Sequence[str] = ("ei", "rhoa")
    link_ei: bool = False
    link_rhoa: bool = False
    ei_bounds: Sequence[float] = (50.0, 3000.0)
    rhoa_bounds: Sequence[float] = (0.2, 1.2)
    mass_positions: Sequence[float] = ()
    mass_bounds: Sequence[float] = (0.0, 0.03)
    mass_start: float = 0.0
    mass_width: float = DEFAULT_WIDTH
    position_bounds: Sequence[float] = (0.0, 1.0)
    ei_points: Sequence[float] = ()
    rhoa_points: Sequence[float] = ()
    interpolation: str = "pchip"
    string_bounds: Sequence[float] | None = None
    cubic_bounds: Sequence[float] | None = None


@dataclass(frozen=True)
class ZoneOptions:
    """Where and how fast the ball strikes, which ball, and the player's swing.

    Attributes
    ----------
    zone : {"uniform", "node"}
        Uniform over ``zone_range``, or a Gaussian of ``zone_sigma`` about the starting
        racket's mode-1 node on the string face (Hatze 1994).
    zone_range : (float, float)
        The uniform zone x/L.
    zone_points : int
        Impact points in the zone.
    zone_sigma : float
        Standard deviation of the node zone x/L.
    speeds : sequence of float
        Incoming ball speeds [m/s].
    racket_speed : float or None
        Swing: the reference point's speed towards the ball with the starting racket [m/s]
        (:class:`.swing.SwingModel`); a stationary racket when None.
    reference, pivot, swing_exponent : float
        The swing's reference point x/L, pivot from the butt [m] and the exponent of the
        swing speed in the racket's inertia.
    ball_mass, zeta : float or None
        m_B [kg] and the ball/string damping ratio (None: 0.057 kg, and the clamped COR 0.83's).
    """

    zone: str = "uniform"
    zone_range: Sequence[float] = (0.6, 0.9)
    zone_points: int = 20
    zone_sigma: float = 0.05
    speeds: Sequence[float] = (20.0, 30.0, 40.0)
    racket_speed: float | None = None
    reference: float = 0.75
    pivot: float = SWING_WEIGHT_AXIS
    swing_exponent: float = SWING_EXPONENT
    ball_mass: float | None = None
    zeta: float | None = None


@dataclass(frozen=True)
class ObjectiveOptions:
    """What a design study maximises or minimises, and within which bounds.

    Attributes
    ----------
    objectives : sequence of str
        Names from :data:`.variables.OBJECTIVES`.
    constraints : dict or None
        Quantity name (:data:`.variables.QUANTITIES`) -> None, ``(low, high)`` or
        ``("start",)`` (the starting racket's value).
    stiffness_cost : float
        Price on EI_1 [1/(N m^2)].
    power_fraction : float
        The power region's fraction of the largest v_out.
    grip : {"loose", "firm"}
        The hand of the handle-shock objectives (:data:`fem_racket.frame.hand.GRIPS`).
    shock_window : float
        Window of the handle-shock measures [s].
    """

    objectives: Sequence[str] = ("cor",)
    constraints: dict[str, Sequence[Any] | None] | None = None
    stiffness_cost: float = 0.0
    power_fraction: float = 0.9
    grip: str = "loose"
    shock_window: float = DEFAULT_WINDOW


#: The option groups of a design problem, by their field in :class:`DesignOptions`.
GROUPS = {"variables": VariableOptions, "zone_options": ZoneOptions, "goals": ObjectiveOptions}


@dataclass(frozen=True)
class DesignOptions:
    """Every setting of a design problem but its starting racket.

    Attributes
    ----------
    variables : VariableOptions
    zone_options : ZoneOptions
    goals : ObjectiveOptions
    law : ContactLaw or None
        The ball/string law (the paper's linear one when None).
    elements : int
        Cells of each design's mesh.
    given : frozenset of str
        The options (fields of the groups, by name) the caller gave: one of them is refused
        where these settings would not use it even at its default value, as any other value
        (:mod:`.unused`); one not named here is refused only at another value than its
        default. :meth:`from_keywords` names every keyword; the commands name what the command
        line gave.
    """

    variables: VariableOptions = field(default_factory=VariableOptions)
    zone_options: ZoneOptions = field(default_factory=ZoneOptions)
    goals: ObjectiveOptions = field(default_factory=ObjectiveOptions)
    law: ContactLaw | None = None
    elements: int = 20
    given: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        refuse_unused(self)  # an option these settings would not use (:mod:`.unused`)

    @classmethod
    def from_keywords(cls, **options: Any) -> DesignOptions:
        """The options from flat keywords (a field of any group, ``law``, ``elements``); an
        unknown one is refused with the nearest known name."""
        names = {f.name: g for g, kind in GROUPS.items() for f in fields(kind)}
        check_names("design_problem", options, (*names, "law", "elements"))
        groups = {
            g: kind(**{k: v for k, v in options.items() if names.get(k) == g})
            for g, kind in GROUPS.items()
        }
        rest = {k: options[k] for k in ("law", "elements") if k in options}
        return cls(**groups, **rest, given=frozenset(options))


@dataclass(frozen=True)
class SearchOptions:
    """How an optimisation searches (:mod:`.solvers`, :mod:`.pareto`).

    Attributes
    ----------
    method : {"SLSQP", "trust-constr", "differential-evolution", "nsga2"}
    maxiter : int
        Iterations (local) or generations (differential evolution).
    popsize : int
        Differential evolution: population per variable.
    pop_size, generations : int
        NSGA-II: population and generations.
    seed : int
        Random seed of the global methods, 0 to :data:`MAX_SEED`.
    given : frozenset of str
        The options given (as :attr:`DesignOptions.given`): refused, even at the default,
        where the method would not use them.
    """

    method: str = "SLSQP"
    maxiter: int = 100
    popsize: int = 10
    pop_size: int = 50
    generations: int = 100
    seed: int = 1
    given: frozenset[str] = frozenset()

    def __post_init__(self) -> None:
        refuse_unused_search(self)  # a budget the method would not use (:mod:`.unused`)
        check_seed(self.seed)


@dataclass(frozen=True)
class ExecutionOptions:
    """Where designs run (:class:`.evaluate.Evaluator`) and whether progress shows.

    Attributes
    ----------
    backend : {"serial", "processes", "dask"} or None
        None: the evaluator's choice by batch size.
    workers : int or None
        Processes of the local pool (all cores when None).
    scheduler : str or None
        Dask scheduler address.
    progress : bool or None
        Progress bar on stderr; None: only on a terminal.
    """

    backend: str | None = None
    workers: int | None = None
    scheduler: str | None = None
    progress: bool | None = None


def check_seed(seed: Any) -> int:
    """``seed`` as an int, refused unless an integer from 0 to :data:`MAX_SEED` (what numpy's
    generators take), before any design runs."""
    return check_integer("seed", seed, minimum=0, maximum=MAX_SEED)


def check_names(where: str, given: Any, known: Sequence[str]) -> None:
    """Refuse, in one line, a name of ``given`` not in ``known`` (with the nearest one)."""
    for key in given:
        if key not in known:
            near = difflib.get_close_matches(key, known, n=1)
            hint = f"; did you mean {near[0]!r}?" if near else ""
            raise InputError(f"option {key!r} is not known to {where}{hint}")
