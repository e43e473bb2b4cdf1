"""Running a study: chunks to the engine (local cores, a local process pool or a Dask cluster),
results into the Zarr store as they finish, resumable at any point.

Backends (``backend=``):

- ``"threads"`` (default): chunks run one after another in this process and the compiled engine
  spreads each chunk over the local cores (numba ``prange``). No set-up, no inter-process
  traffic; measured fastest on one machine (docs/sweep.md, "Benchmark").
- ``"processes"``: a local pool of ``workers`` processes (spawned), one numba thread each; the
  parent writes the results.
- ``"dask"``: chunks go to a Dask cluster (``scheduler="tcp://host:port"`` or ``client=``); the
  client writes the results. A worker lost mid-sweep has its chunks re-run elsewhere by the
  scheduler. Workers load the compiled kernels from the on-disk numba cache when they share
  ``NUMBA_CACHE_DIR`` with a process that compiled them (``SweepStats.cache``).

Whatever the backend, chunk ``k`` always holds the same cases and gives the same numbers, and
finished chunks are never recomputed: an interrupted sweep (Ctrl-C, kill -9, an exception, a lost
worker) run again completes the missing chunks only, and the store equals an uninterrupted run's.
"""

from __future__ import annotations

import os
import socket
import sys
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, Future, ProcessPoolExecutor, wait
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.sweep.engine import (
    ENGINE,
    Evaluator,
    Statics,
    default_threads,
    numba_cache_stats,
)
from impactlab.sweep.inputs import CATEGORY_INPUTS, OUTPUT_ALIASES
from impactlab.sweep.store import StoreMeta, SweepStore, open_sweep
from impactlab.sweep.study import Study, load_study

BACKENDS = ("threads", "processes", "dask")


@dataclass
class ChunkResult:
    """What one chunk computation sends back to the writer."""

    index: int
    outputs: dict[str, np.ndarray]
    status: np.ndarray
    n_cases: int
    eval_s: float
    total_s: float
    cache: dict[str, int]
    worker: str


def _set_numba_threads(n: int | None) -> None:
    if n is None:
        return
    try:
        import numba

        numba.set_num_threads(max(1, min(int(n), numba.config.NUMBA_NUM_THREADS)))  # type: ignore[attr-defined]
    except (ImportError, ValueError):  # pragma: no cover
        pass


def _dask_worker_threads() -> int | None:
    """Inside a Dask worker: numba threads per task = cores / worker threads (None outside)."""
    try:
        from distributed import get_worker

        w = get_worker()
    except (ImportError, ValueError):
        return None
    import numba

    cores = int(numba.config.NUMBA_NUM_THREADS)  # type: ignore[attr-defined]
    return max(1, cores // max(1, int(w.state.nthreads)))


def compute_chunk(study: Study, index: int, evaluator: Evaluator, outputs: Sequence[str],
                  numba_threads: int | None = None) -> ChunkResult:
    """Compute chunk ``index`` of ``study`` (pure: the result depends on the study and ``index``
    only). Runs wherever it is sent: this process, a pool process or a Dask worker."""
    t0 = time.perf_counter()
    _set_numba_threads(numba_threads if numba_threads is not None else _dask_worker_threads())
    before = numba_cache_stats()
    numeric, categories, bshape = study.chunk_cases(index)
    statics = Statics(categories, study.law_params, study.engine.kwargs())
    t1 = time.perf_counter()
    outs, status = evaluator(numeric, statics, outputs)
    t2 = time.perf_counter()
    after = numba_cache_stats()
    n = int(np.prod(bshape, dtype=np.int64))
    status = np.asarray(status, dtype=np.int32)
    if status.shape != (n,):
        raise RuntimeError(f"evaluator returned status of shape {status.shape}, expected ({n},)")
    for o in outputs:
        if np.shape(outs[o]) != (n,):
            raise RuntimeError(f"evaluator returned {o!r} of shape {np.shape(outs[o])}")
    return ChunkResult(
        index=index,
        outputs={o: np.asarray(outs[o]) for o in outputs},
        status=status,
        n_cases=n,
        eval_s=t2 - t1,
        total_s=time.perf_counter() - t0,
        cache={"hits": after["hits"] - before["hits"],
               "misses": after["misses"] - before["misses"],
               "dispatchers": after["dispatchers"]},
        worker=f"{socket.gethostname()}:{os.getpid()}",
    )


@dataclass
class SweepStats:
    """Numbers of one ``run_sweep`` call."""

    n_chunks: int = 0
    n_cases: int = 0
    chunks_before: int = 0
    chunks_computed: int = 0
    cases_computed: int = 0
    wall_s: float = 0.0
    eval_s: float = 0.0
    compute_s: float = 0.0
    write_s: float = 0.0
    backend: str = ""
    workers: int = 0
    #: per worker: numba cache hits/misses seen by its tasks
    cache: dict[str, dict[str, int]] = field(default_factory=dict)
    #: per worker: wall time of its first task [s]
    first_task_s: dict[str, float] = field(default_factory=dict)

    @property
    def throughput(self) -> float:
        """Cases computed per second of wall time."""
        return self.cases_computed / self.wall_s if self.wall_s > 0 else 0.0


@dataclass
class SweepResult:
    """A finished (or resumed) sweep: the store and the numbers of this run."""

    path: Path
    study: Study
    stats: SweepStats

    @property
    def dataset(self) -> Any:
        """The results as a lazy xarray Dataset."""
        return open_sweep(self.path)

    @property
    def complete(self) -> bool:
        return len(SweepStore(self.path).done_chunks()) == self.study.layout.n_chunks


class SweepInterrupted(KeyboardInterrupt):
    """The sweep stopped early (Ctrl-C); the finished chunks are stored."""


def resolve_outputs(study: Study, evaluator: Evaluator) -> tuple[str, ...]:
    """The outputs to keep, checked against what the evaluator provides."""
    fields = tuple(evaluator.output_fields())
    if study.outputs is None:
        return fields
    outs = tuple(OUTPUT_ALIASES.get(o, o) for o in study.outputs)
    unknown = [o for o in outs if o not in fields]
    if unknown:
        raise ValueError(
            f"unknown output(s) {unknown}; the engine provides: {', '.join(fields)} "
            f"(aliases: {', '.join(f'{k}={v}' for k, v in OUTPUT_ALIASES.items())})"
        )
    return outs


def category_values(study: Study) -> dict[str, list[str]]:
    """Every value each category input takes in the study."""
    vals: dict[str, list[str]] = {}
    for name in CATEGORY_INPUTS:
        axis = next((a for a in study.axes if a.name == name), None)
        if axis is not None:
            vals[name] = [str(v) for v in axis.values]
        else:
            vals[name] = [str(study.value_of(name))]
    return vals


def store_meta(study: Study, evaluator: Evaluator) -> StoreMeta:
    """The store metadata for ``study`` run by ``evaluator`` (hash includes the engine and the
    impactlab version)."""
    import impactlab

    outputs = resolve_outputs(study, evaluator)
    ident = f"{evaluator.identity}|impactlab {impactlab.__version__}"
    return StoreMeta(
        study_hash=study.hash(ident),
        outputs=outputs,
        integer_outputs=tuple(o for o in evaluator.integer_outputs() if o in outputs),
        status_messages=evaluator.status_messages(),
        regimes=evaluator.regimes(),
        engine=ident,
    )


@contextmanager
def _progress(total: int, done: int, label: str, mode: bool | None
              ) -> Iterator[Callable[[int], None]]:
    """A rich progress bar on stderr (count, rate, elapsed, ETA). ``mode``: None = when stderr is
    a terminal, True = always, False = never."""
    if mode is False:
        yield lambda n: None
        return
    from rich.console import Console
    from rich.progress import (
        BarColumn,
        MofNCompleteColumn,
        Progress,
        TextColumn,
        TimeElapsedColumn,
        TimeRemainingColumn,
    )

    console = Console(stderr=True, force_terminal=True if mode else None)
    if not console.is_terminal:
        yield lambda n: None
        return
    with Progress(
        TextColumn("[bold]{task.description}"),
        BarColumn(),
        MofNCompleteColumn(),
        TextColumn("impacts"),
        TextColumn("{task.fields[rate]}"),
        TimeElapsedColumn(),
        TextColumn("ETA"),
        TimeRemainingColumn(),
        console=console,
        transient=False,
    ) as prog:
        task = prog.add_task(label, total=total, completed=done, rate="")
        t0 = time.perf_counter()
        count = [0]

        def advance(n: int) -> None:
            count[0] += n
            dt = time.perf_counter() - t0
            rate = f"{count[0] / dt:,.0f}/s" if dt > 0 else ""
            prog.update(task, advance=n, rate=rate)

        yield advance


def _note(msg: str, quiet: bool) -> None:
    if not quiet:
        print(msg, file=sys.stderr, flush=True)


def run_sweep(
    study: Study | str | Path | dict[str, Any],
    store: str | Path | None = None,
    *,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    client: Any = None,
    quiet: bool = False,
    progress: bool | None = None,
    restart: bool = False,
    evaluator: Evaluator | None = None,
    max_in_flight: int | None = None,
) -> SweepResult:
    """Run (or resume) a sweep into a Zarr store.

    study : a ``Study``, a study-file path or a parsed study table.
    store : path of the Zarr store (default ``<study name>.zarr``). An existing store of the same
        study is resumed; one of a different study is refused unless ``restart=True``.
    backend : "threads" (default), "processes" or "dask" (implied by ``scheduler``/``client``).
    workers : local cores (threads: numba threads; processes: pool size); default all cores.
    scheduler : Dask scheduler address ("tcp://host:port"); ``client``: a ``distributed.Client``.
    quiet : no progress bar and no notes; ``progress``: True/False forces the bar on/off
        (default: shown when stderr is a terminal and not quiet).
    evaluator : stand-in for the engine (tests); default ``engine.ENGINE``.
    """
    st = load_study(study)
    ev: Evaluator = evaluator if evaluator is not None else ENGINE
    if scheduler is not None or client is not None:
        if backend not in (None, "dask"):
            raise ValueError(f"a scheduler/client implies backend 'dask', got {backend!r}")
        backend = "dask"
    backend = backend or "threads"
    if backend not in BACKENDS:
        raise ValueError(f"unknown backend {backend!r}; known: {', '.join(BACKENDS)}")
    if backend == "dask" and scheduler is None and client is None:
        raise ValueError("backend 'dask' needs scheduler='tcp://host:port' or a client")
    ncores = default_threads()
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int)
                                or workers < 1):
        raise ValueError(f"workers must be an integer >= 1, got {workers!r}")
    nworkers = workers or ncores
    ev.validate(category_values(st))
    meta = store_meta(st, ev)
    path = Path(store) if store is not None else Path(f"{st.name}.zarr")
    sstore = SweepStore(path)
    try:
        if sstore.exists():
            sstore.acquire()  # refuses while another live process writes this store
        done = sstore.prepare(st, meta, restart=restart)
        sstore.acquire()
        return _run_store(st, ev, meta, sstore, done, backend, nworkers, scheduler, client,
                          quiet, progress, max_in_flight)
    finally:
        sstore.release()


def _run_store(st: Study, ev: Evaluator, meta: StoreMeta, sstore: SweepStore, done: set[int],
               backend: str, nworkers: int, scheduler: str | None, client: Any, quiet: bool,
               progress: bool | None, max_in_flight: int | None) -> SweepResult:
    path = sstore.path
    lay = st.layout
    pending = [k for k in range(lay.n_chunks) if k not in done]
    stats = SweepStats(n_chunks=lay.n_chunks, n_cases=lay.n_cases, chunks_before=len(done),
                       backend=backend, workers=nworkers)
    if done:
        _note(f"resuming {path}: {len(done)} of {lay.n_chunks} chunks already stored", quiet)
    if not pending:
        return SweepResult(path, st, stats)
    done_cases = sum(lay.block_size(k) for k in done)
    show: bool | None = False if quiet and progress is None else progress
    arrays = sstore.open_arrays(
        [*meta.outputs, "status", *(st.sample.inputs if st.sample is not None else ())])
    t0 = time.perf_counter()

    def sink(res: ChunkResult, advance: Callable[[int], None]) -> None:
        tw = time.perf_counter()
        sstore.write_chunk(arrays, st, res.index, res.outputs, res.status)
        stats.write_s += time.perf_counter() - tw
        stats.chunks_computed += 1
        stats.cases_computed += res.n_cases
        stats.eval_s += res.eval_s
        stats.compute_s += res.total_s
        c = stats.cache.setdefault(res.worker, {"hits": 0, "misses": 0, "tasks": 0})
        c["hits"] += res.cache["hits"]
        c["misses"] += res.cache["misses"]
        c["tasks"] += 1
        stats.first_task_s.setdefault(res.worker, res.total_s)
        advance(res.n_cases)

    try:
        with _progress(lay.n_cases, done_cases, st.name, show) as advance:
            if backend == "threads":
                _run_threads(st, pending, ev, meta.outputs, nworkers, sink, advance)
            elif backend == "processes":
                _run_processes(st, pending, ev, meta.outputs, nworkers, sink, advance,
                               max_in_flight)
            else:
                stats.workers = _run_dask(st, pending, ev, meta.outputs, scheduler, client,
                                          sink, advance, max_in_flight)
    except KeyboardInterrupt:
        stats.wall_s = time.perf_counter() - t0
        n_done = len(sstore.done_chunks())
        _note(f"interrupted: {n_done} of {lay.n_chunks} chunks stored in {path}; run the same "
              f"command again to continue", quiet)
        raise SweepInterrupted() from None
    stats.wall_s = time.perf_counter() - t0
    return SweepResult(path, st, stats)


def _run_threads(st: Study, pending: Iterable[int], ev: Evaluator, outputs: Sequence[str],
                 threads: int, sink: Callable[[ChunkResult, Any], None], advance: Any) -> None:
    """Chunks in sequence; chunk k is written by a writer thread while chunk k+1 computes (the
    compiled engine releases the GIL in its parallel region, so the two overlap)."""
    from concurrent.futures import ThreadPoolExecutor

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
    _set_numba_threads(threads)


def _run_processes(st: Study, pending: Sequence[int], ev: Evaluator, outputs: Sequence[str],
                   workers: int, sink: Callable[[ChunkResult, Any], None], advance: Any,
                   max_in_flight: int | None) -> None:
    import multiprocessing as mp

    limit = max_in_flight or 2 * workers
    todo = list(pending)
    ex = ProcessPoolExecutor(max_workers=workers, mp_context=mp.get_context("spawn"),
                             initializer=_pool_init, initargs=(1,))
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


def _run_dask(st: Study, pending: Sequence[int], ev: Evaluator, outputs: Sequence[str],
              scheduler: str | None, client: Any, sink: Callable[[ChunkResult, Any], None],
              advance: Any, max_in_flight: int | None) -> int:
    from distributed import Client, as_completed

    own = client is None
    cl = Client(scheduler, set_as_default=False) if own else client
    try:
        nthreads = sum(cl.nthreads().values()) or 1
        limit = max_in_flight or max(4, 3 * nthreads)
        todo = list(pending)

        def submit(k: int) -> Any:
            return cl.submit(compute_chunk, st, k, ev, tuple(outputs), pure=False,
                             key=f"impactlab-sweep-chunk-{k}-{os.getpid()}-{time.time_ns()}")

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
