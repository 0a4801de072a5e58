"""One labelling rule for every dataset variable (fem_racket.outputs.labels): short long_name,
separate units, dimensionless as "-", so xarray's own plots and plot_sweep read on one line."""

import numpy as np
import pytest

from fem_racket.contact.registry import LAW_PARAMETERS
from fem_racket.io.map_files import CURVES
from fem_racket.outputs.labels import LABELS, MAX_LABEL, label
from fem_racket.studies.cases import VARIABLES
from fem_racket.studies.grid_values import PARAMETERS


def _units(unit: str) -> str:
    return "-" if unit in ("1", "-", "") else unit


@pytest.mark.parametrize("name", sorted(LABELS))
def test_every_label_is_short_and_says_its_unit(name):
    lab = LABELS[name]
    assert len(lab.text) <= MAX_LABEL, lab.text  # xarray wraps labels over 30 characters
    assert lab.units and lab.units != "1"  # the house's "[-]", not CF's "1"
    assert lab.long_name == lab.long_name.strip() and "[" not in lab.long_name


def test_every_sweep_and_map_variable_has_its_label_with_the_declared_unit():
    declared = {name: p.unit for name, p in PARAMETERS.items()}
    declared |= {name: p.unit for name, (_, p) in LAW_PARAMETERS.items()}
    declared |= {name: unit for name, (unit, _) in VARIABLES.items()}
    for name, unit in declared.items():
        assert name in LABELS, f"{name}: add its line to fem_racket.outputs.labels.LABELS"
        assert LABELS[name].units == _units(unit), name
    assert set(CURVES.values()) <= set(LABELS)


def test_a_name_without_a_line_is_labelled_by_itself():
    assert label("k9", "1", "a later law's k9").attrs() == {
        "long_name": "k9",
        "units": "-",
        "description": "a later law's k9",
    }
    assert label("cor").text == "apparent COR e_A [-]"


def test_xarray_plots_a_sweep_file_with_the_short_labels(tmp_path):
    import xarray as xr
    from xarray.plot.utils import label_from_attrs

    import fem_racket as fr

    out = tmp_path / "s.nc"
    fr.sweep(position=[0.6, 0.75], speed=30.0, ei1=[100.0, 200.0], output=out, progress=False)
    with xr.open_dataset(out) as ds:
        assert label_from_attrs(ds.cor) == "apparent COR e_A [-]"
        assert label_from_attrs(ds.ei1) == "grip-side EI1 [N m^2]"
        assert label_from_attrs(ds.contact_time_s) == "contact time t_c [s]"
        assert "(v_out - v_r)/(v_in + v_r)" in ds.cor.attrs["description"]


def test_an_oblique_sweeps_two_speeds_out_are_told_apart(tmp_path):
    """rebound_speed_m_s is the normal component of the outgoing velocity, ball_speed_out_m_s
    its whole speed: both were labelled "v_out" (their long_names distinct, and true, now)."""
    import xarray as xr

    import fem_racket as fr

    out = tmp_path / "o.nc"
    fr.sweep(angle=[20.0, 40.0], speed=30.0, position=0.7, output=out, progress=False)
    with xr.open_dataset(out) as ds:
        normal, whole = ds.rebound_speed_m_s, ds.ball_speed_out_m_s
        assert normal.attrs["long_name"] == "normal rebound v_out,n"
        assert whole.attrs["long_name"] == "ball speed out v_out"
        assert "face normal" in normal.attrs["description"]
        assert "normal and tangential" in whole.attrs["description"]
        assert np.all(
            normal.values < whole.values
        )  # its normal component (the ball leaves along the face too)
