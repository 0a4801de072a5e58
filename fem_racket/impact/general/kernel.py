"""The general integrator's march, compiled (numba): every case on its own frame and step.

The discrete equations are those of :mod:`fem_racket.impact.general.march` (a piecewise-cubic
force on a uniform grid, the contact equation solved at each node, the law's own end
condition), evaluated in modal form: instead of the convolution tables of
:mod:`fem_racket.impact.general.receptance` (O(N^2) per case), each kept mode carries its state
y = x' + i omega x from node to node exactly for the step's cubic force (the recursion of
:mod:`fem_racket.impact.general.histories`), y_{k+1} = e^{i theta} (y_k + a^2 h sum_r F_r G_r),
so a node costs O(modes) (:mod:`fem_racket.impact.general.kernel_modes`). A case's law
parameters are a tuple and its histories one (5, N) array, so a node costs no reference counts.
Every case brings its own frequencies, mode values and step, so one call serves a batch spanning
many frames. The starting nodes 1-3 (forward stencil) are solved by Gauss-Seidel sweeps over
their 4 x 4 weights, as the march does.

Outputs per case: the nodal histories and one row of :data:`RESULTS`: the separation step and
fraction, a status (0 separated, 1 still in contact at the last node, 2 Newton did not
converge), the largest h |dz'/dz| of an ODE state (the march's stiffness), the flexible modes'
energy at the separation node, and what the outcome and the energy balance
(:func:`fem_racket.impact.general.vouch.energy_residual`) integrate from the histories (as
:mod:`fem_racket.impact.general.march` integrates its outcome in numpy): the impulse up to
separation, the peak force (a parabola through the largest node and its neighbours), and the
contact work int F delta' dt and impulse over the whole steps up to the separation node.
"""

from __future__ import annotations

import numpy as np

from fem_racket.impact.general import kernel_laws as kl
from fem_racket.impact.general import kernel_modes as km
from fem_racket.impact.general import kernel_node as kn
from fem_racket.impact.general.jit import njit
from fem_racket.impact.kernel_cache import KERNEL_OPTIONS

__all__ = ["RESULTS", "march_cases"]

_START_SWEEPS = 12
#: Nodes per case the histories' store holds before it grows (its pages are touched only as
#: written).
_STORE = 1024
_F, _D, _V, _Z, _G = kn.F, kn.D, kn.V, kn.Z, kn.G
#: The columns of the kernel's result row per case.
RESULTS = (
    "last",
    "fraction",
    "status",
    "stiffness",
    "flexible_energy",
    "impulse",
    "peak_force",
    "work",
    "node_impulse",
)


@njit(**KERNEL_OPTIONS)
def _start(kind, p, modal, rigid, fdv, H, scale):
    """Nodes 1-3 by Gauss-Seidel sweeps over their 4 x 4 weights (``modal`` = (e^{i theta},
    a^2, G, omega), ``rigid`` as kernel_modes.advance takes it); returns whether Newton
    converged, and the modal states (y, R, R') at node 3."""
    law, state = kind[0], kind[1]
    e, a2, Gw, w = modal
    h, c1 = rigid[1], rigid[2]
    mod = (e, a2, Gw)
    Wd, Wv = km.start_weights(mod, w, rigid)
    H[_D, 0], H[_V, 0] = fdv[0, 0], fdv[1, 0]
    H[_F, 0] = kl.force(law, p, H[_D, 0], H[_V, 0], 0.0)
    if state == 2:
        H[_G, 0] = kl.rate(law, p, H[_D, 0], H[_V, 0], 0.0)
    for m in range(1, 4):
        H[_F, m], H[_G, m] = H[_F, 0], H[_G, 0]
    for _ in range(_START_SWEEPS):
        conv = True
        for m in range(1, 4):
            fb, zb = H[_F, m], H[_Z, m]
            A, B = fdv[0, m], fdv[1, m]
            for j in range(4):
                if j != m:
                    A -= Wd[m, j] * H[_F, j]
                    B -= Wv[m, j] * H[_F, j]
            s = m if m < 3 else 0
            lin = (A, B, Wd[m, m], Wv[m, m])
            prev = kn.node_base(kind, H, c1, (m, 0, s), h)
            Fm, d, v, zm, ok = kn.solve_node(kind, p, prev, lin, H[_F, m], (h, scale))
            _store(kind, p, H, m, (Fm, d, v, zm))
            if not ok:
                return False, np.zeros(0, dtype=np.complex128), 0.0, 0.0
            conv &= abs(H[_F, m] - fb) <= 1e-13 * (abs(H[_F, m]) + scale)
            conv &= abs(H[_Z, m] - zb) <= 1e-13 * (abs(H[_Z, m]) + 1e-9)
        if conv:
            break
    y = np.zeros(w.size, dtype=np.complex128)
    R, Rv = 0.0, 0.0
    for k in range(3):
        R, Rv = km.advance(y, (R, Rv), H[_F, :4], 1 + k if k < 2 else 0, mod, rigid)
    return True, y, R, Rv


@njit(**KERNEL_OPTIONS)
def _store(kind, p, H, m, node):
    """Node m's F, delta, delta', z (and z' of an ODE state) into the histories."""
    Fm, d, v, zm = node
    H[_F, m], H[_D, m], H[_V, m], H[_Z, m] = Fm, d, v, zm
    if kind[1] == 2:
        H[_G, m] = kl.rate(kind[0], p, d, v, zm)


@njit(**KERNEL_OPTIONS)
def _continue_branch(H, m, kd0, kv0):
    """The force was cut to zero past the end at node m: the step's cubic takes the branch's
    cubic continuation instead (the cut is a kink the cubic would smear, O(h^2))."""
    F = H[_F]
    dF = 4.0 * F[m - 1] - 6.0 * F[m - 2] + 4.0 * F[m - 3] - F[m - 4] - F[m]
    H[_F, m], H[_D, m], H[_V, m] = F[m] + dF, H[_D, m] - kd0 * dF, H[_V, m] - kv0 * dF


@njit(**KERNEL_OPTIONS)
def _case(kind, p, modes, grid, fdv, cs, H, res):
    """March one case (histories H = F, D, V, Z, G; ``modes`` = (omega, a^2) of the modes kept,
    ``grid`` = (mu0, h, nodes, force scale, speed), free motion fdv (2, >= nodes): given, or
    (speed NaN) the ball at ``speed`` on a frame at rest, filled node by node) into ``res``."""
    law, state, end, extend = kind
    w, a2 = modes
    mu0, h, n, scale, v = grid
    e = np.exp(1j * w * h)
    Gw, c1, c2 = km.step_weights(e, w, h, cs)
    rigid = (mu0, h, c1, c2)
    ok, y, R, Rv = _start(kind, p, (e, a2, Gw, w), rigid, fdv, H, scale)
    if not ok:
        res[2] = 2.0
        return
    Bw = km.backward_weights(e, a2, h, Gw, w)
    nm = Bw.shape[1]
    kd0, kv0 = mu0 * h * h * c2[0, 3], mu0 * h * c1[0, 3]  # node m's own weight
    for j in range(nm):  # the states at node 3
        Bw[13, j], Bw[14, j] = y[j].real, y[j].imag
        kd0 += Bw[11, j] * Bw[12, j]
        kv0 += Bw[10, j]
    stiff = 0.0
    half, odd = nm // 2, nm % 2 == 1
    hc1 = (h * c1[0, 0], h * c1[0, 1], h * c1[0, 2], h * c1[0, 3])
    for m in range(1, n):
        b = max(m - 3, 0)
        s = 0 if m >= 3 else m
        if m >= 4:
            if v == v:  # at rest: the free motion up to node m only (the march stops early)
                fdv[0, m], fdv[1, m] = v * (m * h), v
            f0, f1, f2 = H[_F, b], H[_F, b + 1], H[_F, b + 2]
            fd = f0 * c2[0, 0] + f1 * c2[0, 1] + f2 * c2[0, 2]
            fv = f0 * c1[0, 0] + f1 * c1[0, 1] + f2 * c1[0, 2]
            R, Rv = R + h * Rv + mu0 * h * h * fd, Rv + mu0 * h * fv
            # the modes over the step (kernel_modes.backward_weights; states and weights rows
            # of one array at fixed rows: no run-time overlap checks), written out here: an
            # array passed to a function costs two atomic reference counts per node
            for j in range(nm):
                yr, yi = Bw[13, j], Bw[14, j]
                er, ei = Bw[0, j], Bw[1, j]
                Bw[13, j] = er * yr - ei * yi + Bw[2, j] * f0 + Bw[4, j] * f1 + Bw[6, j] * f2
                Bw[14, j] = er * yi + ei * yr + Bw[3, j] * f0 + Bw[5, j] * f1 + Bw[7, j] * f2
            if m == 4:  # from now on the state lacks its node's own term: B_2 + e^{i theta} B_3
                for j in range(nm):
                    Bw[6, j], Bw[7, j] = Bw[8, j], Bw[9, j]
            # two fixed partial sums: the same bits in any batch
            d0, d1, v0, v1 = 0.0, 0.0, 0.0, 0.0
            for j in range(half):
                d0 += Bw[14, 2 * j] * Bw[12, 2 * j]
                d1 += Bw[14, 2 * j + 1] * Bw[12, 2 * j + 1]
                v0 += Bw[13, 2 * j]
                v1 += Bw[13, 2 * j + 1]
            if odd:
                d0 += Bw[14, nm - 1] * Bw[12, nm - 1]
                v0 += Bw[13, nm - 1]
            md, mv = d0 + d1, v0 + v1
            guess = 3.0 * H[_F, m - 1] - 3.0 * H[_F, m - 2] + H[_F, m - 3]
            lin = (fdv[0, m] - (R + md), fdv[1, m] - (Rv + mv), kd0, kv0)
            zb, zc = H[_Z, m - 1], 0.0
            if state == 2:  # Adams-Moulton on the step's cubic (kernel_node.node_base)
                acc = 0.0
                for r in range(4):
                    acc += H[_G, b + r] * hc1[r]
                zc = hc1[3]
                zb = H[_Z, m - 1] + acc - zc * H[_G, m]
            prev = (H[_Z, m - 1], zb, zc, H[_D, m - 1], H[_V, m - 1])
            Fm, d, dv, zm, ok = kn.solve_node(kind, p, prev, lin, guess, (h, scale))
            H[_F, m], H[_D, m], H[_V, m], H[_Z, m] = Fm, d, dv, zm
            if state == 2:
                H[_G, m] = kl.rate(law, p, d, dv, zm)
            if not ok:
                res[2] = 2.0
                return
            R += mu0 * h * h * c2[0, 3] * H[_F, m]
            Rv += mu0 * h * c1[0, 3] * H[_F, m]
        if state == 2:
            gz = kl.rate_partials(law, p, H[_D, m], H[_V, m], H[_Z, m])[2]
            stiff = max(stiff, h * abs(gz))
        if kn.ended(
            kind, p, (H[_F, m - 1], H[_D, m - 1], H[_Z, m - 1]), (H[_F, m], H[_D, m], H[_Z, m])
        ):
            cut = extend and end == 0 and m >= 5
            if cut and kl.force(law, p, H[_D, m], H[_V, m], H[_Z, m]) == 0.0:
                _continue_branch(H, m, kd0, kv0)
            res[0], res[1] = m, kn.fraction(kind, p, H, (m, b, s), h, cs)
            res[2], res[3] = 0.0, stiff
            own = H[_F, m] if m >= 4 else 0.0  # node m's own weight, not yet in Y
            energy = 0.0
            for j in range(nm):
                if a2[j] > 0:
                    yr, yi = Bw[13, j] + Bw[10, j] * own, Bw[14, j] + Bw[11, j] * own
                    energy += 0.5 * (yr * yr + yi * yi) / a2[j]
            res[4] = energy
            kn.integrals(H, (m, res[1], n), h, cs, c1, res)
            return
    res[2] = 1.0


@njit(**KERNEL_OPTIONS)
def march_cases(kind, P, modes, cases, fdv, cs, keep):
    """March every case; see the module docstring.

    Parameters
    ----------
    kind : (4,) int tuple
        Law number (kernel_laws.LAW_IDS), state (0 none, 1 memory, 2 ODE), end (0
        displacement, 1 force, 2 state), and ``extend``: where a "displacement" law's force is
        cut to zero at the separation node, continue its branch there by cubic extrapolation
        (0: the march's equations as they are).
    P : (C, p) law parameters
    modes : (W, A2, nmode)
        (C, M) frequencies [rad/s] and a^2 [1/kg] of the modes kept (the pseudo-mode among
        them), the first nmode[c] of each row.
    cases : (mu0, h, nsteps, speed, scale)
        (C,) compliance [1/kg], step [s], nodes, speed [m/s] and Newton's force scale [N].
    fdv : (C, 2, N) free delta and delta' (empty: the ball at ``speed`` on a frame at rest)
    cs : (3, 4, 4) Lagrange coefficients (cubic_force.STENCILS)
    keep : bool
        Return the histories (False: H has no columns).

    Returns
    -------
    store : ndarray (5, T)
        F, delta, delta', z, z' at the nodes each case marched, case by case (none if not
        ``keep``).
    start : ndarray of int (C + 1,)
        Case c's nodes are the columns start[c]:start[c + 1] of ``store``.
    res : ndarray (C, len(RESULTS))
        One row of :data:`RESULTS` per case.

    Each case marches in one work array (zeroed after it where it wrote: every case starts as
    if alone) and only as far as it needs, so ``nsteps`` may be generous (t_max) at no cost;
    no array is padded to the longest case.
    """
    W, A2, nmode = modes
    mu0, h, nsteps, speed, scale = cases
    ncase, N = h.size, 0
    for c in range(ncase):  # the longest case (not nsteps.max(): it links numba.np.arraymath)
        N = max(N, nsteps[c])
    work = np.zeros((5, N))
    res = np.zeros((ncase, len(RESULTS)))
    res[:, 0] = -1.0
    given = fdv.shape[0] > 0
    free = np.empty((2, N))
    start = np.zeros(ncase + 1, dtype=np.int64)
    store = np.empty((5, ncase * min(N, _STORE) if keep else 0))  # grown if short
    for c in range(ncase):
        n = nsteps[c]
        v = np.nan
        if given:
            for m in range(n):
                free[0, m], free[1, m] = fdv[c, 0, m], fdv[c, 1, m]
        else:
            v = speed[c]
            for m in range(4):
                free[0, m], free[1, m] = v * (m * h[c]), v
        # the modes kept and zero modes (a^2 = 0: no weight, no state) up to a multiple of 4
        # where the rows have room, so the pass over the modes has no scalar remainder
        k = min(-(-nmode[c] // 4) * 4, W.shape[1])
        p = (P[c, 0], P[c, 1], P[c, 2], P[c, 3])  # a tuple: no reference counts per node
        grid = (mu0[c], h[c], n, scale[c], v)
        _case(kind, p, (W[c, :k], A2[c, :k]), grid, free, cs, work, res[c])
        u = min(max(int(res[c, 0]) + 1, 4), n) if res[c, 2] == 0.0 else n
        if keep:
            start[c + 1] = start[c] + u
            if start[c + 1] > store.shape[1]:
                more = np.empty((5, max(2 * store.shape[1], start[c + 1])))
                more[:, : start[c]] = store[:, : start[c]]
                store = more
            store[:, start[c] : start[c + 1]] = work[:, :u]
        work[:, :u] = 0.0
    return store[:, : start[ncase]], start, res
