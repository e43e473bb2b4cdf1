"""What ``import impactlab`` sets up before any compiled function is defined: numba's cache
folder and the repair of a damaged entry (``impactlab._compiled_cache``), the notice while
the engine compiles (``impactlab._compile_notice``), the garbage collector's pause during
that compilation (``impactlab._compile_gc``) and its watch of Ctrl-C and SIGTERM
(``impactlab._compile_signals``); in the ``impactlab`` command, a quiet Ctrl-C while it
imports."""

from __future__ import annotations

import contextlib
import signal
import sys
from pathlib import Path
from typing import Any

from impactlab import _compile_gc, _compile_notice, _compile_signals
from impactlab._compiled_cache import repair_damaged_entries, use_cache_dir


def _interrupted_at_start(signum: int, frame: Any) -> None:
    print("interrupted", file=sys.stderr, flush=True)
    raise SystemExit(130)


def _worker() -> bool:
    """True in a process that multiprocessing started (a sweep's worker), whose
    ``sys.argv`` is its parent's."""
    mp = sys.modules.get("multiprocessing")
    return mp is not None and mp.current_process().name != "MainProcess"


def quiet_start_interrupt() -> None:
    """In the ``impactlab`` command (``sys.argv[0]`` named ``impactlab``), Ctrl-C while it
    imports its libraries (a few seconds, before the command line handles Ctrl-C itself)
    prints ``interrupted`` and exits with status 130, as during a command, instead of a
    traceback; the command's worker processes (``sweep run --backend processes``) ignore
    Ctrl-C, which the command itself answers. Any other program that imports impactlab keeps
    Python's own handler."""
    if Path(sys.argv[0] if sys.argv else "").stem != "impactlab":
        return
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        handler = signal.SIG_IGN if _worker() else _interrupted_at_start
        with contextlib.suppress(ValueError):  # not the main thread: Python's handler stays
            signal.signal(signal.SIGINT, handler)


def release_start_interrupt() -> None:
    """Python's own Ctrl-C handler again (the command line turns its KeyboardInterrupt into
    one line), where :func:`quiet_start_interrupt` set the start's."""
    if signal.getsignal(signal.SIGINT) is _interrupted_at_start:
        signal.signal(signal.SIGINT, signal.default_int_handler)


quiet_start_interrupt()
use_cache_dir()
repair_damaged_entries()
_compile_notice.install()
_compile_gc.install()
_compile_signals.install()
