"""Load a script of ``scripts/`` as a module (the folder is not a package) for the tests."""

import importlib.util
from pathlib import Path
from types import ModuleType

#: The repository's scripts folder.
SCRIPTS = Path(__file__).resolve().parents[1] / "scripts"


def load_script(name: str) -> ModuleType:
    """The module ``scripts/<name>.py``, executed afresh."""
    spec = importlib.util.spec_from_file_location(name, SCRIPTS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
