"""What the command-line process does about signals and standard output.

SIGINT raises KeyboardInterrupt and SIGTERM :class:`Terminated` (a KeyboardInterrupt, so that
every ``finally`` and ``except KeyboardInterrupt`` cleans up the same way); each is also recorded
with :func:`fem_racket.outputs.record_interrupt`, since Python swallows an exception raised inside
a ``__del__`` or a weakref callback: no output is moved into place after a signal, however it
was delivered. :class:`GuardedStdout` tells a failing standard output (a closed pipe, a full
device) apart from the failures of the files a command writes.
"""

from __future__ import annotations

import os
import signal
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from fem_racket.outputs import deferring, record_interrupt

__all__ = [
    "GuardedStdout",
    "StdoutFault",
    "Terminated",
    "received",
    "signal_handlers",
    "silence_stdout",
]


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised like Ctrl-C's KeyboardInterrupt so that it gets the same cleanup."""


class StdoutFault(Exception):
    """Writing to standard output failed (the ``OSError`` is its ``__cause__``)."""


class GuardedStdout:
    """``sys.stdout`` whose write errors are :class:`StdoutFault`, told apart from the errors
    of the files a command writes."""

    def __init__(self, stream: Any) -> None:
        self._stream = stream

    def write(self, text: str) -> int:
        """Write to the wrapped stream."""
        try:
            return self._stream.write(text)
        except OSError as exc:
            raise StdoutFault() from exc

    def flush(self) -> None:
        """Flush the wrapped stream."""
        try:
            self._stream.flush()
        except OSError as exc:
            raise StdoutFault() from exc

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)


#: Interruptions received during the current command (a swallowed one included).
received: list[type[BaseException]] = []


@contextmanager
def signal_handlers() -> Iterator[None]:
    """SIGINT raises KeyboardInterrupt and SIGTERM :class:`Terminated`, and records it (see
    :func:`fem_racket.outputs.record_interrupt`: an interruption that Python swallowed, raised
    inside a ``__del__`` or a weakref callback, still stops any output from being moved into
    place). The old handlers are restored after."""

    def handler(signum: int, frame: Any) -> None:
        kind = Terminated if signum == signal.SIGTERM else KeyboardInterrupt
        record_interrupt(kind)
        received.append(kind)
        if not deferring():  # else raised at the end of the deferred block
            raise kind()

    old = {}
    try:
        for s in (signal.SIGINT, signal.SIGTERM):
            old[s] = signal.signal(s, handler)
    except ValueError:  # not the main thread: leave the handlers alone
        pass
    received.clear()
    try:
        yield
    finally:
        for s, h in old.items():
            signal.signal(s, h)
        record_interrupt(None)
        received.clear()


def silence_stdout() -> None:
    """Send later writes (the interpreter's final flush) to /dev/null."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # no file descriptor (e.g. captured)
        pass
