"""The power map's figure: several rackets without overlapping labels, the title naming a racket
only when there is one (issue 23, item 8)."""

from pathlib import Path

import numpy as np
import pytest

from fem_racket.io.map_files import map_figure
from fem_racket.io.mesh_files import read_mesh
from fem_racket.studies.racket_map import racket_map

MESHES = Path(__file__).resolve().parents[2] / "meshes"
SWING = {"speed": 20.0, "racket_speed": 25.0, "pivot": 0.1, "positions": np.linspace(0.5, 1.0, 41)}


@pytest.fixture(scope="module")
def maps():
    names = ("fit_light_racket", "fit_modern_racket", "fit_heavy_racket")
    return [racket_map(read_mesh(MESHES / f"{n}.vtu"), name=n, **SWING) for n in names]


def _texts(fig):
    return [t.get_text() for ax in fig.axes for t in ax.get_legend().get_texts()]


def test_three_rackets_name_their_spots_in_the_legends_not_on_the_curves(maps):
    fig = map_figure(maps)
    ax1, ax2 = fig.axes
    assert not ax1.texts and not ax2.texts  # no annotation that could overlap another
    texts = _texts(fig)
    for m in maps:
        s = m.spots
        assert f"{m.name}: max e_A at {s.max_apparent_cor:.3f}" in texts
        assert (
            f"{m.name}: COP {s.cop:.3f}, mode-1 node {s.node:.3f}, "
            f"max v_out at {s.max_ball_speed:.3f}"
        ) in texts
    title = ax1.get_title()
    assert "(standard)" not in title and not any(m.name in title for m in maps)
    omegas = sorted(m.swing.omega for m in maps)  # rackets of different lengths: a range
    assert omegas[0] < omegas[-1]
    assert f"rackets turning at {omegas[0]:.1f}-{omegas[-1]:.1f} rad/s" in title
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    FigureCanvasAgg(fig).draw()  # the legend below the axes stays inside the figure
    box = ax2.get_legend().get_window_extent()
    assert box.y0 >= 0 and box.x0 >= 0 and box.x1 <= fig.bbox.x1


def test_one_racket_is_named_in_the_title(maps):
    title = map_figure(maps[:1]).axes[0].get_title()
    assert f"racket turning at {maps[0].swing.omega:.1f} rad/s" in title
    assert "(fit_light_racket)" in title


def test_with_pyplot_the_figure_is_pyplots(maps):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = map_figure(maps[:1], pyplot=True)
    assert plt.gcf() is fig and fig.axes[0].get_title() == map_figure(maps[:1]).axes[0].get_title()
    plt.close(fig)
