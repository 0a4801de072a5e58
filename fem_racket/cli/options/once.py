"""Options a command takes once: given a second time, refused (argparse would otherwise keep the
last value and drop the first silently)."""

from __future__ import annotations

import argparse

__all__ = ["Once"]


class Once(argparse.Action):
    """Store an option's value, refusing the option given a second time (the last value would
    otherwise replace the first silently): a one-racket command's ``--mesh``. A subclass says
    why the command takes one in :attr:`reason`."""

    #: Why the option is taken once (the refusal's middle).
    reason = "this command takes one racket"

    def __call__(self, parser, namespace, values, option_string=None):
        first = vars(namespace).get(self.dest)
        if first is not None:  # the default is None: a value here was given before
            raise argparse.ArgumentError(
                self,
                f"{option_string} is given twice ({first!r} and {values!r}): {self.reason}; "
                f"give {option_string} once",
            )
        setattr(namespace, self.dest, values)
