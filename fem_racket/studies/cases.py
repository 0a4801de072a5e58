"""One sweep case -> its result values, with everything reusable cached per process.

Each process (the caller, a pool worker or a Dask worker) keeps: the assembled frame and its
free-free modes per mesh (``FrameModel``), scaled copies for EI changes that scale every
segment (``FrameModel.scaled``: omega ~ sqrt(factor), no eigen-solve), the point vector g(x_i)
per impact point, and, for the exact solver, each case's outcome at unit speed. The coupled
system is linear, so at fixed K_CB the COR and t_c do not depend on the speed and the force
scales with it: cases differing only in speed share one solve, and every case is solved at
V_B0 = 1 m/s, which makes results independent of the order in which cases are run. A swing
(racket_speed, reference, pivot) enters through the closing speed v_in + v_r (K_CB follows it)
and v_out = e_A v_in + (1 + e_A) v_r (:mod:`fem_racket.impact.swing`).

Exact solver: :func:`fem_racket.impact.closed_form.exact_outcome` (scalars only). BDF solvers:
:func:`fem_racket.simulate` with 1 us output steps, the peak force being the largest over them.
"""

from __future__ import annotations

import logging
from collections import OrderedDict
from typing import Any

import numpy as np

from fem_racket.contact.linear import LinearContact
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import PAPER_EI1, standard_frame
from fem_racket.impact.closed_form import exact_outcome
from fem_racket.impact.simulate import simulate
from fem_racket.impact.swing import Swing, ball_speed_out, closing_speed
from fem_racket.impact.system import NoSeparationError, modal_system
from fem_racket.studies.grid import SweepSpec

__all__ = ["VARIABLES", "clear_caches", "run_chunk"]

log = logging.getLogger(__name__)

#: Result variables: name -> (units, description).
VARIABLES: dict[str, tuple[str, str]] = {
    "cor": ("1", "apparent coefficient of restitution (v_out - v_r)/(v_in + v_r)"),
    "contact_time_s": ("s", "contact time t_c"),
    "rebound_speed_m_s": ("m/s", "ball speed after impact -v_B(t_c) (v_out with a swing)"),
    "peak_force_n": ("N", "largest contact force"),
    "kcb_n_m": ("N/m", "ball/string stiffness K_CB used"),
    "racket_speed_at_impact_m_s": ("m/s", "impact point's speed towards the ball before impact"),
}
#: Output step of the BDF solvers in sweeps [s] (their peak force is the maximum over it).
BDF_OUTPUT_STEP = 1e-6

# Per-process caches (each pool or Dask worker fills its own).
_BASE: dict[tuple, FrameModel] = {}
_SCALED: OrderedDict[tuple, FrameModel] = OrderedDict()
_POINT: OrderedDict[tuple, np.ndarray] = OrderedDict()
_UNIT: OrderedDict[tuple, tuple[float, float, float]] = OrderedDict()


def _remember(cache: OrderedDict, key: tuple, value: Any, size: int) -> Any:
    cache[key] = value
    if len(cache) > size:
        cache.popitem(last=False)
    return value


def clear_caches() -> None:
    """Forget the models, point vectors and unit-speed outcomes cached in this process."""
    for cache in (_BASE, _SCALED, _POINT, _UNIT):
        cache.clear()


def _model(spec: SweepSpec, elements: int, ei1: float | None, ei_factor: float) -> tuple:
    """(key, model) of a case's frame, built from cached assembly and modes."""
    if spec.frame is None and spec.ei2 is not None:  # EI2 fixed: not a scaling of EI1
        base_key, factor = (spec.frame_key, elements, ei1, spec.ei2), ei_factor
    elif spec.frame is None:
        base_key, factor = (spec.frame_key, elements), ei_factor * ei1 / PAPER_EI1
    else:
        base_key, factor = (spec.frame_key, elements), ei_factor
    base = _BASE.get(base_key)
    if base is None:
        if spec.frame is None:
            frame = standard_frame(PAPER_EI1 if spec.ei2 is None else ei1, spec.ei2)
        else:
            frame = spec.frame
        base = _BASE[base_key] = FrameModel.build(frame, elements)
        base.modes(spec.modes)
    if factor == 1.0:
        return base_key + (1.0,), base
    key = base_key + (factor,)
    model = _SCALED.get(key)
    if model is None:
        model = _remember(_SCALED, key, base.scaled(factor), 256)
    return key, model


def _point_vector(key: tuple, model: FrameModel, position: float) -> np.ndarray:
    pkey = key[:-1] + (position,)
    g = _POINT.get(pkey)
    if g is None:
        g = _remember(_POINT, pkey, model.fe.point_vector(position * model.mesh.length), 4096)
    return g


def _case(spec: SweepSpec, p: dict[str, Any]) -> tuple[float, ...]:
    """The result values (in :data:`VARIABLES` order) of one case."""
    speed, mass = p["speed"], p["ball_mass"]
    key, model = _model(spec, p["elements"], p["ei1"], p["ei_factor"])
    length = model.mesh.length
    swing = Swing.from_speed(p["racket_speed"], length, reference=p["reference"], pivot=p["pivot"])
    v_r = float(swing.speed_at(p["position"] * length))
    closing = closing_speed(speed, v_r)
    law = LinearContact.for_speed(closing, kcb=p["kcb"], zeta=p["zeta"])
    kcb, zeta = law.stiffness, law.zeta
    if spec.solver != "exact":
        r = simulate(
            model,
            position=p["position"],
            speed=speed,
            ball_mass=mass,
            kcb=kcb,
            zeta=zeta,
            solver=spec.solver,
            separation=spec.separation,
            basis=spec.basis,
            modes=spec.modes,
            output_step=BDF_OUTPUT_STEP,
            rtol=spec.rtol,
            atol=spec.atol,
            swing=swing,
        )
        return r.cor, r.contact_time, r.ball_speed_out, r.peak_force, kcb, v_r
    ukey = (*key, p["position"], mass, kcb, zeta, spec.separation, spec.modes)
    unit = _UNIT.get(ukey)
    if unit is None:
        fm = model.modes(spec.modes)
        g = _point_vector(key, model, p["position"])
        ccb = law.damping(mass)
        system = modal_system(fm.all_omega, fm.all_shapes, g, mass, kcb, ccb, 1.0)
        o = exact_outcome(system, separation=spec.separation)
        unit = _remember(_UNIT, ukey, (-o.rebound_velocity, o.contact_time, o.peak_force), 65536)
    cor, tc, peak = unit
    return cor, tc, ball_speed_out(cor, speed, v_r), peak * closing, kcb, v_r


def run_chunk(chunk: np.ndarray, *, spec: SweepSpec) -> np.ndarray:
    """Results of the cases ``chunk`` (flat indices), shape (len(chunk), len(VARIABLES)).

    A case whose ball does not separate within the time limit, or whose solver fails, gets NaN
    (the sweep reports how many); any other error stops the sweep.
    """
    out = np.empty((len(chunk), len(VARIABLES)))
    for row, index in enumerate(chunk):
        try:
            out[row] = _case(spec, spec.case(int(index)))
        except (NoSeparationError, RuntimeError, np.linalg.LinAlgError) as exc:
            log.warning("case %d failed (NaN in the results): %s", index, exc)
            out[row] = np.nan
    return out
