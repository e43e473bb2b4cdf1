"""The execution backends of a sweep: the chunks in this process (threads), in a local process
pool, or on a Dask cluster. Each hands every finished chunk to ``sink`` (the store writer)."""

from __future__ import annotations

import multiprocessing as mp
import os
import time
from collections.abc import Callable, Iterable, Sequence
from concurrent.futures import (
    FIRST_COMPLETED,
    Future,
    ProcessPoolExecutor,
    ThreadPoolExecutor,
    wait,
)
from typing import Any

from impactlab.sweep.chunks import ChunkResult, compute_chunk, set_numba_threads
from impactlab.sweep.engine import Evaluator
from impactlab.sweep.study import Study

#: The backends, in the order of ``run_sweep``'s documentation.
BACKENDS = ("threads", "processes", "dask")


def run_threads(
    st: Study,
    pending: Iterable[int],
    ev: Evaluator,
    outputs: Sequence[str],
    threads: int,
    sink: Callable[[ChunkResult, Any], None],
    advance: Any,
) -> None:
    """Chunks in sequence; chunk k is written by a writer thread while chunk k+1 computes (the
    compiled engine releases the GIL in its parallel region, so the two overlap)."""
    with ThreadPoolExecutor(1, thread_name_prefix="sweep-writer") as writer:
        last: Future[None] | None = None
        try:
            for k in pending:
                res = compute_chunk(st, k, ev, outputs, numba_threads=threads)
                if last is not None:
                    last.result()  # at most one chunk waits in memory; errors surface here
                last = writer.submit(sink, res, advance)
        finally:
            if last is not None:
                last.result()  # never leave a write half done behind an interrupt


def _pool_init(threads: int) -> None:
    # numba.set_num_threads only: changing NUMBA_NUM_THREADS after numba has been imported
    # (impactlab imports it) makes numba refuse to launch its threads
    set_numba_threads(threads)


def run_processes(
    st: Study,
    pending: Sequence[int],
    ev: Evaluator,
    outputs: Sequence[str],
    workers: int,
    sink: Callable[[ChunkResult, Any], None],
    advance: Any,
    max_in_flight: int | None,
) -> None:
    limit = max_in_flight or 2 * workers
    todo = list(pending)
    ex = ProcessPoolExecutor(
        max_workers=workers,
        mp_context=mp.get_context("spawn"),
        initializer=_pool_init,
        initargs=(1,),
    )
    running: set[Future[ChunkResult]] = set()
    try:
        while todo or running:
            while todo and len(running) < limit:
                running.add(ex.submit(compute_chunk, st, todo.pop(0), ev, outputs, 1))
            finished, running = wait(running, return_when=FIRST_COMPLETED)
            for fut in finished:
                sink(fut.result(), advance)
    except BaseException:
        ex.shutdown(wait=False, cancel_futures=True)
        raise
    ex.shutdown(wait=True)


def run_dask(
    st: Study,
    pending: Sequence[int],
    ev: Evaluator,
    outputs: Sequence[str],
    scheduler: str | None,
    client: Any,
    sink: Callable[[ChunkResult, Any], None],
    advance: Any,
    max_in_flight: int | None,
) -> int:
    # distributed is heavy to import (about 1 s): only Dask runs pay for it
    from distributed import Client, as_completed

    own = client is None
    cl = Client(scheduler, set_as_default=False) if own else client
    try:
        nthreads = sum(cl.nthreads().values()) or 1
        limit = max_in_flight or max(4, 3 * nthreads)
        todo = list(pending)

        def submit(k: int) -> Any:
            return cl.submit(
                compute_chunk,
                st,
                k,
                ev,
                tuple(outputs),
                pure=False,
                key=f"impactlab-sweep-chunk-{k}-{os.getpid()}-{time.time_ns()}",
            )

        first = [submit(todo.pop(0)) for _ in range(min(limit, len(todo)))]
        ac = as_completed(first, loop=cl.loop)
        try:
            for fut in ac:
                res = fut.result()
                fut.release()
                sink(res, advance)
                if todo:
                    ac.add(submit(todo.pop(0)))
        except BaseException:
            for f in list(ac.futures):
                f.cancel()
            raise
        return len(cl.nthreads())
    finally:
        if own:
            cl.close()
