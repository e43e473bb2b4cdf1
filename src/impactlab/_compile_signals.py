"""Ctrl-C and SIGTERM held while numba compiles a function of impactlab, then delivered.

numba hands each compiled object to llvmlite, which calls back into Python through ctypes to
save it to the disk cache. An interrupt that lands in that callback is printed and dropped
("Exception ignored on calling ctypes callback function"), and numba then fails with
``RuntimeError: no compiled object yet``: a Ctrl-C during a first run ended in two tracebacks
and exit status 1 instead of the command's ``interrupted`` line and 130 (a sweep's
``SweepInterrupted``). While the outermost compilation of a function of impactlab runs in the
main thread (``numba:compile`` events, as the garbage collector's pause in
``impactlab._compile_gc``), SIGINT and SIGTERM are noted instead of handled; when it ends, the
handlers in place before are restored and the first signal noted is raised again, so that it
reaches them at once. A Ctrl-C thus waits for the end of the function being compiled (a
fraction of a second to a few seconds), never for the whole engine. Outside the main thread,
where Python cannot set handlers, nothing changes.
"""

from __future__ import annotations

import threading
from typing import Any

from impactlab._compile_notice import module_of, register
from impactlab._interrupts import HELD, hold, release

#: The package whose compilation holds the signals.
PACKAGE = "impactlab."


class SignalHold:
    """Counts nested compilations; the outermost one of ``PACKAGE`` in the main thread holds
    ``HELD`` until it ends."""

    def __init__(self) -> None:
        self.depth = 0
        self.before: dict[int, Any] = {}
        self.noted: list[int] = []

    def note(self, signum: int, frame: Any) -> None:
        """The handler while a compilation runs: remember the signal."""
        self.noted.append(signum)

    def on_start(self, event: Any) -> None:
        if threading.current_thread() is not threading.main_thread():
            return
        self.depth += 1
        if self.depth == 1 and module_of(event).startswith(PACKAGE):
            self.before = hold(self.note)

    def on_end(self, event: Any) -> None:
        if threading.current_thread() is not threading.main_thread():
            return
        self.depth = max(self.depth - 1, 0)
        if self.depth == 0 and self.before:
            before, self.before = self.before, {}
            release(before, self.noted)


#: The hold of this process (registered with numba by ``install``).
HOLD = SignalHold()
_INSTALLED: list[Any] = []


def install() -> None:
    """Register the hold with numba's compile events (once per process)."""
    if not _INSTALLED:
        _INSTALLED.append(register(HOLD))


__all__ = ["HELD", "HOLD", "SignalHold", "install"]
