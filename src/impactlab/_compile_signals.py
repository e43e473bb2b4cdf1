"""Ctrl-C and SIGTERM during a compilation of impactlab: delivered at once, and again where
numba's toolchain dropped them.

numba hands each compiled object to llvmlite, which calls back into Python through ctypes to
save it to the disk cache. An interrupt raised in that callback is printed and dropped
("Exception ignored on calling ctypes callback function"), and numba then fails with
``RuntimeError: no compiled object yet``: a Ctrl-C during a first run ended in two tracebacks
and exit status 1 instead of the command's ``interrupted`` line and 130 (a sweep's
``SweepInterrupted``). While a compilation of a function of impactlab runs in the main thread
(``numba:compile`` events, as the garbage collector's pause in ``impactlab._compile_gc``),
SIGINT and SIGTERM go to the handlers in place as before, at once, and are noted; when a
compilation ends without the interrupt having come through (it was dropped), the signal is
raised again there, so that it reaches the handlers before numba goes on; Python's report of
the dropped interrupt ("Exception ignored ...", a traceback) is left out. Outside the main
thread, where Python cannot set handlers, nothing changes.
"""

from __future__ import annotations

import signal
import sys
import threading
from typing import Any

from impactlab._compile_notice import module_of, register
from impactlab._interrupts import hold, restore

#: The package whose compilation is watched.
PACKAGE = "impactlab."


class SignalWatch:
    """Counts nested compilations; while the outermost one of ``PACKAGE`` runs in the main
    thread, SIGINT and SIGTERM are noted on their way to the handlers in place before."""

    def __init__(self) -> None:
        self.depth = 0
        self.before: dict[int, Any] = {}
        self.noted: list[int] = []
        self.hook: Any = None

    def unraisable(self, report: Any) -> None:
        """``sys.unraisablehook`` while watched: an interrupt dropped in a callback is raised
        again at the compilation's end, so its report is left out; anything else is reported."""
        if isinstance(report.exc_value, KeyboardInterrupt) and self.noted:
            return
        (self.hook or sys.__unraisablehook__)(report)

    def deliver(self, signum: int, frame: Any) -> None:
        """Note the signal, then hand it to the handler in place before (SIG_DFL: its default
        action, at once)."""
        self.noted.append(signum)
        handler = self.before.get(signum, signal.SIG_DFL)
        if callable(handler):
            handler(signum, frame)
            return
        signal.signal(signum, signal.SIG_DFL)
        signal.raise_signal(signum)

    def on_start(self, event: Any) -> None:
        if threading.current_thread() is not threading.main_thread():
            return
        self.depth += 1
        if self.depth != 1 or not module_of(event).startswith(PACKAGE):
            return
        self.before = hold(self.deliver)
        if self.before:
            self.hook, sys.unraisablehook = sys.unraisablehook, self.unraisable

    def on_end(self, event: Any) -> None:
        if threading.current_thread() is not threading.main_thread():
            return
        self.depth = max(self.depth - 1, 0)
        came_through = _interrupted(event)
        if came_through:
            self.noted.clear()
        if self.depth == 0 and self.before:
            restore(self.before)
            self.before = {}
            sys.unraisablehook, self.hook = self.hook or sys.__unraisablehook__, None
        if self.noted and not came_through:  # dropped on its way (an llvmlite callback)
            first = self.noted[0]
            self.noted.clear()
            signal.raise_signal(first)


def _interrupted(event: Any) -> bool:
    """Whether the compilation of ``event`` ended in an interrupt (its exception details)."""
    details = getattr(event, "_exc_details", None) or (None,)
    kind = details[0]
    return isinstance(kind, type) and issubclass(kind, KeyboardInterrupt)


#: The watch of this process (registered with numba by ``install``).
WATCH = SignalWatch()
_INSTALLED: list[Any] = []


def install() -> None:
    """Register the watch with numba's compile events (once per process)."""
    if not _INSTALLED:
        _INSTALLED.append(register(WATCH))


__all__ = ["WATCH", "SignalWatch", "install"]
