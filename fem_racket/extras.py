"""Optional parts of the install: which extra brings which library, and one line when it is
missing.

``pip install -e .`` installs what an impact, a sweep, a map, a refinement and the paper's
reproduction need; the extras add the rest (``pip install -e ".[test]"`` installs them all):

========  ===========================================  =======================================
extra     libraries                                    for
========  ===========================================  =======================================
vtk       pyvista (VTK), imageio, imageio-ffmpeg       export-vtk, animate
design    pymoo, SALib                                 optimize --method nsga2, sensitivity
dask      dask[distributed]                            --scheduler (sweeps and design studies)
all       every one above
========  ===========================================  =======================================
"""

from __future__ import annotations

import importlib
from types import ModuleType

from fem_racket.validation import InputError

__all__ = ["EXTRAS", "MissingExtra", "require"]

#: Top-level module -> the extra that installs it.
EXTRAS = {
    "pyvista": "vtk",
    "vtkmodules": "vtk",
    "imageio": "vtk",
    "imageio_ffmpeg": "vtk",
    "pymoo": "design",
    "SALib": "design",
    "dask": "dask",
    "distributed": "dask",
}


class MissingExtra(InputError):
    """A library of an optional extra is not installed (the command line: one line, exit 2)."""


def require(name: str, what: str) -> ModuleType:
    """Import module ``name`` (of :data:`EXTRAS`), or say in one line which install adds it.

    Parameters
    ----------
    name : str
        The module, e.g. ``"pyvista"`` or ``"SALib.sample.sobol"``.
    what : str
        What needs it, for the message (``"export-vtk"``).
    """
    try:
        return importlib.import_module(name)
    except ModuleNotFoundError as exc:
        top = name.split(".")[0]
        if exc.name is None or exc.name.split(".")[0] != top:
            raise  # the library is there but lacks one of its own dependencies
        extra = EXTRAS[top]
        raise MissingExtra(
            f"{what} needs {top}, which is not installed: pip install 'fem_racket[{extra}]' "
            f"(from a clone: pip install -e '.[{extra}]')"
        ) from None
