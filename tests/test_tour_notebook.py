"""scripts/tour.py run as a Jupyter notebook (jupytext percent cells, executed by nbclient in an
IPython kernel), as a newcomer opens it (issue 23, item 7): every cell runs; no cell writes to
stderr (a warning such as tqdm's "IProgress not found"); no cell's result is a bare
``PosixPath(...)``; every plot shows inline, the power map's too; files go only to the folder it
ran in (its ``output/tour/``), none into the repository."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
TOUR = ROOT / "scripts" / "tour.py"


def _untracked() -> set[str]:
    """The repository's changed or untracked paths outside output/ (None outside a clone)."""
    done = subprocess.run(
        ["git", "status", "--porcelain", "--untracked-files=all"],
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    if done.returncode != 0:
        return set()
    return {ln[3:] for ln in done.stdout.splitlines() if not ln[3:].startswith("output/")}


@pytest.mark.slow  # ~17 s on a quiet machine, 30-60 s under load (kernel start included)
def test_the_tour_runs_as_a_notebook_without_warnings(tmp_path):
    import jupytext
    from nbclient import NotebookClient

    before = _untracked()
    nb = jupytext.read(TOUR)
    env = {"PYTHONPATH": str(ROOT), "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
    old = {k: os.environ.get(k) for k in env}
    os.environ.update(env)  # the kernel imports this checkout's fem_racket
    try:
        NotebookClient(
            nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
        ).execute()
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v
    code = [c for c in nb.cells if c.cell_type == "code"]
    outputs = [o for c in code for o in c.outputs]
    errors = [o.text for o in outputs if o.output_type == "stream" and o.name == "stderr"]
    assert not errors, errors  # warnings included
    results = [o.data.get("text/plain", "") for o in outputs if o.output_type == "execute_result"]
    assert not [r for r in results if "PosixPath(" in r], results

    def images(cell) -> int:
        return sum("image/png" in o.get("data", {}) for o in cell.outputs)

    plotting = [c for c in code if "save_figure(" in c.source]
    assert len(plotting) == 4  # force, sweep, refinement, power map
    assert all(images(c) == 1 for c in plotting), [c.source for c in plotting if images(c) != 1]
    assert "map_figure" in plotting[-1].source
    written = {p.relative_to(tmp_path).parts[:2] for p in tmp_path.rglob("*") if p.is_file()}
    assert written == {("output", "tour")}, written
    tour = tmp_path / "output" / "tour"
    assert {"force.png", "sweep.png", "refine.png", "map.png", "impact_vtk"} <= {
        p.name for p in tour.iterdir()
    }
    assert _untracked() == before  # nothing written into the repository
