"""The command line's argument parser: usage errors in one line, exit code 2.

An option the command does not know is refused naming the command's own help, with the closest
option it has (``fem-racket simulate --positon 0.7`` -> ``did you mean --position?``) or, for an
old spelling, the one that replaced it (:data:`RENAMED`). Every command is a :class:`Command`
(name, summary, the module that adds its options and runs it), added by :func:`add_command`,
its description taken from its module's docstring.
"""

from __future__ import annotations

import argparse
import difflib
import importlib
import re
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

__all__ = ["RENAMED", "Command", "OneLineErrorParser", "add_command", "suggestion"]

#: Old option spellings -> what replaced them (the progress bar shows on a terminal by itself).
RENAMED = {
    "--no-progress": "--quiet",
    "--progress": "the progress bar shows by itself when stderr is a terminal; --quiet hides it",
}


def suggestion(word: str, options: Sequence[str]) -> str:
    """`` (did you mean --x?)`` for the option of ``options`` closest to ``word``, or ``""``."""
    name = word.split("=", 1)[0]
    if name in RENAMED:
        renamed = RENAMED[name]
        return f": did you mean {renamed}?" if renamed.startswith("-") else f": {renamed}"
    close = difflib.get_close_matches(name, [o for o in options if o.startswith("--")], n=1)
    return f": did you mean {close[0]}?" if close else ""


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

    def parse_args(self, args: Any = None, namespace: Any = None) -> argparse.Namespace:  # type: ignore[override]
        """Parse ``args``; a word no option takes is refused by the command it follows."""
        parsed, extras = self.parse_known_args(args, namespace)
        if extras:
            self._command(parsed).unrecognized(extras)
        return parsed

    def _command(self, parsed: argparse.Namespace) -> OneLineErrorParser:
        """The sub-command's parser that ``parsed`` ran (this parser when none)."""
        for action in self._actions:
            if isinstance(action, argparse._SubParsersAction):
                command = action.choices.get(getattr(parsed, action.dest, None) or "")
                if isinstance(command, OneLineErrorParser):
                    return command
        return self

    def unrecognized(self, extras: Sequence[str]) -> None:
        """Refuse the first unknown option of ``extras`` (or the stray values) in one line."""
        options = [s for a in self._actions for s in a.option_strings]
        word = next((w for w in extras if w.startswith("-") and len(w) > 1), None)
        if word is None:
            self.error(f"unrecognized arguments: {' '.join(extras)}")
        self.error(f"unrecognized option {word.split('=', 1)[0]}{suggestion(word, options)}")


def add_command(
    sub: argparse._SubParsersAction, name: str, help: str, doc: str | None = None
) -> argparse.ArgumentParser:
    """Add the command ``name`` to ``sub`` and return its parser.

    Parameters
    ----------
    sub : argparse._SubParsersAction
        The top-level parser's sub-commands.
    name : str
        The command's name (``fem-racket NAME``).
    help : str
        Its line in ``fem-racket --help``.
    doc : str or None
        The command module's docstring, whose second paragraph (the first after its summary) is
        the description ``fem-racket NAME --help`` shows: plain text, no markup, refilled by
        argparse to the terminal's width. Later paragraphs are for readers of the code. None:
        no description.
    """
    description = None if doc is None else doc.split("\n\n")[1]
    return sub.add_parser(name, help=help, description=description)


@dataclass(frozen=True)
class Command:
    """A sub-command: its name and summary, and the module of :mod:`fem_racket.cli.commands` that
    adds its options and runs it, imported only when the command's parser is built in full.

    Parameters
    ----------
    name : str
        The command's name (``fem-racket NAME``).
    help : str
        Its line in ``fem-racket --help``.
    module : str or None
        Its module of :mod:`fem_racket.cli.commands` (None: named after the command).
    described : bool
        The second paragraph of the module's docstring is the command's ``--help`` description
        (see :func:`add_command`); False: no description.
    options : str
        The module's function adding the command's options: ``options(parser)``.
    run : str
        The module's function running the command: ``run(args) -> int`` (``args.func``).
    """

    name: str
    help: str
    module: str | None = None
    described: bool = False
    options: str = "add_arguments"
    run: str = "run"

    @property
    def module_path(self) -> str:
        """The dotted name of the command's module."""
        return f"fem_racket.cli.commands.{self.module or self.name}"

    def add(self, sub: argparse._SubParsersAction, *, full: bool = True) -> argparse.ArgumentParser:
        """Add the command to ``sub`` and return its parser: with its module's options and
        ``func`` when ``full``, else its name and summary only (all ``fem-racket --help`` and a
        mistyped command name need, without importing the module)."""
        if not full:
            return add_command(sub, self.name, self.help)
        module = importlib.import_module(self.module_path)
        parser = add_command(sub, self.name, self.help, module.__doc__ if self.described else None)
        getattr(module, self.options)(parser)
        parser.set_defaults(func=getattr(module, self.run))
        return parser
