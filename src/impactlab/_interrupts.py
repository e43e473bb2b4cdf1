"""Ctrl-C inside a compiled call: numba wraps a ``KeyboardInterrupt`` raised while a function
address is dispatched into a ``SystemError`` ("returned a result with an exception set");
these give it back as the interrupt it is, with its own class (``SweepTerminated`` for
SIGTERM keeps its exit status)."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator


def interrupt_inside(exc: BaseException) -> KeyboardInterrupt | None:
    """The interrupt that numba wrapped into ``exc``, or None."""
    seen = 0
    cause: BaseException | None = exc
    while cause is not None and seen < 8:
        if isinstance(cause, KeyboardInterrupt):
            return cause
        cause, seen = cause.__cause__ or cause.__context__, seen + 1
    return None


@contextlib.contextmanager
def plain_interrupts() -> Iterator[None]:
    """Inside the block, an interrupt wrapped by numba is raised as itself; any other
    ``SystemError`` passes on."""
    try:
        yield
    except SystemError as exc:
        ki = interrupt_inside(exc)
        if ki is None:
            raise
        raise ki from None
