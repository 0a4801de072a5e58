"""The installed package's version (base layer: any module may import it)."""

from importlib.metadata import PackageNotFoundError, version

__all__ = ["__version__"]

try:
    __version__ = version("fem_racket")
except PackageNotFoundError:  # running from a source tree without installation
    __version__ = "0.0.0"
