"""Results that show themselves: one-line reprs and HTML tables with units, never the arrays;
``dir(fem_racket)`` is the public API."""

import numpy as np

import fem_racket as fr
from fem_racket.studies.calibrate import calibrate
from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.result import DesignResult
from fem_racket.studies.design.sensitivity import SobolIndices


def test_dir_of_the_package_is_its_public_names():
    def dunder(n):
        return n.startswith("__") and n.endswith("__")

    assert {n for n in dir(fr) if not dunder(n)} == {n for n in fr.__all__ if not dunder(n)}
    assert set(fr.__all__) <= set(dir(fr))  # no importlib, Any, annotations besides


def test_a_map_and_its_sweet_spots_in_one_line_each():
    m = fr.racket_map(speed=20, racket_speed=25, pivot=0.1, positions=np.linspace(0.5, 1, 41))
    text = repr(m)
    assert "\n" not in text and len(text) < 250 and "array" not in text
    assert text.startswith("RacketMap(name='racket', points=41 over 0.5-1 x/L, speed=20 m/s")
    assert "node=0.7697 x/L" in text  # the paper's mode-1 node, 0.769 L
    spots = repr(m.spots)
    assert spots.startswith("SweetSpots(cop=0.73") and spots.endswith(" x/L)")
    html = m._repr_html_()
    assert "<table>" in html and "m/s" in html and "x/L" in html and "centre of percussion" in html


def test_design_sobol_and_calibration_results_in_one_line_each():
    p = design_problem()
    r = DesignResult(
        problem=p, method="SLSQP", x=np.array(p.x_start) * 1.1, x_start=np.array(p.x_start),
        outputs={"cor": 0.39037}, start_outputs={"cor": 0.29735}, success=True, message="ok",
        iterations=19, evaluator=None,
    )  # fmt: skip
    assert repr(r) == (
        f"DesignResult(method='SLSQP', cor=0.29735 -> 0.39037, variables={len(p.x_start)}, "
        "success=True, iterations=19)"
    )
    assert "[N m^2]" in r._repr_html_() or "N m^2" in r._repr_html_()
    s = SobolIndices(
        "cor", ["ei_1", "rhoa_4"], np.array([0.1, 0.7]), np.array([0.01, 0.07]),
        np.array([0.1, 0.73]), np.array([0.01, 0.06]), 1024, 0.42, 0.1,
    )  # fmt: skip
    assert repr(s) == (
        "SobolIndices(output='cor', designs=1024, mean=0.42, largest_ST=rhoa_4 0.73)"
    )
    assert "ST [-]" in s._repr_html_()
    c = calibrate("linear", "kawazoe-1997")
    assert repr(c).startswith("Calibration(family='linear', targets='kawazoe-1997', ")
    assert "meets_targets=False" in repr(c)  # one K_CB cannot meet three contact times
    assert c._repr_html_().count("<tr>") == len(c.table()) + 1
