"""A case gives the same bits alone or in any batch, and the engine is deterministic.

The compiled case loop solves each case on its own (its own poles, iteration, grid and
refinement) and, on a frame, each case gets the modes and static totals it would need alone
(:func:`fem_racket.impact.exact.engine._frame_groups`), so sweeps give the same numbers however
they are chunked, ordered or resumed. Exact equality, no tolerance: that is the claim.
"""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket import EngineOptions, FrameModel, impacts, modal_impacts, standard_frame


def _cases(rng, n):
    """Random cases, some heavily damped (their roots come from the eigen fallback) and some
    on soft frames (more modes computed than the stiff ones need)."""
    zeta = rng.uniform(0.0, 0.2, n)
    zeta[::7] = 0.9
    return dict(
        position=rng.uniform(0.3, 1.0, n),
        speed=rng.uniform(10.0, 50.0, n),
        zeta=zeta,
        ball_mass=rng.uniform(0.05, 0.065, n),
        ei_factor=np.exp(rng.uniform(-3.0, 2.0, n)),
    )


def _same(a, b, rows):
    for name in ("cor", "contact_time", "peak_force", "modes"):
        x, y = getattr(a, name), getattr(b, name)[rows]
        assert np.array_equal(x, y, equal_nan=True), name


@pytest.mark.parametrize(("separation", "tolerance"), [("displacement", 1e-6), ("force", 1e-4)])
def test_a_case_alone_or_in_any_batch_on_a_frame(separation, tolerance):
    rng = np.random.default_rng(27)
    n = 60
    kw = _cases(rng, n)
    model = FrameModel.build(standard_frame(), 20)
    options = EngineOptions(separation, tolerance, peak_force=True)
    full = impacts(model, options=options, **kw)
    assert np.all(np.isfinite(full.cor)) and len(np.unique(full.modes)) > 3
    again = impacts(model, options=options, **kw)
    _same(again, full, slice(None))  # deterministic
    perm = rng.permutation(n)
    _same(impacts(model, options=options, **{k: v[perm] for k, v in kw.items()}), full, perm)
    for i in rng.choice(n, 8, replace=False):
        alone = impacts(model, options=options, **{k: v[i : i + 1] for k, v in kw.items()})
        _same(alone, full, slice(i, i + 1))
    half = np.arange(0, n, 2)
    _same(impacts(model, options=options, **{k: v[half] for k, v in kw.items()}), full, half)


def test_a_case_alone_or_in_any_batch_of_structures(standard_model):
    rng = np.random.default_rng(28)
    n = 40
    fm = standard_model.modes(None)
    x = rng.uniform(0.3, 1.0, n) * standard_model.mesh.length
    g = standard_model.fe.field_matrix(x, 0)
    values = g @ fm.shapes
    rigid = ((g @ fm.rigid) ** 2).sum(axis=1)
    omega = fm.omega[None, :] * np.sqrt(np.exp(rng.uniform(-3.0, 2.0, n)))[:, None]
    kw = dict(speed=rng.uniform(10.0, 50.0, n), zeta=_cases(rng, n)["zeta"])
    options = EngineOptions(peak_force=True)
    full = modal_impacts(omega, values, rigid, options=options, **kw)
    for i in rng.choice(n, 8, replace=False):
        one = {k: v[i : i + 1] for k, v in kw.items()}
        alone = modal_impacts(omega[i : i + 1], values[i : i + 1], rigid[i : i + 1],
                              options=options, **one)  # fmt: skip
        _same(alone, full, slice(i, i + 1))
