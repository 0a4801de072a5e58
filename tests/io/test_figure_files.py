"""Figures in PNG, SVG and PDF at a chosen resolution, each with its provenance inside."""

import json

import pytest

from fem_racket.io.figure_files import save_figure
from fem_racket.outputs import provenance
from fem_racket.validation import InputError


@pytest.fixture
def figure():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(4, 3))
    ax.plot([0, 1], [0, 1])
    yield fig
    plt.close(fig)


def test_png_size_follows_the_dpi_and_holds_the_provenance(figure, tmp_path):
    from PIL import Image

    meta = provenance({"figure": "test"})
    for dpi in (100, 200):
        path = save_figure(figure, tmp_path / f"f{dpi}.png", meta, dpi=dpi)
        with Image.open(path) as im:
            im.load()
            assert im.size == (4 * dpi, 3 * dpi)  # 4 x 3 inches
            assert json.loads(im.text["provenance"]) == meta


def test_svg_and_pdf_are_vector_files_with_the_provenance(figure, tmp_path):
    meta = provenance({"figure": "test"})
    svg = save_figure(figure, tmp_path / "f.svg", meta).read_text()
    assert svg.lstrip().startswith("<?xml") and "<path" in svg and "fem_racket" in svg
    pdf = save_figure(figure, tmp_path / "f.pdf", meta).read_bytes()
    assert pdf.startswith(b"%PDF") and b"/Creator (fem_racket" in pdf


@pytest.mark.parametrize(
    ("name", "dpi", "message"),
    [("f.jpg", 150, "must end in .png, .svg, .pdf"), ("f.png", 10, "dpi = 10")],
)
def test_bad_format_or_dpi_is_one_line(figure, tmp_path, name, dpi, message):
    with pytest.raises(InputError, match=message):
        save_figure(figure, tmp_path / name, provenance(), dpi=dpi)
    assert not list(tmp_path.iterdir())


def test_existing_figure_is_kept_without_overwrite(figure, tmp_path):
    path = tmp_path / "f.png"
    path.write_bytes(b"mine")
    with pytest.raises(InputError, match="already exists"):
        save_figure(figure, path, provenance())
    assert path.read_bytes() == b"mine"
