"""One impact through the batched engine, with the state at separation (for ``simulate``).

``simulate(..., output_step=None)`` needs only t = 0 and t = t_c. From the engine's roots
lambda_j and contact-force residues f_j = (K_CB + C_CB lambda_j) r_j (per unit speed, see
:mod:`fem_racket.impact.exact.roots`), with F(t) = Re sum m f_j exp(lambda_j t)::

    J(t) = Re sum m f_j (e^{lambda t} - 1) / lambda
    P(t) = Re sum m f_j (e^{lambda t} - 1 - lambda t) / lambda^2
    ball:            u_B = V t - P/m_B,   v_B = V - J/m_B
    rigid mode r:    eta_r = a_r P,       eta_r' = a_r J
    kept mode f:     eta_f = Re sum m a_f f_j e^{lambda_j t} / (lambda_j^2 + omega_f^2)
    dropped mode f:  eta_f = a_f F(t) / omega_f^2   (quasi-static, as the pseudo-mode assumes)

(eta_f(s) = a_f F(s) / (s^2 + omega_f^2), and F(s) vanishes at s = +-i omega_f for a mode in the
model, so only the lambda_j are poles). With ``tolerance=None`` no mode is dropped and the state
is exact.
"""

from __future__ import annotations

import math

import numpy as np

from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.frame.model import FrameModel
from fem_racket.impact.exact.roots import RootSet, coupled_roots
from fem_racket.impact.exact.separation import impulse, peak_force, separation_time
from fem_racket.impact.offaxis import RIGID_OFFAXIS, combined_modes, combined_point_vector
from fem_racket.impact.point import frame_modal_data
from fem_racket.impact.problem import Impact
from fem_racket.impact.reduction import cutoff_factor, pole_blocks
from fem_racket.impact.system import Trajectory, no_separation, output_times

__all__ = ["engine_impact"]

#: Give up on separation after this many eq-11 contact times (as the exact path).
T_MAX_FACTOR = 20.0


def engine_impact(
    model: FrameModel,
    impact: Impact,
    ball: Ball,
    contact: LinearContact,
    *,
    separation: str,
    modes: int | None,
    tolerance: float | None,
    t_max: float | None,
    offset: float = 0.0,
    output_step: float | None = None,
) -> tuple[Trajectory, np.ndarray, int]:
    """Trajectory at t = 0 and t_c (or every ``output_step`` [s] between them) in the
    coordinates [u_B, rigid, flexible modes], the matrix taking the frame coordinates to
    Hermite DOFs (off axis: then the torsion DOFs, see
    :func:`fem_racket.impact.offaxis.combined_modes`), and the number of flexible modes in the
    model (those above the cut-off are represented by the residual pseudo-mode).

    ``modes`` bounds the frame modes used (a plain truncation, as the other paths);
    ``tolerance`` then drops those not needed for it (None: keep them all). ``offset`` [m]: the
    impact point's distance from the long axis (:mod:`fem_racket.impact.offaxis`).
    ``output_step``: histories at :func:`~fem_racket.impact.system.output_times`, by the same
    sums at each time (the rows at 0 and t_c are those without histories).
    """
    x_i = impact.position * model.mesh.length
    if offset == 0.0:
        fm = model.modes(modes)
        data = frame_modal_data(model, np.array([impact.position]), None, limit=fm.omega.size)
        omega, a, shapes = data.omega, data.values[0], fm.all_shapes
        rig = model.fe.point_vector(x_i) @ fm.rigid
        rigid = float(data.rigid[0])
    else:  # off axis: bending and torsion modes in one basis (fem_racket.impact.offaxis)
        cm = combined_modes(model, modes)
        aa = cm.all_shapes.T @ combined_point_vector(model, x_i, offset)
        omega, a, shapes, rig = cm.omega, aa[RIGID_OFFAXIS:], cm.all_shapes, aa[:RIGID_OFFAXIS]
        rigid = float(rig @ rig)
    k = contact.stiffness
    c = contact.damping(ball.mass)
    mu0 = 1.0 / ball.mass + rigid
    wc = math.sqrt(k * mu0)
    t_est = math.pi / wc
    limit = T_MAX_FACTOR * t_est if t_max is None else t_max
    # As the batch: a near-touch of zero before separation is solved again with every mode.
    for beta in (cutoff_factor(tolerance, separation), math.inf):
        kept, lam, res, mult, tc, touch = _reduced(omega, a, mu0, k, c, beta, separation, limit)
        if not touch:
            break
    if not tc <= limit:
        raise no_separation(limit)
    fw = (k + c * lam) * res
    one = RootSet(lam[None], res[None], mult)
    J = float(impulse(one, fw[None], np.array([tc]))[0])
    m = mult
    e = np.exp(lam * tc)
    P = m * float((fw * (np.expm1(lam * tc) - lam * tc) / lam**2).real.sum())
    F = m * float((fw * e).real.sum())
    dF = m * float((fw * lam * e).real.sum())
    V = impact.speed
    n_rigid = rig.size
    times = output_times(output_step, tc)
    x = np.zeros((times.size, 1 + n_rigid + a.size))
    xv = np.zeros_like(x)
    x[-1, 0], xv[0, 0], xv[-1, 0] = tc - P / ball.mass, 1.0, 1.0 - J / ball.mass
    x[-1, 1 : 1 + n_rigid], xv[-1, 1 : 1 + n_rigid] = rig * P, rig * J
    w2 = omega**2
    den = lam[None, :] ** 2 + w2[:, None]  # (modes, roots)
    x[-1, 1 + n_rigid :] = a * np.where(
        np.arange(a.size) < kept, m * ((fw * e)[None, :] / den).real.sum(axis=1), F / w2
    )
    xv[-1, 1 + n_rigid :] = a * np.where(
        np.arange(a.size) < kept, m * ((fw * lam * e)[None, :] / den).real.sum(axis=1), dF / w2
    )
    if times.size > 2:
        _between(x, xv, times[1:-1], (rig, a, w2, kept, ball.mass), (lam, fw, m, den))
    peak = _peak(omega, a, mu0, k, c, separation, limit) if kept < a.size else None
    if peak is None:
        peak = float(peak_force(one, fw[None], np.array([tc]))[0][0])
    peak *= V
    traj = Trajectory(times, x * V, xv * V, peak)
    return traj, shapes, int(omega.size)


def _between(x, xv, t, frame, roots) -> None:
    """Fill rows 1 to -2 of ``x`` and ``xv`` (per unit speed) at times ``t`` [s], strictly
    between 0 and t_c, with the sums of the module docstring; ``frame`` is (rigid mode
    values, flexible mode values a_f, omega_f^2, modes kept, m_B), ``roots`` (lambda_j, f_j,
    multiplicity, the denominators lambda_j^2 + omega_f^2 of shape (modes, roots))."""
    rig, a, w2, kept, mb = frame
    lam, fw, m, den = roots
    lt = np.multiply.outer(t, lam)
    e = np.exp(lt)
    em1 = np.expm1(lt)
    J = m * (fw * em1 / lam).real.sum(axis=1)
    P = m * (fw * (em1 - lt) / lam**2).real.sum(axis=1)
    F = m * (fw * e).real.sum(axis=1)
    dF = m * (fw * lam * e).real.sum(axis=1)
    n_rigid = rig.size
    x[1:-1, 0], xv[1:-1, 0] = t - P / mb, 1.0 - J / mb
    x[1:-1, 1 : 1 + n_rigid] = np.outer(P, rig)
    xv[1:-1, 1 : 1 + n_rigid] = np.outer(J, rig)
    flex = slice(1 + n_rigid, None)
    x[1:-1, flex] = np.outer(F, a / w2)  # dropped modes: quasi-static
    xv[1:-1, flex] = np.outer(dF, a / w2)
    inv = (1.0 / den[:kept]).T  # (roots, kept modes)
    x[1:-1, 1 + n_rigid : 1 + n_rigid + kept] = a[:kept] * m * ((fw * e) @ inv).real
    xv[1:-1, 1 + n_rigid : 1 + n_rigid + kept] = a[:kept] * m * ((fw * lam * e) @ inv).real


def _reduced(omega, a, mu0, k, c, beta, separation, limit):
    """Modes kept (below beta omega_c), upper roots, residues, their multiplicity, t_c [s] and
    the near-touch flag of one impact per unit speed (t_c NaN: no separation by ``limit``)."""
    zero = np.zeros(1)
    wc = math.sqrt(k * mu0)
    _, d, v = next(
        pole_blocks(omega[None], a[None], np.array([mu0]), np.array([wc]), beta, zero, zero)
    )
    kept = int(np.sum(omega < beta * wc))
    roots = next(r for p, r in coupled_roots(d, v, np.array([k]), np.array([c])) if p.size)
    lam = roots.lam[0]
    w = roots.res if separation == "displacement" else ((k + c * lam) * roots.res[0])[None]
    t_est = math.pi / wc
    t, touch = separation_time(roots, w, np.array([t_est]), np.array([limit]))
    return kept, lam, roots.res[0], roots.mult, float(t[0]), bool(touch[0])


def _peak(omega, a, mu0, k, c, separation, limit) -> float | None:
    """Peak contact force per unit speed [N s/m] on every mode over its own contact, as the
    histories' path (:func:`fem_racket.impact.exact.closed_form.peak_force`) finds it: the
    COR tolerance drops modes that the force's high-frequency ripple carries (2.4e-4 of the
    peak at 0.75 L and 20 m/s on the standard racket). None when that contact does not end."""
    _, lam, res, mult, tc, _ = _reduced(omega, a, mu0, k, c, math.inf, separation, limit)
    if not tc <= limit:
        return None
    fw = (k + c * lam) * res
    return float(peak_force(RootSet(lam[None], res[None], mult), fw[None], np.array([tc]))[0][0])
