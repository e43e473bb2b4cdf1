"""Say so on stderr while impactlab compiles its engine (a first run, or after an update).

numba compiles a function on its first call unless its disk cache holds it; it emits the event
``numba:compile`` around every such compilation (never for a function loaded from the cache).
``install`` registers a listener for it: when an impactlab function starts compiling and the
compilation is still running after ``DELAY_S``, one line goes to stderr (what is compiled, why,
about how long, where it is cached), and on a terminal a counter of the seconds and functions
compiled so far follows on the same line until the compilation ends. Compilations within
``DELAY_S`` (small helpers; ``KERNEL_DELAY_FACTOR`` times it for the kernels that a cold run
compiles on the way to an engine, which then announces itself) print nothing.
``IMPACTLAB_QUIET_COMPILE=1`` silences it. A part
compiled in several pieces, one after the other (the flexible drop: its right-hand side, step
and event handler, then the drop), runs them inside ``one_line()``: one line and one counter
for all of them. A progress display on the terminal gives way to the notice (``gives_way``).
"""

from __future__ import annotations

import os
import shutil
import sys
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any, TextIO

from impactlab._interrupts import plain_interrupts

#: Seconds a compilation runs before it is announced (short ones stay silent).
DELAY_S = 1.0
#: The parts compiled on the way to an engine (its kernels, then the engine itself) wait this
#: many times ``DELAY_S`` of the process's CPU time: a cold run compiles them for 1-3 s and then
#: the engine, which says so; announcing both gave two lines where a busy host stretched the
#: kernels past 1 s (of wall time, and past 5 s on a host at load 6).
KERNEL_DELAY_FACTOR = 5.0
#: Those parts, by their description in ``PARTS``.
KERNEL_PARTS = frozenset(("the engine's shared kernels", "the contact-law kernels"))
#: The compiled parts, by the module of the function being compiled: (name, about how long in
#: CPU seconds on a 2-core machine, as measured by benchmarks/bench_compile.py).
PARTS: tuple[tuple[str, str, int], ...] = (
    ("impactlab.dynamics.slipcore", "the partial-slip impact engine", 20),
    ("impactlab.dynamics.flexcore.batch", "the flexible-rod drop batch", 10),
    ("impactlab.dynamics.slip_batch", "the partial-slip batch engine", 10),
    ("impactlab.dynamics.flexcore", "the flexible-rod drop engine", 25),
    ("impactlab.dynamics.core.batch", "the parallel batch engine", 20),
    ("impactlab.dynamics.core", "the impact engine", 25),
    ("impactlab.dynamics.kernels", "the engine's shared kernels", 5),
    ("impactlab.contact", "the contact-law kernels", 5),
)


def describe(module: str) -> tuple[str, int]:
    """(what is compiled, about how many seconds) for a function of ``module``."""
    for prefix, name, seconds in PARTS:
        if module.startswith(prefix):
            return name, seconds
    return "impactlab's compiled code", 10


#: Progress displays (rich ``Progress``) on the terminal while impactlab may compile: taken off
#: it just before a notice is shown (:func:`gives_way`), so that the notice keeps its one line;
#: their owner starts them again with its next update.
_DISPLAYS: list[Any] = []


@contextmanager
def gives_way(display: Any) -> Iterator[None]:
    """Within the block, ``display`` (a rich ``Progress`` that does not redirect stderr) is
    stopped when a compile notice is about to be shown; its owner restarts it (``start()``
    where ``display.live.is_started`` is false) at its next update."""
    _DISPLAYS.append(display)
    try:
        yield
    finally:
        _DISPLAYS.remove(display)


def _clear_displays() -> None:
    for display in tuple(_DISPLAYS):  # a copy: the owner's block may end meanwhile
        try:
            if display.live.is_started:
                display.stop()
        except Exception:  # a display that cannot stop is not worth a crash
            pass


class _Notice:
    """The state of one announced compilation (a timer thread prints and refreshes the line)."""

    def __init__(
        self, module: str, stream: TextIO, cache_dir: str, announced: set[str] | None = None
    ) -> None:
        self.module = module
        self.announced = set() if announced is None else announced
        self.stream = stream
        self.cache_dir = cache_dir
        self.count = 0
        self.started = time.monotonic()
        self.cpu_started = time.process_time()
        self.shown = False
        self.done = threading.Event()
        self.thread = threading.Thread(target=self._run, name="impactlab-compile", daemon=True)
        self.thread.start()

    def _run(self) -> None:
        what, seconds = describe(self.module)
        if what in KERNEL_PARTS:  # measured in CPU time: a busy host stretches the wall time
            limit = DELAY_S * KERNEL_DELAY_FACTOR
            while time.process_time() - self.cpu_started < limit:
                if self.done.wait(min(0.25, limit)):
                    return
        elif self.done.wait(DELAY_S):
            return
        if what in self.announced:  # one line per part and process: a part compiled in
            return  # several pieces (the flexible drop's addresses, then the drop) says it once
        self.announced.add(what)
        self.shown = True
        _clear_displays()
        tty = _isatty(self.stream)
        line = (
            f"impactlab: compiling {what} (first run after installing or updating impactlab; "
            f"about {seconds} s, once: cached in {self.cache_dir})"
        )
        # the refreshed line must fit the terminal: \r returns to the start of its last row only
        fits = len(line) + len(" ... 9999 s, 9999 functions ... done in 9999 s") < _columns()
        _write(self.stream, line + ("" if tty and fits else "\n"))
        if not tty:
            return
        head = line if fits else "  compiling"
        while not self.done.wait(0.5):
            elapsed = time.monotonic() - self.started
            _write(self.stream, f"\r{head} ... {elapsed:.0f} s, {self.count} functions")

    def finish(self) -> None:
        self.done.set()
        self.thread.join()
        if self.shown and _isatty(self.stream):
            elapsed = time.monotonic() - self.started
            _write(self.stream, f" ... done in {elapsed:.0f} s\n")


def _columns() -> int:
    """The terminal's width in characters (80 where it is not known)."""
    return shutil.get_terminal_size((80, 24)).columns


def _isatty(stream: TextIO) -> bool:
    try:
        return stream.isatty()
    except (AttributeError, ValueError):
        return False


def _write(stream: TextIO, text: str) -> None:
    try:
        stream.write(text)
        stream.flush()
    except (OSError, ValueError):  # a closed or broken stream: the notice is not worth a crash
        pass


class _Listener:
    """Counts nested compilations; the outermost impactlab one owns the notice."""

    def __init__(self) -> None:
        self.depth = 0
        self.notice: _Notice | None = None
        self.lock = threading.Lock()
        self.announced: set[str] = set()  # the parts announced in this process
        self.groups = 0  # open ``one_line`` blocks: their compiles share one notice

    def on_start(self, event: Any) -> None:
        with self.lock:
            self.depth += 1
            if self.notice is not None:
                self.notice.count += 1
                return
            if self.depth != 1 or os.environ.get("IMPACTLAB_QUIET_COMPILE", "") not in ("", "0"):
                return
            module = module_of(event)
            if module.startswith("impactlab."):
                cache = os.environ.get("NUMBA_CACHE_DIR", "numba's default folder")
                self.notice = _Notice(module, sys.stderr, cache, self.announced)

    def on_end(self, event: Any) -> None:
        with self.lock:
            self.depth = max(self.depth - 1, 0)
            if self.depth == 0 and self.groups == 0 and self.notice is not None:
                notice, self.notice = self.notice, None
            else:
                return
        notice.finish()

    def open_group(self) -> None:
        with self.lock:
            self.groups += 1

    def close_group(self) -> None:
        with self.lock:
            self.groups = max(self.groups - 1, 0)
            if self.groups != 0 or self.depth != 0 or self.notice is None:
                return
            notice, self.notice = self.notice, None
        notice.finish()


def module_of(event: Any) -> str:
    """The module of the function a ``numba:compile`` event compiles ("" if it has none)."""
    try:
        return str(event.data["dispatcher"].py_func.__module__)
    except (AttributeError, KeyError, TypeError):
        return ""


def register(target: Any) -> Any:
    """Register ``target`` (``on_start(event)``, ``on_end(event)``) for numba's
    ``numba:compile`` events; returns numba's listener."""
    from numba.core import event

    class _NumbaListener(event.Listener):  # type: ignore[misc]
        def on_start(self, ev: Any) -> None:
            target.on_start(ev)

        def on_end(self, ev: Any) -> None:
            target.on_end(ev)

    handle = _NumbaListener()
    event.register("numba:compile", handle)
    return handle


#: The listener of this process (registered with numba by ``install``).
LISTENER = _Listener()
_INSTALLED: list[Any] = []


def install() -> None:
    """Register the listener with numba (once per process)."""
    if not _INSTALLED:
        _INSTALLED.append(register(LISTENER))


@contextmanager
def one_line(listener: _Listener = LISTENER) -> Iterator[None]:
    """The compilations inside the block are announced as one: the first one's line, with one
    counter (on a terminal) that ends when the block does. Nothing compiled: nothing printed.
    Its compiled calls dispatch function addresses, so an interrupt numba wraps comes back as
    itself (:func:`impactlab._interrupts.plain_interrupts`)."""
    listener.open_group()
    try:
        with plain_interrupts():
            yield
    finally:
        listener.close_group()
