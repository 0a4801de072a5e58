"""Notebook forms of the results: short repr, HTML tables, xarray datasets."""

import numpy as np
import pytest

import fem_racket as fr


@pytest.fixture(scope="module")
def result(standard_model):
    return fr.simulate(standard_model, position=0.75, speed=20.0)


def test_every_result_type_has_a_short_repr(standard_model, result):
    study = fr.refinement_study(elements=[5, 10])
    objects = [
        result,
        standard_model,
        standard_model.fe,
        standard_model.mesh,
        standard_model.modes(),
        standard_model.props,
        fr.coupled_modes(standard_model, 0.75),
        fr.impact_series(result, frames=5),
        study,
    ]
    for obj in objects:
        text = repr(obj)
        assert len(text) < 300 and "\n" not in text and "array(" not in text, text
        assert text.startswith(type(obj).__name__ + "(")
    text = repr(result)
    for part in (f"cor={result.cor:.5f}", "contact_time=4.0401 ms", "'exact'", "40 modes"):
        assert part in text, part


def test_html_tables_hold_the_summary(result):
    html = fr.refinement_study(elements=[5, 10])._repr_html_()
    assert html.startswith("<table>") and html.count("<tr>") == 3  # header + 2 meshes
    html = result._repr_html_()
    assert "coefficient of restitution" in html and "0.37657" in html and "K_CB" in html


def test_impact_histories_as_a_dataset(result):
    ds = result.to_xarray()
    np.testing.assert_array_equal(ds.time.values, result.t)
    np.testing.assert_array_equal(ds.contact_force.values, result.force)
    assert ds.contact_force.attrs["units"] == "N" and ds.time.attrs["units"] == "s"
    assert ds.frame_deflection.shape == (result.t.size, result.model.mesh.points.size)
    assert ds.attrs["cor"] == result.cor and ds.attrs["modes"] == 40


def test_refinement_study_as_a_dataset():
    study = fr.refinement_study(elements=[5, 10, 20], positions=[0.6, 0.75])
    ds = study.to_xarray()
    assert dict(ds.sizes) == {"elements": 3, "mode": 4, "position": 2}
    np.testing.assert_array_equal(ds.cor.values, study.cor)
    np.testing.assert_array_equal(ds.modes_used.values, [10, 20, 40])  # 2 per element, <= 80
    assert ds.contact_time.attrs["units"] == "s" and ds.attrs["zeta"] == pytest.approx(
        0.0592, abs=5e-5
    )
