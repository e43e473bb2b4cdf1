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
A resume first checks the finished chunks against their checksums and computes the damaged ones
again. The engine's ``flags`` output is always stored when the engine has it.
One chunk's computation is in :mod:`~impactlab.sweep.chunks`, the backends in
:mod:`~impactlab.sweep.backends`, what a run returns in :mod:`~impactlab.sweep.run_result`.
"""

from __future__ import annotations

import dataclasses
import re
import sys
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from impactlab.dynamics.input_checks import check_friction_rtol
from impactlab.sweep.backends import (
    BACKENDS,
    DEFAULT_WORKER_TIMEOUT,
    WRITE_ERRORS,
    Job,
    run_dask,
    run_processes,
    run_threads,
    write_error,
)
from impactlab.sweep.chunks import ChunkResult
from impactlab.sweep.engine import (
    ENGINE,
    Evaluator,
    computed_outputs,
    with_derived,
)
from impactlab.sweep.integrity import describe
from impactlab.sweep.limits import usable_cores
from impactlab.sweep.options import with_recorded_chunk_size
from impactlab.sweep.progress_bar import progress_bar
from impactlab.sweep.run_result import SweepResult, SweepStats
from impactlab.sweep.store import StoreMeta, SweepStore
from impactlab.sweep.study import Study, load_study
from impactlab.sweep.study_meta import category_values, store_meta
from impactlab.sweep.study_record import with_recorded_laws
from impactlab.sweep.summary import not_ok_text, result_counts
from impactlab.sweep.termination import sigterm_as_interrupt, terminated


class FlaggedCasesWarning(UserWarning):
    """A sweep left cases whose result is not ok (a flag that is not advisory): stored, but not
    plain success (``SweepStats.flagged`` counts them)."""


class FailedCasesWarning(FlaggedCasesWarning):
    """No case of a sweep succeeded: every case was refused or failed (no status 0;
    ``SweepStats.failed`` counts them, ``SweepStats.status`` names why). A
    :class:`FlaggedCasesWarning`, so that a filter of those covers it (the command line says it
    in its own line and exits with status 2)."""


class SweepInterrupted(KeyboardInterrupt):
    """The sweep stopped early (Ctrl-C, or SIGTERM: ``terminated``); the finished chunks are
    stored. ``args[0]``: the line that says how many; ``said``: whether it was printed already
    (not when quiet)."""

    def __init__(
        self, message: str = "interrupted", said: bool = False, terminated: bool = False
    ) -> None:
        super().__init__(message)
        self.said = said
        #: stopped by SIGTERM, not Ctrl-C (``sweep.termination``: the command exits 143)
        self.terminated = terminated


def _note(msg: str, quiet: bool) -> None:
    if not quiet:
        print(msg, file=sys.stderr, flush=True)


@dataclass(frozen=True)
class _Backend:
    """Where the chunks run (checked arguments of ``run_sweep``)."""

    name: str
    workers: int
    scheduler: str | None = None
    client: Any = None
    max_in_flight: int | None = None
    worker_timeout: float = DEFAULT_WORKER_TIMEOUT


#: A scheduler's address: an optional scheme, then, for the network schemes (and none), a host
#: (a name, an IPv4 or a bracketed IPv6 address) and a port.
_ADDRESS = re.compile(r"(?:(?P<scheme>[A-Za-z][A-Za-z0-9+.-]*)://)?(?P<rest>\S+)")
_HOST_PORT = re.compile(r"(?:\[[0-9A-Fa-f:.]+\]|[^\s:/\[\]]+):\d{1,5}")


def _check_scheduler(scheduler: Any) -> None:
    """ValueError, naming ``scheduler``, for what is not a Dask scheduler's address
    (``tcp://host:8786``, ``host:8786``, ``tls://[::1]:8786``, ``inproc://...``), before the
    store is made."""
    found = _ADDRESS.fullmatch(scheduler) if isinstance(scheduler, str) else None
    scheme = (found["scheme"] or "tcp").lower() if found else ""
    if found is None or (
        scheme in ("tcp", "tls", "ws", "wss") and not _HOST_PORT.fullmatch(found["rest"])
    ):
        raise ValueError(
            f"scheduler {scheduler!r}: expected a Dask scheduler's address, a host and its "
            "port, such as 'tcp://10.0.0.5:8786' or 'localhost:8786'"
        )


def _backend(
    backend: str | None,
    workers: int | None,
    scheduler: str | None,
    client: Any,
    max_in_flight: int | None,
    worker_timeout: float,
) -> _Backend:
    if scheduler is not None or client is not None:
        if backend not in (None, "dask"):
            raise ValueError(f"a scheduler/client implies backend 'dask', got {backend!r}")
        backend = "dask"
    backend = backend or "threads"
    if backend not in BACKENDS:
        raise ValueError(f"unknown backend {backend!r}; known: {', '.join(BACKENDS)}")
    if backend == "dask" and scheduler is None and client is None:
        raise ValueError("backend 'dask' needs scheduler='tcp://host:port' or a client")
    if scheduler is not None:
        _check_scheduler(scheduler)
    if workers is not None and (
        isinstance(workers, bool) or not isinstance(workers, int) or workers < 1
    ):
        raise ValueError(f"workers must be an integer >= 1, got {workers!r}")
    if isinstance(worker_timeout, bool) or not (
        isinstance(worker_timeout, int | float) and worker_timeout > 0
    ):
        raise ValueError(f"worker_timeout must be a number of seconds > 0, got {worker_timeout!r}")
    return _Backend(
        backend, workers or usable_cores(), scheduler, client, max_in_flight, worker_timeout
    )


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
    max_cases: int | None = None,
    worker_timeout: float = DEFAULT_WORKER_TIMEOUT,
) -> SweepResult:
    """Run (or resume) a sweep into a Zarr store.

    study : a ``Study``, a study-file path or a parsed study table.
    store : path of the Zarr store (default ``<study name>.zarr``). An existing store of the same
        study is resumed (damaged chunks are computed again); one of a different study is refused
        unless ``restart=True``.
    backend : "threads" (default), "processes" or "dask" (implied by ``scheduler``/``client``).
    workers : local cores (threads: numba threads; processes: pool size); default all cores.
    scheduler : Dask scheduler address ("tcp://host:port"); ``client``: a ``distributed.Client``.
    quiet : no progress bar and no notes; ``progress``: True/False forces the bar on/off
        (default: shown when stderr is a terminal and not quiet). The warnings below stay:
        they mark the store's result, also on a resume that computes nothing (silence them
        with ``warnings.catch_warnings``; ``stats.flagged`` and ``stats.failed`` count them).
    evaluator : stand-in for the engine (tests); default ``engine.ENGINE``.
    max_cases : refuse a study of more cases than this (default: the study's ``max_cases``).
    worker_timeout : Dask: seconds without any worker on the cluster before the sweep stops with
        an error (the finished chunks stay stored).

    Warns once (``FlaggedCasesWarning``) when the store holds cases not ok (``stats.flagged``),
    and once (``FailedCasesWarning``) when no case succeeded (``stats.succeeded == 0``: every
    case refused or failed, ``stats.failed`` of them).
    A store that cannot be written (a full disk) raises ``backends.StoreWriteError`` (an
    OSError) saying how many chunks are stored; the same call then continues.
    """
    st = load_study(study, max_cases=max_cases)
    path = Path(store) if store is not None else Path(f"{st.name}.zarr")
    st = with_recorded_laws(st, path)  # a store's own laws: its resume needs no --law-file
    st = st if restart else with_recorded_chunk_size(st, path)  # its chunking, unless set
    ev: Evaluator = evaluator if evaluator is not None else ENGINE
    be = _backend(backend, workers, scheduler, client, max_in_flight, worker_timeout)
    ev.validate(category_values(st))
    if st.engine.rtol is not None:  # a model's own cap (partial slip, mindlin)
        for friction in category_values(st)["friction"]:
            check_friction_rtol(float(st.engine.rtol), str(friction))
    meta = store_meta(st, ev)
    unkept = [o for o in st.uncertainty.outputs if o not in meta.outputs] if st.uncertainty else []
    if unkept:  # found before the sweep, not by its report after it
        raise ValueError(
            f"[uncertainty] would report {unkept}, which the study does not keep (it keeps: "
            f"{', '.join(meta.outputs)}); keep them in [outputs], or name the outputs to "
            f"report in [uncertainty] outputs"
        )
    sstore = SweepStore(path)
    with sigterm_as_interrupt():  # kill PID: as Ctrl-C (the lock released, a line)
        try:
            try:
                done = sstore.prepare(st, meta, restart=restart)
            except OSError as exc:
                if exc.errno not in WRITE_ERRORS:
                    raise
                done_now = len(sstore.done_chunks()) if sstore.exists() else None
                raise write_error(exc, path, done_now, st.layout.n_chunks) from exc
            damaged = sstore.verify(done)
            if damaged:
                _note(f"{path}: damaged, computing again: {describe(damaged)}", quiet)
                sstore.discard(damaged)
            stats = SweepStats(
                n_chunks=st.layout.n_chunks,
                n_cases=st.layout.n_cases,
                chunks_before=len(done) - len(damaged),
                backend=be.name,
                workers=be.workers,
                chunks_repaired=len(damaged),
            )
            intact = done - set(damaged)
            res = _run_store(
                st, ev, _stored_meta(sstore, meta), sstore, intact, be, stats, quiet, progress
            )
            stats.status, stats.flagged = result_counts(path)  # the store's, after the run
        finally:
            sstore.release()
    if stats.not_ok:
        warnings.warn(
            FlaggedCasesWarning(
                f"sweep {st.name!r} in {str(path)!r}: {not_ok_text(stats.flagged)}: stored, but "
                f"not plain success (impactlab.flags.ResultFlag); the ok cases: (ds.status == 0) "
                f"& ((ds.flags & ~ADVISORY_FLAGS) == 0); impactlab sweep info {path} counts them"
            ),
            stacklevel=2,
        )
    if stats.failed and not stats.succeeded:
        parts = "; ".join(f"{n} with status {key}" for key, n in stats.status.items() if n)
        warnings.warn(
            FailedCasesWarning(
                f"sweep {st.name!r} in {str(path)!r}: no case succeeded: {stats.failed} case(s) "
                f"refused or failed ({parts}); the store keeps their status, whose meaning is "
                f"in ds.attrs['status_messages']; impactlab sweep info {path} counts them"
            ),
            stacklevel=2,
        )
    return res


def _stored_meta(sstore: SweepStore, meta: StoreMeta) -> StoreMeta:
    """``meta`` with the outputs the store holds (a store made before an output was always
    stored goes on without it)."""
    stored = tuple(sstore.attrs().get("outputs", meta.outputs))
    if stored == meta.outputs:
        return meta
    ints = tuple(o for o in meta.integer_outputs if o in stored)
    return dataclasses.replace(meta, outputs=stored, integer_outputs=ints)


def _run_store(
    st: Study,
    ev: Evaluator,
    meta: StoreMeta,
    sstore: SweepStore,
    done: set[int],
    be: _Backend,
    stats: SweepStats,
    quiet: bool,
    progress: bool | None,
) -> SweepResult:
    path = sstore.path
    lay = st.layout
    pending = [k for k in range(lay.n_chunks) if k not in done]
    if done:
        _note(f"resuming {path}: {len(done)} of {lay.n_chunks} chunks already stored", quiet)
    if not pending:
        return SweepResult(path, st, stats)
    done_cases = sum(lay.block_size(k) for k in done)
    show: bool | None = False if quiet and progress is None else progress
    writer = sstore.writer(
        [*meta.outputs, "status", *(st.sample.inputs if st.sample is not None else ())]
    )
    t0 = time.perf_counter()

    def sink(res: ChunkResult, advance: Callable[[int], None]) -> None:
        tw = time.perf_counter()
        outputs = with_derived(res.outputs, meta.outputs)  # derived outputs: computed here
        try:
            sstore.write_chunk(writer, st, res.index, outputs, res.status)
        except OSError as exc:  # a full disk: one line, the chunks stored are kept
            raise write_error(exc, path, len(sstore.done_chunks()), lay.n_chunks) from exc
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
        stats.first_task_cases.setdefault(res.worker, res.n_cases)
        advance(res.n_cases)

    try:
        with progress_bar(lay.n_cases, done_cases, st.name, show) as advance:
            job = Job(st, pending, ev, computed_outputs(meta.outputs), sink, advance)
            if be.name == "threads":
                run_threads(job, be.workers)
            elif be.name == "processes":
                run_processes(job, be.workers, be.max_in_flight)
            else:
                stats.workers = run_dask(
                    job, be.scheduler, be.client, be.max_in_flight, be.worker_timeout
                )
    except KeyboardInterrupt as exc:
        stats.wall_s = time.perf_counter() - t0
        n_done = len(sstore.done_chunks())
        line = (
            f"interrupted: {n_done} of {lay.n_chunks} chunks stored in {path}; run the same "
            f"command again to continue"
        )
        _note(line, quiet)
        raise SweepInterrupted(line, said=not quiet, terminated=terminated(exc)) from None
    finally:
        writer.close()
    stats.wall_s = time.perf_counter() - t0
    return SweepResult(path, st, stats)
