"""Plotting helpers draw on an Axes and return it, with units and readable labels."""

import pytest

import fem_racket as fr
from fem_racket.io.plotting import coordinate_labels, force_note


@pytest.fixture(scope="module")
def plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    yield plt
    plt.close("all")


@pytest.fixture(scope="module")
def result():
    return fr.simulate(position=0.75, speed=20.0)


def test_coordinate_labels_are_short_and_distinct():
    assert coordinate_labels([0.55, 0.6166666666666667, 0.6833333333333333]) == [
        "0.55",
        "0.617",
        "0.683",
    ]
    assert coordinate_labels([1.0001, 1.0002]) == ["1.0001", "1.0002"]  # more digits if needed


def test_plot_impact_force_says_why_it_is_not_zero_at_the_ends(plt, result):
    ax = fr.plot_impact(result, "force")
    assert ax.get_xlabel() == "time [ms]" and ax.get_ylabel() == "contact force [N]"
    # F(0) = C_CB V_B0 (the dashpot) and F(t_c) = C_CB delta'(t_c) < 0 (delta back to zero)
    f0 = result.damping * result.impact.speed
    assert result.force[0] == pytest.approx(f0, rel=1e-9) and result.force[-1] < 0
    note = force_note(result)
    assert f"{f0:.0f} N" in note and "dashpot pulls" in note and "separation='force'" in note
    assert any(note == t.get_text() for t in ax.texts)
    _, mine = plt.subplots()
    assert fr.plot_impact(result, "velocity", ax=mine) is mine


def test_plot_sweep_labels_lines_with_rounded_coordinates(plt):
    ds = fr.sweep(position="0.55:0.95:4", speed=[20, 30], ei1="50:3000:3:log", backend="serial")
    ax = fr.plot_sweep(ds.cor, "ei1", hue="position", speed=30)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert labels == ["0.55", "0.683", "0.817", "0.95"]
    assert ax.get_xscale() == "log" and ax.get_xlabel() == "grip-side EI1 [N m^2]"
    assert ax.get_ylabel() == "apparent COR e_A [-]"  # not the terse "cor [1]"
    assert ax.get_legend().get_title().get_text() == "impact point [x/L]"
    assert ax.get_title() == "ball speed v_in = 30 m/s"


def test_plot_refinement_returns_the_axes(plt):
    study = fr.refinement_study(elements=[5, 10, 20])
    ax = fr.plot_refinement(study, "frequency")
    assert ax.get_xscale() == "log" and "[-]" in ax.get_ylabel()
    assert len(ax.get_lines()) == 5  # four modes and the slope -4 guide
