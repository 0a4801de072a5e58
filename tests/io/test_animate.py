"""Offscreen animation: real rendering (EGL), real GIF/MP4 files, read back with imageio."""

import json

import imageio.v2 as imageio
import imageio_ffmpeg
import numpy as np
import pytest

from fem_racket import InputError, render_animation, simulate
from fem_racket.io.animate import AnimationOptions

SMALL = (320, 160)  # pixels; small images keep the tests fast


@pytest.fixture(scope="module")
def result(standard_model):
    return simulate(standard_model, position=0.769, output_step=5e-5)


def _gif_frames(path):
    return np.stack([np.asarray(f)[..., :3] for f in imageio.mimread(path)])


def test_gif_frames_are_drawn_and_move(result, tmp_path):
    path = render_animation(
        result, tmp_path / "impact.gif", AnimationOptions(frames=6, size=SMALL, field="moment")
    )
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
    path = render_animation(
        result, tmp_path / "impact.mp4", AnimationOptions(frames=5, fps=10, size=SMALL)
    )
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
        render_animation(result, path, AnimationOptions(**kwargs))
    assert list(tmp_path.iterdir()) == []


def test_existing_file_is_kept_without_overwrite(result, tmp_path):
    path = tmp_path / "a.gif"
    path.write_bytes(b"old")
    with pytest.raises(InputError, match="already exists"):
        render_animation(result, path, AnimationOptions(frames=2, size=SMALL))
    assert path.read_bytes() == b"old"
    render_animation(result, path, AnimationOptions(frames=2, size=SMALL), overwrite=True)
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


def test_strung_animation_draws_the_bed_beside_the_frame(standard_model, tmp_path):
    # issue 25 item 6: with a string bed the image is split, the frame's side view on the left
    # and the bed's surface on the right; both halves are drawn and the bed moves (its right
    # half changes between frames while the ball pushes it in).
    from fem_racket.impact.strung.impact import simulate_strung
    from fem_racket.io.animate_scene import SIDE_SHARE
    from fem_racket.strings.bed import StringBed

    strung = simulate_strung(standard_model, StringBed(), position=0.76, speed=30.0)
    size = (480, 208)
    with pytest.raises(InputError, match="model is required"):
        render_animation(strung, tmp_path / "x.gif", AnimationOptions(frames=2, size=size))
    path = render_animation(
        strung, tmp_path / "bed.gif", AnimationOptions(frames=5, size=size), model=standard_model
    )
    frames = _gif_frames(path)
    assert frames.shape == (5, size[1], size[0], 3)
    cut = int(SIDE_SHARE * size[0])
    for f in frames:
        for half in (f[:, :cut], f[:, cut:]):
            assert len(np.unique(half.reshape(-1, 3), axis=0)) > 20
    # the bed's half changes from the first image to the middle one (the bed deflects)
    right = frames[:, 40:-40, cut:]
    assert np.any(right[0] != right[2], axis=-1).mean() > 0.02
    meta = json.loads((tmp_path / "bed.gif.json").read_text())
    assert meta["parameters"]["stringbed_stiffness_n_m"] == strung.point.bed_stiffness
    assert meta["parameters"]["frames"] == 5


def test_animate_cli_with_strings(capsys, tmp_path):
    from tests.clirun import run

    out = tmp_path / "s.gif"
    code, text, err = run(capsys, "animate", "--string-tension", "240", "--out", out,
                          "--frames", "3", "--size", "320x160", "--quiet")  # fmt: skip
    assert code == 0, err
    assert len(_gif_frames(out)) == 3


def test_options_of_a_table_are_its_fields_by_name():
    # a run file's [animate] values (with keys the options do not hold) give the same options
    # as the keywords, checked alike
    table = {"out": "a.gif", "field": "slope", "frames": 7, "fps": 10.0, "scale": 2.0,
             "subdivide": 3, "size": (320, 160), "overwrite": True}  # fmt: skip
    same = AnimationOptions(field="slope", frames=7, fps=10.0, scale=2.0, subdivide=3, size=SMALL)
    assert AnimationOptions.of(table) == same
    with pytest.raises(InputError, match="scale"):
        AnimationOptions.of({**table, "scale": -1.0})
