"""Python's cyclic garbage collector paused while numba compiles impactlab's engine.

numba's compiler creates millions of Python objects (IR, types, llvmlite values); most live
until the compilation ends, and the collector passes over them again and again: 7.0 s of the
47 s of CPU of a first flexible drop went to 4168 collections (``gc.callbacks``, rigid engine
already cached), and a cold rigid impact took 30.6-33.8 s of CPU without the collector against
35.6-40.7 s with it (2026-11-29, busy machine). While numba compiles a function of impactlab
as the outermost compilation (``numba:compile`` events, ``numba.core.event``), the collector is
off; at the end it is switched on again and collects the youngest generation once, which frees
what the compilation left (the peak memory of that compilation grows, about 380 -> 670 MB for the
rigid engine). With the collector off, every object the compilation created is in that
generation, so one pass over it finds the compilation's garbage without passing over the rest of
the process again: a full collection (``gc.collect()``) went over all of numba's long-lived
objects as well, at the end of each of the seven compilations of a first rigid impact (1.9 s of
CPU in the collector against 1.3 s, 2026-11-29). A cycle that reaches into older objects waits
for the collector's next full pass, as it would without the pause. A collector switched off by
the caller stays off. Python's reference counting frees everything
else as usual in between; only reference cycles wait. Functions loaded from the disk cache
emit no such event, so a cached start is untouched.
"""

from __future__ import annotations

import gc
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from impactlab._compile_notice import module_of, register

#: The package whose compilation pauses the collector.
PACKAGE = "impactlab."
#: The generation collected when a compilation ends: the objects created while it was paused.
YOUNGEST = 0


class GCPause:
    """Counts nested compilations; the outermost one of ``PACKAGE`` pauses the collector."""

    def __init__(self) -> None:
        self.depth = 0
        self.paused = False
        self.lock = threading.Lock()
        self.defer = False  # freeze the compilation's garbage instead (``garbage_deferred``)
        self.froze = False

    def on_start(self, event: Any) -> None:
        with self.lock:
            self.depth += 1
            if self.depth == 1 and gc.isenabled() and module_of(event).startswith(PACKAGE):
                gc.disable()
                self.paused = True

    def on_end(self, event: Any) -> None:
        with self.lock:
            self.depth = max(self.depth - 1, 0)
            if self.depth != 0 or not self.paused:
                return
            self.paused = False
        gc.enable()
        if self.defer and self.froze:
            gc.freeze()  # garbage and all: handed back when ``garbage_deferred`` ends
        else:
            gc.collect(YOUNGEST)


#: The pause of this process (registered with numba by ``install``).
PAUSE = GCPause()
_INSTALLED: list[Any] = []


def install() -> None:
    """Register the pause with numba's compile events (once per process)."""
    if not _INSTALLED:
        _INSTALLED.append(register(PAUSE))


@contextmanager
def garbage_deferred(pause: GCPause = PAUSE) -> Iterator[None]:
    """Within the block, the objects alive at its start, and at the end of each compilation
    (its garbage included), move to the collector's permanent generation (``gc.freeze``) and go
    back to its oldest generation when the block ends (``gc.unfreeze``), to be collected at its
    next full pass. For a command that compiles, runs once and ends (``impactlab simulate``):
    the process exits before that pass, and its exit skips the frozen objects
    (``impactlab.cli``), so the pass over the compilation's garbage (0.8 s of CPU after a first
    rigid impact, 1.27 million objects) is never made, and the collections inside the block pass
    over none of the modules loaded before it. The price is memory: the garbage stays until the
    block ends (the process's peak, about 600 MB for the rigid engine, is then its size to the
    end). Where the caller had frozen objects itself, they are left as they are and the block
    collects as outside it."""
    pause.defer = True
    if gc.get_freeze_count() == 0:
        gc.freeze()
        pause.froze = True
    try:
        yield
    finally:
        pause.defer = False
        if pause.froze:
            pause.froze = False
            gc.unfreeze()
