"""Optional parts of the install: which extra brings which library, and one line when it is
missing.

``pip install -e .`` installs the core (scikit-fem, numpy, scipy, meshio, pyvista,
scikit-sundae and the file and plotting libraries): every command but the few below; the extras
add the rest (``pip install -e ".[test]"`` installs them all):

========  ===========================================  =======================================
extra     libraries                                    for
========  ===========================================  =======================================
animate   imageio, imageio-ffmpeg                      animate (GIF, MP4)
design    pymoo, SALib                                 optimize --method nsga2, sensitivity
dask      dask[distributed]                            --scheduler (sweeps and design studies)
all       every one above
========  ===========================================  =======================================

:func:`require` is also the door to pyvista, a core library imported only where it is used: its
import loads pooch, whose ``tqdm.auto`` warns in a Jupyter kernel without ipywidgets
(``TqdmWarning: IProgress not found``) about download bars fem_racket never shows, so that one
warning is silenced while pyvista is imported. :func:`check_installed` refuses the same way
without importing: a command's checks (``fem-racket config --check`` runs them) name a missing
library before any work, and the library is imported where the work uses it.
"""

from __future__ import annotations

import importlib
import importlib.util
import warnings
from types import ModuleType

from fem_racket.validation import InputError

__all__ = ["EXTRAS", "MissingExtra", "check_installed", "require"]

#: Top-level module -> the extra that installs it.
EXTRAS = {
    "imageio": "animate",
    "imageio_ffmpeg": "animate",
    "pymoo": "design",
    "SALib": "design",
    "dask": "dask",
    "distributed": "dask",
}


class MissingExtra(InputError):
    """A library of an optional extra is not installed (the command line: one line, exit 2)."""


def _import(name: str) -> ModuleType:
    """``importlib.import_module(name)``, pooch's notebook warning silenced (see above)."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message="IProgress not found", module="tqdm")
        return importlib.import_module(name)


def require(name: str, what: str) -> ModuleType:
    """Import module ``name``, or say in one line which install adds it (a library of
    :data:`EXTRAS`; a core library missing is a broken install: its own ImportError).

    Parameters
    ----------
    name : str
        The module, e.g. ``"pyvista"`` or ``"SALib.sample.sobol"``.
    what : str
        What needs it, for the message (``"fem-racket animate"``).
    """
    try:
        return _import(name)
    except ModuleNotFoundError as exc:
        top = name.split(".")[0]
        if top not in EXTRAS or exc.name is None or exc.name.split(".")[0] != top:
            raise  # a core library, or one lacking one of its own dependencies
        extra = EXTRAS[top]
        raise MissingExtra(
            f"{what} needs {top}, which is not installed: pip install 'fem_racket[{extra}]' "
            f"(from a clone: pip install -e '.[{extra}]')"
        ) from None


def check_installed(name: str, what: str) -> None:
    """Refuse as :func:`require` does when the top-level module ``name`` cannot be found, without
    importing it (its finders only: pyvista costs ~0.4 s to import, nothing to find).

    Parameters
    ----------
    name : str
        A top-level module, e.g. ``"imageio"``.
    what : str
        What needs it, for the message.
    """
    if importlib.util.find_spec(name) is None:
        require(name, what)  # its import fails too: require's one line (or the import's error)
