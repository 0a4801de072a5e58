"""The command line's argument parser: usage errors in one line, exit code 2."""

from __future__ import annotations

import argparse
import re

__all__ = ["OneLineErrorParser"]


class OneLineErrorParser(argparse.ArgumentParser):
    """An argparse parser whose usage errors are one line (no usage dump), exit code 2.

    A word starting with a minus and a digit is a value, not an option (argparse's own rule
    takes only plain negative numbers), so ranges with a negative start read as they are
    written: ``--offsets -0.1:0.1:41``. No option's name starts with a digit.
    """

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = re.compile(r"^-\.?\d")

    def error(self, message: str) -> None:  # type: ignore[override]
        """Print ``prog: error: message`` and exit 2."""
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")
