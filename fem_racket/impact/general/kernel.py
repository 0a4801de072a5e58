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

__all__ = ["RESULTS", "march_cases"]

_JIT = {"cache": True, "nogil": True, "error_model": "numpy"}
_START_SWEEPS = 12
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


@njit(**_JIT)
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
            if not kn.solve_node(kind, p, H, (m, 0, s), lin, H[_F, m], (h, scale), c1):
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


@njit(**_JIT)
def _integrals(H, at, h, cs, c1, res):
    """The impulse up to separation (``at`` = (last, fraction, nodes)), the peak force, and
    the contact work and impulse over the whole steps up to the last node, into ``res``."""
    last, frac, n = at
    imp, work, before = 0.0, 0.0, 0.0
    for k in range(last):
        s, b = (k + 1, 0) if k < 2 else (0, k - 2)
        si, sw = 0.0, 0.0
        for r in range(4):
            si += c1[s, r] * H[_F, b + r]
            sw += c1[s, r] * (H[_F, b + r] * H[_V, b + r])
        before = imp
        imp += h * si
        work += h * sw
    k = last - 1
    s, b = (k + 1, 0) if k < 2 else (0, k - 2)
    part = 0.0
    # frac^(j + 1) as numba multiplies an integer power, written out: the same bits interpreted
    f2 = frac * frac
    powers = (frac, f2, frac * f2, f2 * f2)
    for r in range(4):
        q = 0.0
        for j in range(4):
            q += cs[s, r, j] * (powers[j] / (j + 1.0))
        part += q * H[_F, b + r]
    res[5], res[7], res[8] = before + h * part, work, imp
    top = 0
    for k in range(1, last + 1):
        if H[_F, k] > H[_F, top]:
            top = k
    i = min(max(top, 1), n - 2)
    a = H[_F, i - 1]
    mid = H[_F, i] if i <= last else -np.inf
    c = H[_F, i + 1] if i + 1 <= last else -np.inf
    den = a - 2.0 * mid + c
    top_f, rise = H[_F, top], c - a
    res[6] = mid - 0.125 * (rise * rise) / den if np.isfinite(den) and den < 0.0 else top_f


@njit(**_JIT)
def _continue_branch(H, m, kd0, kv0):
    """The force was cut to zero past the end at node m: the step's cubic takes the branch's
    cubic continuation instead (the cut is a kink the cubic would smear, O(h^2))."""
    F = H[_F]
    dF = 4.0 * F[m - 1] - 6.0 * F[m - 2] + 4.0 * F[m - 3] - F[m - 4] - F[m]
    H[_F, m], H[_D, m], H[_V, m] = F[m] + dF, H[_D, m] - kd0 * dF, H[_V, m] - kv0 * dF


@njit(**_JIT)
def _case(kind, p, modes, grid, fdv, cs, H, res):
    """March one case (histories H = F, D, V, Z, G; ``modes`` = (omega, a^2) of the modes kept,
    ``grid`` = (mu0, h, nodes, force scale, speed), free motion fdv (2, >= nodes): given, or
    (speed NaN) the ball at ``speed`` on a frame at rest, filled node by node) into ``res``."""
    law, state, end, extend = kind
    w, a2 = modes
    mu0, h, n, scale, v = grid
    e = np.exp(1j * w * h)
    Gw, c1, c2 = km.weights(w, h, cs)
    rigid = (mu0, h, c1, c2)
    ok, y, R, Rv = _start(kind, p, (e, a2, Gw, w), rigid, fdv, H, scale)
    if not ok:
        res[2] = 2.0
        return
    Bw = km.backward_weights(e, a2, h, Gw, w)
    nm = w.size
    Y = np.empty((2, nm))
    kd0, kv0 = mu0 * h * h * c2[0, 3], mu0 * h * c1[0, 3]  # node m's own weight
    for j in range(nm):
        Y[0, j], Y[1, j] = y[j].real, y[j].imag
        kd0 += Bw[11, j] * Bw[12, j]
        kv0 += Bw[10, j]
    stiff = 0.0
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
            md, mv = km.stride(Y, Bw, (f0, f1, f2), m == 4)
            guess = 3.0 * H[_F, m - 1] - 3.0 * H[_F, m - 2] + H[_F, m - 3]
            lin = (fdv[0, m] - (R + md), fdv[1, m] - (Rv + mv), kd0, kv0)
            if not kn.solve_node(kind, p, H, (m, b, 0), lin, guess, (h, scale), c1):
                res[2] = 2.0
                return
            R += mu0 * h * h * c2[0, 3] * H[_F, m]
            Rv += mu0 * h * c1[0, 3] * H[_F, m]
        if state == 2:
            gz = kl.rate_partials(law, p, H[_D, m], H[_V, m], H[_Z, m])[2]
            stiff = max(stiff, h * abs(gz))
        if kn.ended(kind, p, H, m):
            cut = extend and end == 0 and m >= 5
            if cut and kl.force(law, p, H[_D, m], H[_V, m], H[_Z, m]) == 0.0:
                _continue_branch(H, m, kd0, kv0)
            res[0], res[1] = m, kn.fraction(kind, p, H, (m, b, s), h, cs)
            res[2], res[3] = 0.0, stiff
            own = H[_F, m] if m >= 4 else 0.0  # node m's own weight, not yet in Y
            energy = 0.0
            for j in range(nm):
                if a2[j] > 0:
                    yr, yi = Y[0, j] + Bw[10, j] * own, Y[1, j] + Bw[11, j] * own
                    energy += 0.5 * (yr * yr + yi * yi) / a2[j]
            res[4] = energy
            _integrals(H, (m, res[1], n), h, cs, c1, res)
            return
    res[2] = 1.0


@njit(**_JIT)
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
    H : ndarray (C, 5, W)
        F, delta, delta', z, z' at the nodes each case marched (zeros after them; W the most).
    res : ndarray (C, len(RESULTS))
        One row of :data:`RESULTS` per case.

    Each case marches in one work array (zeroed after it where it wrote: every case starts as
    if alone) and only as far as it needs, so ``nsteps`` may be generous (t_max) at no cost.
    """
    W, A2, nmode = modes
    mu0, h, nsteps, speed, scale = cases
    ncase, N = h.size, int(nsteps.max())
    work = np.zeros((5, N))
    res = np.zeros((ncase, len(RESULTS)))
    res[:, 0] = -1.0
    given = fdv.shape[0] > 0
    free = np.empty((2, N))
    used = np.zeros(ncase, dtype=np.int64)
    start = np.zeros(ncase + 1, dtype=np.int64)
    store = np.empty((5, 0))
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
        k = nmode[c]
        p = (P[c, 0], P[c, 1], P[c, 2], P[c, 3])  # a tuple: no reference counts per node
        grid = (mu0[c], h[c], n, scale[c], v)
        _case(kind, p, (W[c, :k], A2[c, :k]), grid, free, cs, work, res[c])
        u = min(max(int(res[c, 0]) + 1, 4), n) if res[c, 2] == 0.0 else n
        used[c] = u
        if keep:
            start[c + 1] = start[c] + u
            if start[c + 1] > store.shape[1]:  # grow the store of every case's histories
                more = np.empty((5, max(2 * store.shape[1], start[c + 1], 64 * ncase)))
                more[:, : start[c]] = store[:, : start[c]]
                store = more
            store[:, start[c] : start[c + 1]] = work[:, :u]
        work[:, :u] = 0.0
    H = np.zeros((ncase, 5, used.max() if keep else 0))
    if keep:
        for c in range(ncase):
            H[c, :, : used[c]] = store[:, start[c] : start[c + 1]]
    return H, res
