"""The execution backends of a sweep: the chunks in this process (threads), in a local process
pool, or on a Dask cluster. Each hands every finished chunk to ``job.sink`` (the store writer).

Pool processes die with their parent (Linux: ``PR_SET_PDEATHSIG``; elsewhere a thread watches
the parent process id), so a killed sweep leaves no orphans computing on. A Dask sweep whose
cluster has no worker left for ``worker_timeout`` seconds stops with an error instead of
waiting for ever.
"""

from __future__ import annotations

import ctypes
import errno
import multiprocessing as mp
import os
import queue
import signal
import sys
import threading
import time
from collections.abc import Callable, Sequence
from concurrent.futures import (
    FIRST_COMPLETED,
    Future,
    ProcessPoolExecutor,
    ThreadPoolExecutor,
    wait,
)
from concurrent.futures.process import BrokenProcessPool
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from impactlab._oserror import oserror_words
from impactlab.sweep.chunks import ChunkResult, compute_chunk, set_numba_threads
from impactlab.sweep.engine import Evaluator
from impactlab.sweep.study import Study

#: The backends, in the order of ``run_sweep``'s documentation.
BACKENDS = ("threads", "processes", "dask")
#: Default seconds a Dask sweep waits while its cluster has no worker before it gives up.
DEFAULT_WORKER_TIMEOUT = 60.0
_PR_SET_PDEATHSIG = 1  # <linux/prctl.h>


@dataclass
class Job:
    """The chunks to compute and where their results go."""

    study: Study
    pending: Sequence[int]
    evaluator: Evaluator
    outputs: Sequence[str]
    sink: Callable[[ChunkResult, Any], None]
    advance: Any

    def deliver(self, res: ChunkResult) -> None:
        self.sink(res, self.advance)


def run_threads(job: Job, threads: int) -> None:
    """Chunks in sequence; chunk k is written by a writer thread while chunk k+1 computes (the
    compiled engine releases the GIL in its parallel region, so the two overlap)."""
    with ThreadPoolExecutor(1, thread_name_prefix="sweep-writer") as writer:
        last: Future[None] | None = None
        try:
            for k in job.pending:
                res = compute_chunk(job.study, k, job.evaluator, job.outputs, numba_threads=threads)
                if last is not None:
                    last.result()  # at most one chunk waits in memory; errors surface here
                last = writer.submit(job.deliver, res)
        finally:
            if last is not None:
                last.result()  # never leave a write half done behind an interrupt


def _watch_parent(parent: int) -> None:
    while True:
        time.sleep(1.0)
        if os.getppid() != parent:
            os._exit(1)


def die_with_parent(parent: int) -> None:
    """Make this (pool) process exit when its parent ``parent`` dies: the kernel's parent-death
    signal on Linux, a watching thread elsewhere."""
    if sys.platform.startswith("linux"):
        libc = ctypes.CDLL(None, use_errno=True)
        armed = libc.prctl(_PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0) == 0
    else:
        armed = False
    if os.getppid() != parent:  # the parent died before the signal was armed
        os._exit(1)
    if not armed:
        threading.Thread(target=_watch_parent, args=(parent,), daemon=True).start()


def _pool_init(threads: int, parent: int) -> None:
    die_with_parent(parent)
    # Ctrl-C reaches the whole process group: the parent answers it (SweepInterrupted) and
    # shuts the pool down; a worker interrupted mid-chunk would only add tracebacks
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    # numba.set_num_threads only: changing NUMBA_NUM_THREADS after numba has been imported
    # (impactlab imports it) makes numba refuse to launch its threads
    set_numba_threads(threads)


class WorkerLostError(RuntimeError):
    """A process of the ``processes`` pool died (killed: by hand, or by the system when memory
    ran out); the finished chunks are stored, a run of the same study continues."""


def _lost(job: Job, stored: int) -> WorkerLostError:
    n = job.study.layout.n_chunks
    return WorkerLostError(
        f"a worker process of the processes backend died (killed by hand, or by the system "
        f"when memory ran out; from a Python script, a run_sweep call not under "
        f'`if __name__ == "__main__":`, which each worker runs again as it imports the '
        f"script): {stored} of {n} chunks stored; run the same command again to continue (with "
        f"fewer --workers if memory ran out)"
    )


def run_processes(job: Job, workers: int, max_in_flight: int | None) -> None:
    """Chunks on a spawned pool of ``workers`` processes; a dead worker stops the sweep with a
    :class:`WorkerLostError` once the chunks that finished are stored."""
    limit = max_in_flight or 2 * workers
    todo = list(job.pending)
    stored = job.study.layout.n_chunks - len(todo)
    ex = ProcessPoolExecutor(
        max_workers=workers,
        mp_context=mp.get_context("spawn"),
        initializer=_pool_init,
        initargs=(1, os.getpid()),
    )
    running: set[Future[ChunkResult]] = set()
    try:
        while todo or running:
            while todo and len(running) < limit:
                k = todo.pop(0)
                running.add(ex.submit(compute_chunk, job.study, k, job.evaluator, job.outputs, 1))
            finished, running = wait(running, return_when=FIRST_COMPLETED)
            lost = [f for f in finished if isinstance(f.exception(), BrokenProcessPool)]
            for fut in finished:
                if fut not in lost:
                    job.deliver(fut.result())
                    stored += 1
            if lost:
                raise BrokenProcessPool
    except BrokenProcessPool:
        # a broken pool has its workers terminated already: wait for them, so that what they
        # print as they die (a script without the main guard: its traceback) comes before the
        # error, which is then the last line on stderr
        ex.shutdown(wait=True, cancel_futures=True)
        raise _lost(job, stored) from None
    except BaseException:
        ex.shutdown(wait=False, cancel_futures=True)
        raise
    ex.shutdown(wait=True)


class NoWorkersError(RuntimeError):
    """The Dask cluster had no worker for ``worker_timeout`` seconds (the finished chunks are
    stored; a run of the same study continues)."""


class _WorkerWatch:
    """Fails the sweep once the cluster has had no worker for ``timeout`` seconds."""

    def __init__(self, client: Any, timeout: float) -> None:
        self.client = client
        self.timeout = timeout
        self.since: float | None = None

    def check(self) -> None:
        if self.client.nthreads():
            self.since = None
            return
        now = time.monotonic()
        self.since = now if self.since is None else self.since
        if now - self.since >= self.timeout:
            raise NoWorkersError(
                f"no Dask worker left on the cluster for {self.timeout:g} s (worker_timeout); "
                f"the finished chunks are stored: start workers and run the same command again "
                f"to continue"
            )


def run_dask(
    job: Job,
    scheduler: str | None,
    client: Any,
    max_in_flight: int | None,
    worker_timeout: float = DEFAULT_WORKER_TIMEOUT,
) -> int:
    """Chunks as tasks on a Dask cluster; returns the number of workers at the end."""
    # distributed is heavy to import (about 1 s): only Dask runs pay for it
    from distributed import Client

    own = client is None
    cl = Client(scheduler, set_as_default=False) if own else client
    finished: queue.Queue[Any] = queue.Queue()
    running: set[Any] = set()
    todo = list(job.pending)

    def submit(k: int) -> None:
        fut = cl.submit(
            compute_chunk,
            job.study,
            k,
            job.evaluator,
            tuple(job.outputs),
            pure=False,
            key=f"impactlab-sweep-chunk-{k}-{os.getpid()}-{time.time_ns()}",
        )
        running.add(fut)
        fut.add_done_callback(finished.put)

    try:
        limit = max_in_flight or max(4, 3 * (sum(cl.nthreads().values()) or 1))
        watch = _WorkerWatch(cl, worker_timeout)
        while todo and len(running) < limit:
            submit(todo.pop(0))
        while running:
            try:
                fut = finished.get(timeout=min(1.0, worker_timeout))
            except queue.Empty:
                watch.check()
                continue
            running.discard(fut)
            res = fut.result()
            fut.release()
            job.deliver(res)
            if todo:
                submit(todo.pop(0))
        return len(cl.nthreads())
    except BaseException:
        for f in list(running):
            f.cancel()
        raise
    finally:
        if own:
            cl.close()


class StoreWriteError(OSError):
    """Writing the store failed (disk full, quota, read-only, ...): the chunks stored before are
    kept, and the same run again continues. ``str()``: one line saying so; ``errno``: the
    cause's; ``__cause__``: the error itself (with its file)."""

    def __init__(self, message: str, cause: OSError) -> None:
        super().__init__(message)
        self.errno = cause.errno

    def __str__(self) -> str:
        return str(self.args[0])


#: The errnos that stop a sweep with ``write_error``'s line while its store is made ready (a
#: full disk, a quota, a read-only file system; their words: ``impactlab._oserror``).
WRITE_ERRORS = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EROFS})


def write_error(exc: OSError, path: Path, stored: int | None, n_chunks: int) -> StoreWriteError:
    """``exc`` while writing the store at ``path`` (``stored`` of ``n_chunks`` chunks stored;
    None: while creating it) as one line that says what is kept and what to do."""
    what, todo = oserror_words(exc, elsewhere="choose another --out") or (
        exc.strerror or type(exc).__name__,
        "fix its cause",
    )
    kept = (
        "while creating it: nothing stored yet"
        if stored is None
        else f"{stored} of {n_chunks} chunks stored; nothing stored is lost"
    )
    return StoreWriteError(
        f"{what} writing {str(path)!r} ({kept}): {todo} and run the same command again", exc
    )
