"""Stopping FE runs cleanly: Ctrl-C (KeyboardInterrupt) or SIGTERM while ccx runs ends every
running ccx process, starts no other, lets each run remove its working folder, and then ends
as it would have (a KeyboardInterrupt raised; a SIGTERM ends the process as SIGTERM does).

``run_parallel`` runs jobs on threads this way; ``popen`` and ``release`` track the ccx
processes (``ccx.run_ccx``)."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import threading
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import ThreadPoolExecutor, as_completed
from typing import Any, TypeVar

T = TypeVar("T")

_LOCK = threading.Lock()
_RUNNING: set[subprocess.Popen[str]] = set()
_STOPPING = threading.Event()


class RunsStoppedError(Exception):
    """A ccx run ended, or not started, because the runs are being stopped (Ctrl-C, SIGTERM)."""


def popen(args: Sequence[str], **kwargs: Any) -> subprocess.Popen[str]:
    """``subprocess.Popen(args, text=True, ...)``, tracked until :func:`release`;
    :class:`RunsStoppedError` instead while runs are being stopped."""
    with _LOCK:
        if _STOPPING.is_set():
            raise RunsStoppedError("not started: the FE runs are being stopped")
        proc = subprocess.Popen(args, text=True, **kwargs)
        _RUNNING.add(proc)
    return proc


def release(proc: subprocess.Popen[str]) -> None:
    """Stop tracking ``proc`` (it has ended); :class:`RunsStoppedError` when it was ended by
    :func:`stop_running`."""
    with _LOCK:
        _RUNNING.discard(proc)
        stopped = _STOPPING.is_set()
    if stopped:
        raise RunsStoppedError("ended: the FE runs are being stopped")


def stop_running() -> None:
    """End every tracked ccx process (SIGTERM) and start no other until :func:`resume`."""
    with _LOCK:
        _STOPPING.set()
        for proc in _RUNNING:
            with contextlib.suppress(OSError):  # already gone
                proc.terminate()


def resume() -> None:
    """Allow new ccx processes again (after :func:`stop_running`)."""
    _STOPPING.clear()


@contextlib.contextmanager
def sigterm_as_interrupt() -> Iterator[None]:
    """While inside: SIGTERM raises KeyboardInterrupt in the main thread (so that every
    ``finally`` and ``with`` runs: ccx is ended, its temporary folder removed); on leaving,
    a SIGTERM received ends the process with the default action, as it would have. Only in the
    main thread and where SIGTERM has its default action (a handler of the program's own is
    left in place)."""
    if (
        threading.current_thread() is not threading.main_thread()
        or signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL
    ):
        yield
        return
    got: list[int] = []

    def handler(signum: int, frame: Any) -> None:
        if got:  # a second one while stopping: the first is being handled
            return
        got.append(signum)
        raise KeyboardInterrupt("SIGTERM: the FE runs are stopped")

    signal.signal(signal.SIGTERM, handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
        if got:  # cleaned up: now end as the signal would have
            os.kill(os.getpid(), signal.SIGTERM)


def run_parallel(
    todo: Sequence[int],
    workers: int,
    job: Callable[[int], T],
    handle: Callable[[T], None],
) -> None:
    """Run ``job(i)`` for each ``i`` of ``todo`` on ``workers`` threads, handing each return
    value to ``handle`` as it comes. On any exception in this thread (Ctrl-C; SIGTERM, made
    one by :func:`sigterm_as_interrupt`): every running ccx is ended, no job left is started,
    and the running ones are waited for (their folders removed) before it propagates."""
    with sigterm_as_interrupt(), ThreadPoolExecutor(max_workers=workers) as pool:
        try:
            for future in as_completed([pool.submit(job, i) for i in todo]):
                handle(future.result())
        except BaseException:
            stop_running()
            try:
                pool.shutdown(wait=True, cancel_futures=True)
            finally:
                resume()
            raise
