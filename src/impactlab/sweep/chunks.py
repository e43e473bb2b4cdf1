"""One chunk of a sweep: its computation wherever it runs (this process, a pool process, a Dask
worker) and what it sends back to the writer."""

from __future__ import annotations

import os
import socket
import sys
import time
from collections.abc import Sequence
from dataclasses import dataclass

import numba
import numpy as np

from impactlab.sweep.engine import Evaluator, Statics, numba_cache_stats
from impactlab.sweep.models import tabulates
from impactlab.sweep.study import Study


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


def set_numba_threads(n: int | None) -> None:
    """Limit numba's parallel threads to ``n`` (clamped to [1, NUMBA_NUM_THREADS]); None: as is."""
    if n is None:
        return
    numba.set_num_threads(max(1, min(int(n), numba.config.NUMBA_NUM_THREADS)))  # type: ignore[attr-defined]


def _dask_worker_threads() -> int | None:
    """Inside a Dask worker: numba threads per task = cores / worker threads (None outside)."""
    if "distributed" not in sys.modules:  # not imported: this is no Dask worker
        return None
    # distributed is heavy to import; only Dask runs (which imported it already) get here
    from distributed import get_worker

    try:
        w = get_worker()
    except ValueError:  # not inside a worker
        return None
    cores = int(numba.config.NUMBA_NUM_THREADS)  # type: ignore[attr-defined]
    return max(1, cores // max(1, int(w.state.nthreads)))


def compute_chunk(
    study: Study,
    index: int,
    evaluator: Evaluator,
    outputs: Sequence[str],
    numba_threads: int | None = None,
) -> ChunkResult:
    """Compute chunk ``index`` of ``study`` (pure: the result depends on the study and ``index``
    only). Runs wherever it is sent: this process, a pool process or a Dask worker."""
    t0 = time.perf_counter()
    set_numba_threads(numba_threads if numba_threads is not None else _dask_worker_threads())
    before = numba_cache_stats()
    study.register_laws()  # a user's law travels with the study to every worker
    numeric, categories, bshape = study.chunk_cases(index)
    table = tabulates(study.axes, study.sample)  # the study's choice, never the chunk's
    statics = Statics(categories, study.law_params, study.engine.kwargs(), table)
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
        cache={
            "hits": after["hits"] - before["hits"],
            "misses": after["misses"] - before["misses"],
            "dispatchers": after["dispatchers"],
        },
        worker=f"{socket.gethostname()}:{os.getpid()}",
    )
