"""Ctrl-C inside a compiled call: numba wraps a ``KeyboardInterrupt`` raised while a function
address is dispatched into a ``SystemError`` ("returned a result with an exception set");
these give it back as the interrupt it is, with its own class (``SweepTerminated`` for
SIGTERM keeps its exit status). And Ctrl-C and SIGTERM held over a few statements that must
run whole (a saved step and its bookkeeping), then delivered."""

from __future__ import annotations

import contextlib
import signal
import threading
from collections.abc import Callable, Iterator
from typing import Any

#: The signals a hold notes instead of handling.
HELD = (signal.SIGINT, signal.SIGTERM)


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


def hold(note: Callable[[int, Any], None]) -> dict[int, Any]:
    """In the main thread, ``note`` handles ``HELD`` from now on; returns the handlers it
    replaced (to :func:`restore`). Ignored signals, handlers not set from Python and other
    threads (where Python cannot set handlers) are left alone: {}."""
    if threading.current_thread() is not threading.main_thread():
        return {}
    before: dict[int, Any] = {}
    for sig in HELD:
        handler = signal.getsignal(sig)
        if handler in (signal.SIG_IGN, None):
            continue
        before[sig] = handler
        signal.signal(sig, note)
    return before


def restore(before: dict[int, Any]) -> None:
    """The handlers ``before`` (from :func:`hold`) back in place."""
    for sig, handler in before.items():
        signal.signal(sig, handler)


@contextlib.contextmanager
def signals_held() -> Iterator[None]:
    """Within the block, Ctrl-C and SIGTERM are noted; when it ends, the first is delivered to
    the handlers in place before (the block runs whole, in the main thread)."""
    noted: list[int] = []
    before = hold(lambda signum, frame: noted.append(signum))
    try:
        yield
    finally:
        restore(before)
        if noted:
            signal.raise_signal(noted[0])  # it reaches the handlers restored, at once
