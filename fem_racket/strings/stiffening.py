"""The bed's geometric stiffening: the strings stretch and their tension rises as the bed deflects.

The dynamic model (:mod:`fem_racket.strings.point`) keeps the tension at its strung value T (a
linear membrane). This module measures what that leaves out. A bed deflected by u(x, y) stretches
its mains, on average over the head, by the strain (1/A) int u_x^2/2 dA and its crosses by
(1/A) int u_y^2/2 dA, so each string's tension becomes ``T + EA eps`` (EA: the string's axial
rigidity) and the bed's tensions per width ``N_x, N_y`` rise with them. Static equilibrium under
the ball's disk load with those tensions (uniform over the bed: the Foeppl-type membrane
approximation, each direction's strain averaged over the head) is solved by a fixed point on
the tension at a given mean deflection w_bar over the disk::

    u = w_bar K(N)^-1 q / (q^T K(N)^-1 q),   eps_x = u^T Kxx u / (2 A),   eps_y = u^T Kyy u / (2 A)

and the secant stiffness there is ``k(N) = 1 / (q^T K(N)^-1 q)``. The ratio k(w_bar)/k(0) is
the stiffening (``DESIGN.md`` section 10: modest, of order 5-30 % at 10-20 mm, typical).
"""

from __future__ import annotations

import numpy as np

from fem_racket.strings.bed import StringBed
from fem_racket.strings.membrane import bed_mesh, disk_load
from fem_racket.strings.point import DEFAULT_REFINE
from fem_racket.validation import check_range

__all__ = ["stiffening", "stiffening_ratio"]

#: Most fixed-point iterations on the tension, and their relative convergence tolerance.
ITERATIONS = 50
TOLERANCE = 1e-12


def stiffening(
    bed: StringBed, deflection_m: float, point=(0.0, 0.0), refine: int = DEFAULT_REFINE
) -> tuple[float, float, float]:
    """Secant stiffness [N/m] at mean deflection ``deflection_m`` [m] under the ball's disk at
    ``point`` (from the head's centre [m]), and the mains' and crosses' tensions there [N]."""
    from scipy.sparse.linalg import splu

    w = check_range("deflection", deflection_m, 0.0, 0.1, unit="m")
    mesh = bed_mesh(float(bed.head_length_m), float(bed.head_width_m), refine)
    q = disk_load(mesh, np.asarray(point, dtype=float)[None], bed.load_radius_m)[:, 0]
    ea = bed.material.axial_rigidity_n
    t_x = t_y = float(bed.tension_n)
    for _ in range(ITERATIONS):
        n_x = bed.mains * t_x / bed.head_width_m
        n_y = bed.crosses * t_y / bed.head_length_m
        u = splu((n_x * mesh.Kxx + n_y * mesh.Kyy).tocsc()).solve(q)
        c = float(q @ u)
        u *= w / c
        new_x = bed.tension_n + ea * float(u @ (mesh.Kxx @ u)) / (2.0 * bed.area_m2)
        new_y = bed.tension_n + ea * float(u @ (mesh.Kyy @ u)) / (2.0 * bed.area_m2)
        done = abs(new_x - t_x) + abs(new_y - t_y) <= TOLERANCE * bed.tension_n
        t_x, t_y = new_x, new_y
        if done:
            break
    else:
        raise RuntimeError(f"the bed's tension did not converge at deflection {w} m")
    return 1.0 / c, t_x, t_y


def stiffening_ratio(bed: StringBed, deflection_m: float) -> float:
    """k(deflection) / k(0) at the head's centre: the bed's stiffening [-]."""
    return stiffening(bed, deflection_m)[0] / stiffening(bed, 0.0)[0]
