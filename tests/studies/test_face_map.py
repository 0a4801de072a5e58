"""The power map of the string face (fem_racket.studies.face_map) and ``map --offsets``."""

import json

import numpy as np
import pytest
import xarray as xr

from fem_racket.frame.head import DEFAULT_HEAD
from fem_racket.impact.exact.engine import impacts
from fem_racket.studies.face_map import face_map, power_area
from fem_racket.validation import InputError
from tests.clirun import run

X = np.linspace(0.5, 1.0, 26)
Y = np.linspace(-0.12, 0.12, 13)


@pytest.fixture(scope="module")
def face(standard_model):
    return face_map(standard_model, positions=X, offsets=Y, speed=25.0)


def test_face_map_is_the_engine_on_the_head_and_blank_off_it(standard_model, face):
    xx, yy = np.meshgrid(X, Y)
    on = DEFAULT_HEAD.contains(xx * 0.68, yy)
    assert np.all(np.isfinite(face.apparent_cor[on])) and np.all(np.isnan(face.apparent_cor[~on]))
    j, i = 4, 15
    ref = impacts(standard_model, position=X[i], offset=Y[j], speed=25.0).cor
    assert face.apparent_cor[j, i] == pytest.approx(float(ref), abs=1e-12)  # same cases
    np.testing.assert_allclose(face.apparent_cor, face.apparent_cor[::-1], rtol=0, atol=1e-12)
    assert face.max_apparent_cor[1] == 0.0  # the best point is on the axis


def test_power_area_of_a_known_region():
    # e = 1 - r^2 on a disc: e >= f where r <= sqrt(1 - f); area pi (1 - f) (grid error O(h))
    x = np.linspace(-1.0, 1.0, 401)
    xx, yy = np.meshgrid(x, x)
    e = 1.0 - (xx**2 + yy**2)
    e[e < 0.0] = np.nan
    area = power_area(x, x, e, 0.75) / 1e4
    assert area == pytest.approx(np.pi * 0.25, rel=2e-2)


def test_swing_raises_v_out_and_keeps_e_a_symmetric(standard_model):
    m = face_map(standard_model, positions=X, offsets=Y, speed=20.0, racket_speed=20.0, pivot=0.1)
    ok = np.isfinite(m.apparent_cor)
    assert np.all(m.ball_speed_out[ok] > 20.0 * m.apparent_cor[ok])
    assert np.isfinite(m.cop)


def test_cli_face_map(capsys, tmp_path):
    out = [tmp_path / "f.png", tmp_path / "f.nc", tmp_path / "f.csv"]
    code, text, _ = run(capsys, "map", "--offsets", "-0.1:0.1:9", "--positions", "0.5:1:21",
                        "--out", *out)  # fmt: skip
    assert code == 0 and "power area" in text and "cm^2" in text
    ds = xr.open_dataset(out[1])
    assert ds.apparent_cor.dims == ("racket", "offset", "position")
    assert ds.apparent_cor.shape == (1, 9, 21)
    ds.close()
    code, text, _ = run(capsys, "map", "--offsets", "-0.1:0.1:9", "--positions", "0.5:1:21",
                        "--json", "--out", tmp_path / "g.nc")  # fmt: skip
    assert json.loads(text)["power_area_cm2"] > 0.0
    code, _, err = run(capsys, "map", "--offsets", "0,0.1", "--law", "hunt-crossley",
                       "--out", tmp_path / "h.nc")  # fmt: skip
    assert code == 2 and "not allowed with --offsets" in err


def test_refusals(standard_model):
    with pytest.raises(InputError, match="offsets = 1 values"):
        face_map(standard_model, positions=X, offsets=[0.0])
    with pytest.raises(InputError, match="unknown face-map options"):
        face_map(standard_model, positions=X, offsets=Y, options={"law": "x"})


def test_sweep_with_an_offset_axis(capsys, tmp_path):
    # the sweep's engine and general-integrator paths take the offset as an axis
    for law in ([], ["--law", "hunt-crossley"]):
        out = tmp_path / f"s{len(law)}.nc"
        code, _, _ = run(capsys, "sweep", "--offset", "-0.05:0.05:3", "--position", "0.6,0.74",
                         "--out", out, *law)  # fmt: skip
        assert code == 0
        ds = xr.open_dataset(out)
        cor = ds.cor.transpose("position", "offset").values
        ds.close()
        np.testing.assert_allclose(cor[:, 0], cor[:, 2], rtol=0, atol=1e-12)  # mirror
        assert np.all(cor[:, 1] > cor[:, 0])  # off axis the racket rolls: less rebound
    code, _, err = run(capsys, "sweep", "--offset", "0.2", "--out", tmp_path / "x.nc")
    assert code == 2 and "offset = 0.2 m is not allowed" in err


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"options": {"elements": 10}}, "elements = 10 is not allowed with a FrameModel"),
        ({"reference": 0.6}, "reference = 0.6 x/L is not allowed without a swing"),
        ({"offsets": np.linspace(-0.1, 0.1, 20_000)}, "offsets = 20000 values with positions"),
    ],
)
def test_face_map_refuses_what_it_would_drop(standard_model, kwargs, message):
    with pytest.raises(InputError, match=message):
        face_map(standard_model, **{"positions": X, "offsets": Y, **kwargs})


def test_spin_map_refuses_modes_and_separation_under_a_law(standard_model):
    from fem_racket.contact.presets import get_law
    from fem_racket.impact.incidence import Incidence
    from fem_racket.studies.spin_map import spin_map

    law = get_law("hunt-crossley")
    for options, message in (
        ({"modes": 10}, "modes = 10 is not allowed with solver 'general'"),
        ({"separation": "force"}, "separation = 'force' is not allowed with contact law"),
    ):
        with pytest.raises(InputError, match=message):
            spin_map(
                standard_model, positions=X, offsets=Y, incidence=Incidence(angle=30.0),
                options={"law": law, **options},
            )  # fmt: skip
