"""Offscreen animation: real rendering (EGL), real GIF/MP4 files, read back with imageio."""

import json

import imageio.v2 as imageio
import imageio_ffmpeg
import numpy as np
import pytest

from fem_racket import InputError, render_animation, simulate

SMALL = (320, 160)  # pixels; small images keep the tests fast


@pytest.fixture(scope="module")
def result(standard_model):
    return simulate(standard_model, position=0.769, output_step=5e-5)


def _gif_frames(path):
    return np.stack([np.asarray(f)[..., :3] for f in imageio.mimread(path)])


def test_gif_frames_are_drawn_and_move(result, tmp_path):
    path = render_animation(result, tmp_path / "impact.gif", frames=6, size=SMALL, field="moment")
    frames = _gif_frames(path)
    assert frames.shape == (6, SMALL[1], SMALL[0], 3)
    for f in frames:
        # Not blank: a background plus frame, ball, colour bar and texts in many colours.
        colours = np.unique(f.reshape(-1, 3), axis=0)
        assert len(colours) > 20
        background = np.all(f == f[0, 0], axis=-1).mean()
        assert 0.3 < background < 0.99
    # Each image differs from the next (the ball and frame move, the time label changes).
    for a, b in zip(frames[:-1], frames[1:], strict=True):
        assert np.any(a != b, axis=-1).mean() > 1e-3
    meta = json.loads((tmp_path / "impact.gif.json").read_text())
    assert meta["parameters"]["field"] == "bending moment [N m]"
    assert meta["parameters"]["frames"] == 6
    assert meta["parameters"]["time_s"][-1] == result.contact_time


def test_mp4_has_every_frame(result, tmp_path):
    path = render_animation(result, tmp_path / "impact.mp4", frames=5, fps=10, size=SMALL)
    # ffmpeg decodes the whole stream (its reading generators leak pipes, so not those).
    n_frames, seconds = imageio_ffmpeg.count_frames_and_secs(str(path))
    assert n_frames == 5
    assert seconds == pytest.approx(5 / 10)  # frames / fps
    assert path.stat().st_size > 1000


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"path": "a.avi"}, "must end in"),
        ({"field": "stress"}, "field"),
        ({"frames": 1}, "frames"),
        ({"scale": 0.0}, "scale"),
        ({"fps": -1.0}, "fps"),
        ({"size": (321, 160)}, "size"),
    ],
)
def test_bad_input_writes_nothing(result, tmp_path, kwargs, match):
    path = tmp_path / kwargs.pop("path", "a.gif")
    with pytest.raises(InputError, match=match):
        render_animation(result, path, **kwargs)
    assert list(tmp_path.iterdir()) == []


def test_existing_file_is_kept_without_overwrite(result, tmp_path):
    path = tmp_path / "a.gif"
    path.write_bytes(b"old")
    with pytest.raises(InputError, match="already exists"):
        render_animation(result, path, frames=2, size=SMALL)
    assert path.read_bytes() == b"old"
    render_animation(result, path, frames=2, size=SMALL, overwrite=True)
    assert len(_gif_frames(path)) == 2
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.gif", "a.gif.json"]


def test_bench_script_runs_small(capsys):
    """scripts/bench_vtk.py, a fast variant (its full run is the performance report)."""
    import runpy
    from pathlib import Path

    script = Path(__file__).parents[2] / "scripts" / "bench_vtk.py"
    bench = runpy.run_path(str(script))
    rows = bench["main"](["--steps", "4", "--frames", "2", "--no-mp4", "--compare-hdf"])
    assert [r["task"].split(",")[0] for r in rows] == [
        "export .pvd+.vtu",
        "export .vtkhdf (frame only)",
        "animate gif",
    ]
    assert "velocity [m_s]" in rows[1]["note"]  # the renaming that ruled .vtkhdf out
    assert "wall [s]" in capsys.readouterr().out
