"""Python's cyclic garbage collector paused while numba compiles the flexible drop.

numba's compiler creates millions of Python objects (IR, types, llvmlite values); most live
until the compile ends, and the collector passes over them again and again: 7.0 s of the
47 s of CPU of a first flexible drop went to 4168 collections (``gc.callbacks``, rigid engine
already cached, 2026-11-29). While numba compiles a function of this package as the outermost
compilation (``numba:compile`` events, ``numba.core.event``), the collector is off; at the end it
is switched on again and runs once, which frees what the compile left (about 280 MB more at the
peak, 650 instead of 370 MB). A collector switched off by the caller stays off. Python's
reference counting frees everything else as usual in between; only reference cycles wait.
"""

from __future__ import annotations

import gc
import threading
from typing import Any

#: The compiled package whose compilation pauses the collector.
PACKAGE = "impactlab.dynamics.flexcore."


def _module_of(event: Any) -> str:
    try:
        return str(event.data["dispatcher"].py_func.__module__)
    except (AttributeError, KeyError, TypeError):
        return ""


class GCPause:
    """Counts nested compilations; the outermost one of ``PACKAGE`` pauses the collector."""

    def __init__(self) -> None:
        self.depth = 0
        self.paused = False
        self.lock = threading.Lock()

    def on_start(self, event: Any) -> None:
        with self.lock:
            self.depth += 1
            if self.depth == 1 and gc.isenabled() and _module_of(event).startswith(PACKAGE):
                gc.disable()
                self.paused = True

    def on_end(self, event: Any) -> None:
        with self.lock:
            self.depth = max(self.depth - 1, 0)
            if self.depth != 0 or not self.paused:
                return
            self.paused = False
        gc.enable()
        gc.collect()


_INSTALLED: list[Any] = []


def install() -> None:
    """Register the pause with numba's compile events (once per process)."""
    if _INSTALLED:
        return
    from numba.core import event

    pause = GCPause()

    class _Listener(event.Listener):  # type: ignore[misc]
        def on_start(self, ev: Any) -> None:
            pause.on_start(ev)

        def on_end(self, ev: Any) -> None:
            pause.on_end(ev)

    handle = _Listener()
    event.register("numba:compile", handle)
    _INSTALLED.append(handle)
