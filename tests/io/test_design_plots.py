"""The Pareto figure's zoomed panel (issue 23, item 8: the quick study's single-design front
had garbled offset ticks, "1e-11+0.229")."""

import numpy as np

from fem_racket.io.design_plots import ZOOM_BELOW, zoom_limits

CLOUD = np.array([[28.0, 0.10], [36.0, 0.27]])  # every design: 8 m/s by 0.17 m


def test_a_front_of_one_design_is_not_zoomed():
    assert zoom_limits(np.array([[35.3, 0.229]]), CLOUD) is None
    assert zoom_limits(np.array([[35.3, 0.229], [35.3, 0.229]]), CLOUD) is None


def test_a_wide_front_is_not_zoomed():
    wide = np.array([[30.0, 0.25], [30.0 + ZOOM_BELOW * 8.0, 0.24]])  # a quarter of the cloud
    assert zoom_limits(wide, CLOUD) is None


def test_a_small_front_gets_margins_in_its_units():
    front = np.array([[35.5, 0.266], [36.1, 0.243]])
    np.testing.assert_allclose(
        zoom_limits(front, CLOUD), [[35.5 - 0.09, 36.1 + 0.09], [0.243 - 0.00345, 0.266 + 0.00345]]
    )
    # one objective constant along the front: 2 % of the cloud's range, not 1e-9 of the value
    flat = np.array([[35.5, 0.25], [36.1, 0.25]])
    np.testing.assert_allclose(zoom_limits(flat, CLOUD)[1], [0.25 - 0.0034, 0.25 + 0.0034])
