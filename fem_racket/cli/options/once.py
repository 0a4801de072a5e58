"""Options a command takes once: given a second time, refused (argparse would otherwise keep the
last value and drop the first silently): :class:`Once` for a one-racket command's ``--mesh`` and
``--config``, :func:`refuse_repeated` for every option taking a value."""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from typing import Any

from fem_racket.validation import InputError, show

__all__ = ["Once", "refuse_repeated"]


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


class _Recorder(argparse.Namespace):
    """A namespace that claims to hold every option (argparse fills in no defaults) and keeps
    every value an option is given, in order (:attr:`given`: dest -> values)."""

    def __init__(self) -> None:
        super().__init__()
        object.__setattr__(self, "given", {})

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        return _Recorder

    def __setattr__(self, name: str, value: Any) -> None:
        self.given.setdefault(name, []).append(value)
        super().__setattr__(name, value)


def refuse_repeated(parser: argparse.ArgumentParser, argv: Sequence[str]) -> None:
    """Refuse an option that takes a value given twice in ``argv`` (a command's arguments) with
    two different values, under one name or two (``--speed`` and ``--speeds``): argparse keeps
    the last and drops the first silently. Options that collect (``--mesh`` on ``map``) and
    flags are not concerned.

    Raises
    ------
    InputError
        Naming the option, both values and what to do.
    """
    actions = {a.dest: a for a in parser._actions if type(a) is argparse._StoreAction}
    recorder = _Recorder()
    parser.parse_known_args(list(argv), namespace=recorder)
    for dest, values in recorder.given.items():
        if dest in actions and len(values) > 1 and any(v != values[0] for v in values):
            name = actions[dest].option_strings[0]
            raise InputError(
                f"{name} is given twice ({show(values[0])} and {show(values[-1])}): the last "
                f"would replace the first; give {name} once"
            )
