"""The general integrator's march, compiled (numba): every case on its own frame and step.

The discrete equations are those of :mod:`fem_racket.impact.general.march` (a piecewise-cubic
force on a uniform grid, the contact equation solved at each node, the law's own end
condition), evaluated in modal form: instead of the convolution tables of
:mod:`fem_racket.impact.general.receptance` (O(N^2) per case), each kept mode carries its state
y = x' + i omega x from node to node exactly for the step's cubic force (the recursion of
:mod:`fem_racket.impact.law_impact`), y_{k+1} = e^{i theta} (y_k + a^2 h sum_r F_r G_r), so a
node costs O(modes). Every case brings its own frequencies, mode values and step, so one call
serves a batch spanning many frames. The starting nodes 1-3 (forward stencil) are solved by
Gauss-Seidel sweeps over their 4 x 4 weights, as the march does.

Outputs per case: the nodal histories, the separation step and fraction, a status (0 separated,
1 still in contact at the last node, 2 Newton did not converge), the largest h |dz'/dz| of an
ODE state (the march's stiffness) and the flexible modes' energy at the separation node.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from fem_racket.impact.general import kernel_laws as kl
from fem_racket.impact.general import kernel_modes as km

__all__ = ["march_cases"]

_JIT = {"cache": True, "nogil": True, "error_model": "numpy"}
_NEWTON_ITER = 40
_START_SWEEPS = 12


@njit(**_JIT)
def _newton(law, state, p, A, B, kd0, kv0, guess, zp, zb, zc, h, scale, d0, v0):
    """F and z at a node (as step.solve_step for one case); ok False if not converged."""
    F, z = guess, zp
    for _ in range(_NEWTON_ITER):
        d, v = A - kd0 * F, B - kv0 * F
        if state == 1:
            z = max(zp, kl.turn_max(d0, v0, d, v, h))
        f, fd, fv, fz = kl.force_partials(law, p, d, v, z)
        r1 = F - f
        tol = 1e-12 * (abs(F) + scale)
        if state == 2:
            r2 = z - zb - zc * kl.rate(law, p, d, v, z)
            if abs(r1) <= tol and abs(r2) <= 1e-12 * (abs(z) + 1e-9):
                return F, z, True
            gd, gv, gz = kl.rate_partials(law, p, d, v, z)
            j11 = 1.0 + fd * kd0 + fv * kv0
            j21 = zc * (gd * kd0 + gv * kv0)
            j22 = 1.0 - zc * gz
            det = j11 * j22 + fz * j21
            dF = -(r1 * j22 + fz * r2) / det
            z = z - (j11 * r2 - j21 * r1) / det
        else:
            if abs(r1) <= tol:
                return F, z, True
            dF = -r1 / (1.0 + fd * kd0 + fv * kv0)
        cap = 2.0 * (abs(F) + scale)
        F = F + max(min(dF, cap), -cap)
    return F, z, False


@njit(**_JIT)
def _ended(law, end, p, F, D, Z, m):
    """True where the contact ends in step m - 1 (nodes m - 1, m)."""
    if end == 1:
        return F[m - 1] > 0 and F[m] <= 0
    if end == 2:
        return Z[m - 1] > 0 and Z[m] <= 0
    e0, e1 = kl.end_value(law, p, Z[m - 1]), kl.end_value(law, p, Z[m])
    return D[m - 1] - e0 > 0 and D[m] - e1 <= 0


@njit(**_JIT)
def _fraction(law, end, p, H, m, b, s, h, cs):
    """Where in step m - 1 (stencil s from node b) the contact ended (0-1]."""
    F, D, V, Z, G = H
    if end == 1:
        coef = np.zeros(4)
        for r in range(4):
            for q in range(4):
                coef[q] += F[b + r] * cs[s, r, q]
        return kl.cubic_root(coef, F[m - 1], F[m])
    if end == 2:
        return kl.hermite_root(Z[m - 1], G[m - 1], Z[m], G[m], 0.0, h)
    return kl.hermite_root(D[m - 1], V[m - 1], D[m], V[m], kl.end_value(law, p, Z[m]), h)


@njit(**_JIT)
def _solve_node(law, state, p, H, m, b, s, A, B, kd0, kv0, guess, h, c1, scale):
    """The contact equation at node m (stencil s of step m - 1 from node b); False if Newton
    fails."""
    F, D, V, Z, G = H
    zb, zc = Z[m - 1], 0.0
    if state == 2:  # Adams-Moulton on the step's cubic: z_m = zb + zc g_m
        acc = 0.0
        for r in range(4):
            acc += G[b + r] * (h * c1[s, r])
        zc = h * c1[s, m - b]
        zb = Z[m - 1] + acc - zc * G[m]
    Fm, zm, ok = _newton(
        law, state, p, A, B, kd0, kv0, guess, Z[m - 1], zb, zc, h, scale, D[m - 1], V[m - 1]
    )
    d, v = A - kd0 * Fm, B - kv0 * Fm
    if state == 1:
        zm = max(Z[m - 1], kl.turn_max(D[m - 1], V[m - 1], d, v, h))
    F[m], D[m], V[m], Z[m] = Fm, d, v, zm
    if state == 2:
        G[m] = kl.rate(law, p, d, v, zm)
    return ok


@njit(**_JIT)
def _case(law, state, end, p, w, a2, mu0, h, n, fdv, scale, cs, extend, H, res):
    """March one case (histories H = F, D, V, Z, G up to node n - 1, free motion fdv = (2, n));
    res = (last, fraction, status, stiffness, flexible energy)."""
    F, D, V, Z, G = H
    nm = w.size
    e = np.exp(1j * w * h)
    Gw, c1, c2 = km.weights(w, h, cs)
    y = np.zeros(nm, dtype=np.complex128)
    # weights of the starting nodes 0-3 at nodes 1-3: unit forces through steps 0, 1, 2
    Wd, Wv, f = np.zeros((4, 4)), np.zeros((4, 4)), np.zeros(4)
    for node in range(4):
        f[:] = 0.0
        f[node] = 1.0
        y[:] = 0.0
        R, Rv = 0.0, 0.0
        for k in range(3):
            R, Rv = km.advance(y, R, Rv, f, 1 + k if k < 2 else 0, e, a2, mu0, h, Gw, c1, c2)
            Wd[k + 1, node], Wv[k + 1, node] = km.response(y, R, Rv, w)
    D[0], V[0] = fdv[0, 0], fdv[1, 0]
    F[0] = kl.force(law, p, D[0], V[0], 0.0)
    if state == 2:
        G[0] = kl.rate(law, p, D[0], V[0], 0.0)
    for m in range(1, 4):
        F[m], G[m] = F[0], G[0]
    for _ in range(_START_SWEEPS):
        conv = True
        for m in range(1, 4):
            fb, zb = F[m], Z[m]
            A, B = fdv[0, m], fdv[1, m]
            for j in range(4):
                if j != m:
                    A -= Wd[m, j] * F[j]
                    B -= Wv[m, j] * F[j]
            s = m if m < 3 else 0
            if not _solve_node(law, state, p, H, m, 0, s, A, B, Wd[m, m], Wv[m, m], F[m], h,
                               c1, scale):  # fmt: skip
                res[2] = 2.0
                return
            conv &= abs(F[m] - fb) <= 1e-13 * (abs(F[m]) + scale)
            conv &= abs(Z[m] - zb) <= 1e-13 * (abs(Z[m]) + 1e-9)
        if conv:
            break
    y[:] = 0.0
    R, Rv = 0.0, 0.0
    for k in range(3):
        R, Rv = km.advance(y, R, Rv, F[:4], 1 + k if k < 2 else 0, e, a2, mu0, h, Gw, c1, c2)
    kd0, kv0 = mu0 * h * h * c2[0, 3], mu0 * h * c1[0, 3]
    tail = np.empty(nm, dtype=np.complex128)  # node m's own weight in the backward step
    for j in range(nm):
        tail[j] = e[j] * a2[j] * h * Gw[0, 3, j]
        kd0 += tail[j].imag / w[j]
        kv0 += tail[j].real
    f[3] = 0.0
    stiff = 0.0
    for m in range(1, n):
        b = max(m - 3, 0)
        s = 0 if m >= 3 else m
        if m >= 4:
            f[:3] = F[b : b + 3]
            R, Rv = km.advance(y, R, Rv, f, 0, e, a2, mu0, h, Gw, c1, c2)
            rd, rv = km.response(y, R, Rv, w)
            guess = 3.0 * F[m - 1] - 3.0 * F[m - 2] + F[m - 3]
            A, B = fdv[0, m] - rd, fdv[1, m] - rv
            if not _solve_node(law, state, p, H, m, b, 0, A, B, kd0, kv0, guess, h, c1, scale):
                res[2] = 2.0
                return
            R += mu0 * h * h * c2[0, 3] * F[m]
            Rv += mu0 * h * c1[0, 3] * F[m]
            for j in range(nm):
                y[j] += tail[j] * F[m]
        if state == 2:
            gz = kl.rate_partials(law, p, D[m], V[m], Z[m])[2]
            stiff = max(stiff, h * abs(gz))
        if _ended(law, end, p, F, D, Z, m):
            if extend and end == 0 and m >= 5 and kl.force(law, p, D[m], V[m], Z[m]) == 0.0:
                # the force was cut to zero past the end: the step's cubic takes the branch's
                # cubic continuation instead (the cut is a kink the cubic would smear, O(h^2))
                dF = 4.0 * F[m - 1] - 6.0 * F[m - 2] + 4.0 * F[m - 3] - F[m - 4] - F[m]
                F[m], D[m], V[m] = F[m] + dF, D[m] - kd0 * dF, V[m] - kv0 * dF
                for j in range(nm):
                    y[j] += tail[j] * dF
            res[0], res[1] = m, _fraction(law, end, p, H, m, b, s, h, cs)
            res[2], res[3] = 0.0, stiff
            energy = 0.0
            for j in range(nm):
                if a2[j] > 0:
                    energy += 0.5 * (y[j].real ** 2 + y[j].imag ** 2) / a2[j]
            res[4] = energy
            return
    res[2] = 1.0


@njit(**_JIT)
def march_cases(law, state, end, P, W, A2, nmode, mu0, h, nsteps, speed, fdv, scale, cs, extend):
    """March every case; see the module docstring.

    Parameters
    ----------
    law, state, end : int
        Law number (kernel_laws.LAW_IDS), state (0 none, 1 memory, 2 ODE), end (0
        displacement, 1 force, 2 state).
    P : (C, p) law parameters; W, A2 : (C, M) frequencies [rad/s] and a^2 [1/kg] of the modes
    kept (the pseudo-mode among them), the first nmode[c] of each row; mu0 : (C,) compliance
    [1/kg]; h : (C,) step [s]; nsteps : (C,) nodes; speed : (C,) [m/s]; fdv : (C, 2, N) free
    delta and delta' (empty: the ball at ``speed`` on a frame at rest); scale : (C,) Newton's
    force scale [N]; cs : (3, 4, 4) Lagrange coefficients (cubic_force.STENCILS); extend :
    where a "displacement" law's force is cut to zero at the separation node, continue its
    branch there by cubic extrapolation (False: the march's equations as they are).

    Returns
    -------
    H : ndarray (5, C, N)
        F, delta, delta', z, z' at the nodes.
    res : ndarray (C, 5)
        Separation step, fraction, status, stiffness, flexible energy.
    """
    ncase, N = h.size, int(nsteps.max())
    H = np.zeros((5, ncase, N))
    res = np.zeros((ncase, 5))
    res[:, 0] = -1.0
    given = fdv.shape[0] > 0
    for c in range(ncase):
        n = nsteps[c]
        free = np.empty((2, n))
        for m in range(n):
            if given:
                free[0, m], free[1, m] = fdv[c, 0, m], fdv[c, 1, m]
            else:
                free[0, m], free[1, m] = speed[c] * (m * h[c]), speed[c]
        k = nmode[c]
        _case(
            law, state, end, P[c], W[c, :k], A2[c, :k], mu0[c], h[c], n, free, scale[c], cs, extend,
            (H[0, c], H[1, c], H[2, c], H[3, c], H[4, c]), res[c],
        )  # fmt: skip
    return H, res
