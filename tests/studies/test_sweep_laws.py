"""Sweeps under a contact law: law parameters as dimensions, and a swinging racket."""

from __future__ import annotations

import numpy as np
import pytest
from script_loader import load_script

from fem_racket.contact.presets import PRESETS, get_law
from fem_racket.frame.model import FrameModel
from fem_racket.impact.law_impact import LawOptions, solve_law_impact
from fem_racket.impact.simulate import simulate
from fem_racket.impact.swing import Swing, ball_speed_out
from fem_racket.studies.sweep import sweep
from fem_racket.validation import InputError

#: The calibrated hysteretic law (k1, k2 [N/m^n], n).
KAWAZOE = PRESETS["kawazoe-1997-nonlinear"]
#: The general integrator's COR error at its default tolerance 1e-6: <= 1.2e-6 against CVODE on
#: the paper's racket (fem_racket.impact.general.integrator.settings, scripts/bench_laws.py). A
#: batch
#: shares the step of its shortest contact within a group, so a case in a sweep and the same
#: case alone differ by up to about twice that.
GENERAL_COR = 2e-6


@pytest.fixture(scope="module")
def model10() -> FrameModel:
    return FrameModel.build(None, 10)


def test_a_law_parameter_sweep_is_simulate_at_each_value():
    k2 = [6e16, KAWAZOE.k2, 1.2e17]
    ds = sweep(
        law="hysteretic", k2=k2, position=[0.6, 0.8], speed=30.0, backend="serial", peak_force=True
    )
    assert ds.cor.dims == ("position", "k2")
    assert ds.k2.attrs == {
        "long_name": "unloading k2",
        "units": "N/m^n",
        "description": "hysteretic unloading stiffness k2",
    }
    assert ds.attrs["contact_law"] == "hysteretic" and ds.attrs["solver"] == "general"
    # the fixed parameters (the family's defaults here) are attributes, the swept one is not
    assert ds.attrs["contact_k1_n_m_n"] == KAWAZOE.k1
    assert ds.attrs["contact_hyst_exponent"] == KAWAZOE.exponent
    assert "contact_k2_n_m_n" not in ds.attrs
    for p in (0.6, 0.8):
        for v in k2:
            r = simulate(position=p, speed=30.0, law=get_law("hysteretic", k2=v), output_step=None)
            case = ds.sel(position=p, k2=v)
            assert float(case.cor) == pytest.approx(r.cor, abs=GENERAL_COR)
            assert float(case.rebound_speed_m_s) == pytest.approx(-r.rebound_velocity, abs=1e-4)
            # contact time converges more slowly than the COR (DESIGN section 9)
            assert float(case.contact_time_s) == pytest.approx(r.contact_time, rel=1e-4)
            # the peak force is the largest sample on the step the batch shares: the n = 8.9
            # law's sharp peak moves it by ~1e-3
            assert float(case.peak_force_n) == pytest.approx(r.peak_force, rel=3e-3)
    # a stiffer unloading branch returns less energy: e^2 = k1/k2 for linear branches (Cross 2000)
    assert np.all(np.diff(ds.cor.values, axis=1) < 0.0)


def test_two_law_dimensions_and_a_string_grid():
    ds = sweep(
        law="hunt-crossley",
        hc_exponent="1.5:2:2",
        hc_alpha=[0.0, 0.05],
        hc_stiffness=1e7,
        speed=20.0,
        backend="serial",
    )
    assert ds.cor.dims == ("hc_exponent", "hc_alpha")
    assert ds.hc_exponent.values.tolist() == [1.5, 2.0]
    assert ds.attrs["contact_hc_stiffness_n_m_n"] == 1e7
    r = simulate(law=get_law("hunt-crossley", hc_stiffness=1e7, hc_exponent=2.0, hc_alpha=0.05))
    case = ds.cor.sel(hc_exponent=2.0, hc_alpha=0.05)
    assert float(case) == pytest.approx(r.cor, abs=GENERAL_COR)
    # no damping: Hunt-Crossley is elastic, less energy is lost than with alpha > 0
    assert np.all(ds.cor.sel(hc_alpha=0.0) > ds.cor.sel(hc_alpha=0.05))


def test_a_law_object_takes_overrides_and_the_linear_law_is_unchanged():
    ds = sweep(law=KAWAZOE, k1=[3e15, 3.182e15], position=0.8, speed=30.0, backend="serial")
    ref = sweep(law="kawazoe-1997-nonlinear", position=0.8, speed=30.0, backend="serial")
    # the preset's own k1: the same cases, batched with another k1 (one step for the batch)
    assert float(ds.cor.sel(k1=3.182e15)) == pytest.approx(float(ref.cor), abs=GENERAL_COR)
    lin = sweep(position=[0.6, 0.8], speed=[20.0, 30.0], backend="serial")
    named = sweep(position=[0.6, 0.8], speed=[20.0, 30.0], law="linear", backend="serial")
    np.testing.assert_array_equal(lin.cor.values, named.cor.values)
    assert lin.attrs["contact_law"] == "linear" and lin.attrs["solver"] == "exact"


def test_law_sweeps_give_the_same_numbers_on_every_backend():
    # fixed chunks under a law (studies/sweep.py LAW_CHUNK), each case computed on its own
    kw = dict(law=KAWAZOE, k2=np.geomspace(5e16, 1.5e17, 14), position="0.5:0.9:5", speed=25.0)
    serial = sweep(**kw, backend="serial")
    pool = sweep(**kw, backend="processes", workers=2)
    np.testing.assert_array_equal(serial.cor.values, pool.cor.values)
    assert np.all(np.isfinite(serial.cor.values))


def test_a_law_sweep_over_frames_on_a_pool_equals_serial():
    # several chunks, so a pool runs: the caller solves two cases first (the forked workers
    # inherit the compiled kernels) and drops them; each case is computed on its own
    kw = dict(law=KAWAZOE, position=[0.6, 0.8], speed=[20.0, 40.0], ei1="50:3000:6:log")
    serial = sweep(**kw, backend="serial", progress=False)
    pool = sweep(**kw, backend="processes", workers=2, chunk_size=5, progress=False)
    np.testing.assert_array_equal(serial.cor.values, pool.cor.values)
    np.testing.assert_array_equal(serial.contact_time_s.values, pool.contact_time_s.values)
    assert np.all(np.isfinite(serial.cor.values))


def test_the_warm_up_before_a_pool_says_nothing(monkeypatch, caplog):
    import logging
    import warnings

    from fem_racket.studies import sweep as module

    def noisy(chunk, *, spec):
        logging.getLogger("fem_racket.studies.cases").warning("%d cases failed", len(chunk))
        warnings.warn("noisy", RuntimeWarning, stacklevel=1)

    monkeypatch.setattr(module, "run_chunk", noisy)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        module._warm_up(None, np.arange(2))
        noisy(np.arange(2), spec=None)  # the same outside the warm-up is heard
    assert [r.getMessage() for r in caplog.records] == ["2 cases failed"]
    assert [str(w.message) for w in seen] == ["noisy"]
    assert not logging.root.manager.disable  # logging as it was


def test_a_resumed_law_sweep_equals_an_uninterrupted_one(tmp_path):
    from fem_racket.studies.cases import COLUMNS
    from fem_racket.studies.checkpoint import Checkpoint
    from fem_racket.studies.grid import SweepSpec
    from fem_racket.studies.sweep import sweep_result

    kw = dict(k2=np.geomspace(5e16, 1.5e17, 14), position="0.5:0.9:5", speed=25.0)
    run = sweep_result(law=KAWAZOE, **kw, backend="serial", peak_force=True)
    clean = run.to_xarray()
    # a run killed after its first 64 cases were saved
    out = tmp_path / "s.nc"
    spec = SweepSpec.build(None, law=KAWAZOE, peak_force=True, **kw)
    ckpt = Checkpoint(out, spec.digest, spec.describe(), spec.size, len(COLUMNS))
    ckpt.save(np.arange(64), run.values[:64])
    ckpt.close()
    resumed = sweep(law=KAWAZOE, **kw, backend="serial", peak_force=True, output=out)
    np.testing.assert_array_equal(resumed.cor.values, clean.cor.values)
    np.testing.assert_array_equal(resumed.peak_force_n.values, clean.peak_force_n.values)
    assert list(resumed.data_vars) == list(clean.data_vars) and "kcb_n_m" not in resumed


def test_a_law_without_k_cb_writes_no_k_cb(tmp_path):
    """A law other than the paper's has no K_CB: its sweep held an all-NaN ``kcb_n_m``
    ("stiffness K_CB") in the dataset, the .nc and the .csv; the paper's law keeps it."""
    import xarray as xr

    kw = dict(position=[0.5, 0.8, 0.95], speed=30.0, backend="serial")
    for law, has in (("hunt-crossley", False), ("linear", True), (None, True)):
        nc, csv = tmp_path / f"{law}.nc", tmp_path / f"{law}.csv"
        ds = sweep(law=law, **kw, output=nc)
        sweep(law=law, **kw, output=csv)
        with xr.open_dataset(nc) as back:
            assert ("kcb_n_m" in back) is has and ("kcb_n_m" in ds) is has, law
        assert ("kcb_n_m" in csv.read_text().splitlines()[0]) is has, law
        assert all(np.isfinite(ds[v]).all() for v in ds.data_vars), law


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"law": "linear", "k1": 1e15}, "law parameters ['k1'] are not allowed with law 'linear'"),
        ({"law": "kawazoe-1997-nonlinear", "k1": 1e15}, "it is a preset"),
        ({"law": "hysteretic", "hc_alpha": 0.1}, "hc_alpha is not allowed with law 'hysteretic'"),
        ({"law": "hunt-crossley", "hc_exponent": "0.5:2:3"}, "hc_exponent = 0.5"),
        ({"law": "hunt-crossley", "hc_exponent": [1.5, 1.5]}, "distinct"),
        ({"law": "series", "string_cubic": -1.0}, "string_cubic = -1"),
        ({"law": "series", "stiffness": 1.0}, "stiffness is not a sweep parameter"),
    ],
)
def test_bad_law_parameters(kwargs, message):
    with pytest.raises(InputError, match=message.replace("[", r"\[").replace("]", r"\]")) as e:
        sweep(backend="serial", **kwargs)
    assert "\n" not in str(e.value)


def test_a_swinging_racket_under_a_law_matches_cvode_from_the_swing(model10):
    """v_out = e_A(v_c) v_in + (1 + e_A) v_r for any law (studies/law_cases.py): the sweep
    (stationary racket at the closing speed, general integrator) against CVODE started from the
    swing's velocity field, and the identity itself between two CVODE runs."""
    positions, speeds = [0.6, 0.85], [-5.0, 25.0]
    ds = sweep(
        law=KAWAZOE,
        position=positions,
        racket_speed=speeds,
        pivot=0.08,
        speed=20.0,
        elements=10,
        backend="serial",
    )
    length = model10.mesh.length
    for p in positions:
        for v in speeds:
            swing = Swing.from_speed(v, length, pivot=0.08)
            v_r = float(swing.speed_at(p * length))
            lab = solve_law_impact(
                KAWAZOE,
                model10,
                p,
                0.057,
                20.0,
                frame_velocity=swing.cg_motion(model10.props.cg),
                options=LawOptions("cvode", output_step=None),
            )
            v_out = -float(lab.ball_velocity[-1])
            case = ds.sel(position=p, racket_speed=v)
            assert float(case.racket_speed_at_impact_m_s) == pytest.approx(v_r, rel=1e-12)
            e_a = (v_out - v_r) / (20.0 + v_r)
            assert float(case.cor) == pytest.approx(e_a, abs=GENERAL_COR)
            assert float(case.rebound_speed_m_s) == pytest.approx(v_out, abs=GENERAL_COR * 40)
            assert float(case.contact_time_s) == pytest.approx(lab.t[-1], rel=1e-5)
            # the identity, CVODE both ways (its tolerances 1e-10/1e-12: agreement to ~1e-9)
            still = solve_law_impact(
                KAWAZOE,
                model10,
                p,
                0.057,
                20.0 + v_r,
                options=LawOptions("cvode", output_step=None),
            )
            e_still = -float(still.ball_velocity[-1]) / (20.0 + v_r)
            assert ball_speed_out(e_still, 20.0, v_r) == pytest.approx(v_out, abs=1e-8)
            assert still.t[-1] == pytest.approx(lab.t[-1], rel=1e-7)


def test_a_swing_under_a_law_with_cvode_cases_agrees_with_the_batch():
    kwargs = dict(law=KAWAZOE, position=0.7, racket_speed=20.0, pivot=0.1, elements=10)
    batch = sweep(**kwargs, backend="serial")
    one = sweep(**kwargs, solver="cvode", backend="serial")
    assert float(one.cor) == pytest.approx(float(batch.cor), abs=GENERAL_COR)
    assert float(one.rebound_speed_m_s) == pytest.approx(float(batch.rebound_speed_m_s), abs=1e-4)
    assert float(one.racket_speed_at_impact_m_s) == float(batch.racket_speed_at_impact_m_s)


def test_bench_law_studies_script_runs(capsys):
    rows = load_script("bench_law_studies").main(["--quick"])
    assert all(r["wall_s"] > 0 for r in rows if "wall_s" in r)
    # batched sweep and one simulate per case: the same impacts within the integrator's error
    assert rows[-1]["value"] <= GENERAL_COR
    assert "per impact" in capsys.readouterr().out
