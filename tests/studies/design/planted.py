"""A planted design function for the design-study tests: synthetic outputs with a known optimum,
so that a solver, a constraint or a resumed history is checked without solving impacts."""

import numpy as np

from fem_racket.studies.design.objectives import output_names

#: The planted optimum in the unit box (ei_1, ei_2, rhoa_1, rhoa_2).
CENTRE = np.array([0.3, 0.6, 0.45, 0.7])
#: The ball speed's optimum: the Pareto front of (cor, ball_speed) is the segment CENTRE-OTHER.
OTHER = np.array([0.7, 0.2, 0.65, 0.3])


def planted(problem, designs):
    """Synthetic outputs: "mass" = sum of unit coordinates, cor = 1 - |u - CENTRE|^2,
    ball_speed = -|u - OTHER|^2; the other quantities 0."""
    u = problem.to_unit(designs)
    out = np.zeros((len(u), len(output_names(problem))))
    names = output_names(problem)
    out[:, names.index("mass_kg")] = u.sum(axis=1)
    for name, c, base in (("cor", CENTRE, 1.0), ("ball_speed", OTHER, 0.0)):
        if name in names:
            out[:, names.index(name)] = base - ((u - c) ** 2).sum(axis=1)
    return out
