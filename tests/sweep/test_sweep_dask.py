"""A real Dask cluster (scheduler and workers as separate processes on 127.0.0.1) gives the
same store as a local run, also when a worker is killed mid-sweep; workers load the compiled
kernels from the shared on-disk numba cache; a cluster that loses its last worker stops the
sweep with an error. Gated evaluators (``sweep_fakes``) decide which worker computes what, so
no test depends on how fast a process runs."""

from __future__ import annotations

import importlib
import os
import signal
import socket
import subprocess
import sys
import threading
from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import BarrierEvaluator, GatedEvaluator, store_files, wait_for

from impactlab.sweep import ENGINE, Study, SweepStore, run_sweep

pytestmark = pytest.mark.slow  # end to end: a real Dask cluster of separate processes

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class Cluster:
    """`dask scheduler` and `dask worker` processes on loopback."""

    def __init__(self, tmp: Path) -> None:
        self.port = _free_port()
        self.address = f"tcp://127.0.0.1:{self.port}"
        self.env = dict(os.environ)
        self.env["PYTHONPATH"] = os.pathsep.join(
            [str(HERE), *filter(None, [os.environ.get("PYTHONPATH")])]
        )
        self.env["NUMBA_NUM_THREADS"] = "1"
        self.env["DASK_DISTRIBUTED__WORKER__DAEMON"] = "False"
        self.log = tmp
        self.procs: list[subprocess.Popen[bytes]] = []
        self.scheduler = self._spawn(
            "scheduler",
            [
                "distributed.cli.dask_scheduler",
                "--host",
                "127.0.0.1",
                "--port",
                str(self.port),
                "--no-dashboard",
            ],
        )
        self.workers: list[subprocess.Popen[bytes]] = []

    def _spawn(self, name: str, args: list[str]) -> subprocess.Popen[bytes]:
        out = (self.log / f"{name}.log").open("wb")
        p = subprocess.Popen(
            [sys.executable, "-m", *args], env=self.env, stdout=out, stderr=subprocess.STDOUT
        )
        self.procs.append(p)
        return p

    def add_worker(self) -> subprocess.Popen[bytes]:
        name = f"w{len(self.workers)}"
        p = self._spawn(
            name,
            [
                "distributed.cli.dask_worker",
                self.address,
                "--nthreads",
                "1",
                "--no-nanny",
                "--no-dashboard",
                "--name",
                name,
                "--host",
                "127.0.0.1",
            ],
        )
        self.workers.append(p)
        return p

    def wait_for_workers(self, n: int) -> None:
        from distributed import Client

        with Client(self.address, timeout=60, set_as_default=False) as c:
            c.wait_for_workers(n, timeout=90)
            # import the package up front so that every worker starts its first chunk at once
            c.run(importlib.import_module, "impactlab.sweep")

    def close(self) -> None:
        for p in reversed(self.procs):
            if p.poll() is None:
                p.terminate()
        for p in self.procs:
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    c = Cluster(tmp_path_factory.mktemp("dask"))
    try:
        c.add_worker()
        c.add_worker()
        c.wait_for_workers(2)
        yield c
    finally:
        c.close()


def _study(n_angle: int = 12) -> Study:
    return Study(
        name="dask",
        chunk_size=40,
        grid={
            "angle": np.radians(np.linspace(10, 80, n_angle)),
            "mu": np.linspace(0.0, 0.5, 11),
            "vy": [-1.41, -2.18],
        },
        outputs=["e", "delta_p", "sliding_length", "duration", "regime"],
    )


def _evaluator():
    return ENGINE


def test_cluster_equals_local_and_loads_cached_kernels(cluster, tmp_path) -> None:
    ev = _evaluator()
    local = run_sweep(_study(), tmp_path / "local.zarr", evaluator=ev, quiet=True)
    both = BarrierEvaluator(ev, str(tmp_path), n=2)  # each worker computes a chunk
    remote = run_sweep(
        _study(), tmp_path / "dask.zarr", evaluator=both, quiet=True, scheduler=cluster.address
    )
    assert remote.stats.backend == "dask"
    assert remote.stats.chunks_computed == local.stats.n_chunks > 4
    assert len(remote.stats.cache) == 2  # both workers ran chunks
    assert store_files(remote.path) == store_files(local.path)
    # each worker loaded the engine from NUMBA_CACHE_DIR: cache hits, no compilation
    for worker, c in remote.stats.cache.items():
        assert c["misses"] == 0, (worker, c)
        assert c["hits"] > 0, (worker, c)


class _Sweep(threading.Thread):
    """``run_sweep`` in a thread; its result or exception in ``.result`` / ``.error``."""

    def __init__(self, *args, **kwargs) -> None:
        super().__init__(daemon=True)
        self.args, self.kwargs = args, kwargs
        self.result = None
        self.error: BaseException | None = None

    def run(self) -> None:
        try:
            self.result = run_sweep(*self.args, **self.kwargs)
        except BaseException as exc:  # reported by the test
            self.error = exc


def _kill(proc: subprocess.Popen[bytes]) -> None:
    os.kill(proc.pid, signal.SIGKILL)
    proc.wait(timeout=60)


def test_killed_worker_mid_sweep_still_gives_identical_store(cluster, tmp_path) -> None:
    ref = run_sweep(_study(16), tmp_path / "ref.zarr", evaluator=_evaluator(), quiet=True)
    victim = cluster.add_worker()
    cluster.wait_for_workers(3)
    store = tmp_path / "killed.zarr"
    gated = GatedEvaluator(_evaluator(), str(tmp_path), victim.pid)
    t = _Sweep(_study(16), store, evaluator=gated, quiet=True, scheduler=cluster.address)
    t.start()
    # the other workers are held back: the first chunk stored is the victim's
    wait_for(lambda: SweepStore(store).done_chunks() or not t.is_alive(), "the victim's chunk")
    assert t.is_alive(), t.error
    _kill(victim)  # while it holds its next chunk
    (tmp_path / "release").touch()
    t.join(timeout=300)
    assert not t.is_alive()
    assert t.error is None, t.error
    res = t.result
    assert res.complete  # type: ignore[attr-defined]
    # the victim had finished a chunk before it died; the survivors did the rest
    workers = res.stats.cache  # type: ignore[attr-defined]
    assert any(w.endswith(f":{victim.pid}") for w in workers), workers
    assert sum(c["tasks"] for c in workers.values()) == ref.stats.n_chunks
    assert len(SweepStore(store).done_chunks()) == ref.stats.n_chunks
    assert store_files(store) == store_files(ref.path)


def test_losing_the_last_worker_stops_the_sweep_with_an_error(tmp_path) -> None:
    lone = Cluster(tmp_path)
    try:
        victim = lone.add_worker()
        lone.wait_for_workers(1)
        store = tmp_path / "lost.zarr"
        gated = GatedEvaluator(_evaluator(), str(tmp_path), victim.pid)
        t = _Sweep(
            _study(), store, evaluator=gated, quiet=True, scheduler=lone.address, worker_timeout=2
        )
        t.start()
        wait_for(lambda: SweepStore(store).done_chunks() or not t.is_alive(), "the first chunk")
        assert t.is_alive(), t.error
        _kill(victim)
        t.join(timeout=300)
        assert not t.is_alive()
    finally:
        lone.close()
    assert isinstance(t.error, RuntimeError), t.error
    assert "no Dask worker left on the cluster for 2 s" in str(t.error)
    assert "run the same command again" in str(t.error)
    assert len(SweepStore(store).done_chunks()) == 1  # the victim's chunk stays stored
    assert not (store / ".sweep" / "lock").exists()
