"""A sweep stopped by SIGTERM (``kill PID``, a batch system's time limit, ``timeout``) ends as
one stopped by Ctrl-C: the chunks written are kept, the store's lock is released, a line says
how many chunks are stored, and the command exits 143 (128 + SIGTERM).

While :func:`sigterm_as_interrupt` is active, SIGTERM raises :class:`SweepTerminated` (a
KeyboardInterrupt) in the main thread, where the sweep handles Ctrl-C. A handler that the
program installed itself is left alone, as is a sweep run outside the main thread (Python
delivers signals to the main thread only).
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from types import FrameType

__all__ = ["TERMINATED_EXIT", "SweepTerminated", "sigterm_as_interrupt", "terminated"]

#: The exit status of a command ended by SIGTERM (128 + 15, as the shell reports it).
TERMINATED_EXIT = 128 + int(signal.SIGTERM)


class SweepTerminated(KeyboardInterrupt):
    """SIGTERM received while a sweep ran."""


def _raise(_signum: int, _frame: FrameType | None) -> None:
    raise SweepTerminated("terminated")


@contextmanager
def sigterm_as_interrupt() -> Iterator[None]:
    """SIGTERM raises :class:`SweepTerminated` inside the block (only where its handler is the
    default one and this is the main thread); the handler before it is restored after."""
    main = threading.current_thread() is threading.main_thread()
    if not main or signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL:
        yield
        return
    signal.signal(signal.SIGTERM, _raise)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, signal.SIG_DFL)


def terminated(exc: BaseException) -> bool:
    """Whether ``exc`` (an interrupt of a sweep) was caused by SIGTERM."""
    return isinstance(exc, SweepTerminated) or bool(getattr(exc, "terminated", False))
