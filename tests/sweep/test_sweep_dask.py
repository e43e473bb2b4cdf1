"""A real Dask cluster (scheduler and workers as separate processes on 127.0.0.1) gives the
same store as a local run, also when a worker is killed mid-sweep; workers load the compiled
kernels from the shared on-disk numba cache."""

from __future__ import annotations

import importlib
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import SlowEvaluator, store_files

from impactlab.sweep import ENGINE, Study, SweepStore, run_sweep

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
        self.env.setdefault("NUMBA_CACHE_DIR", str(ROOT / ".numba_cache"))
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
    remote = run_sweep(
        _study(), tmp_path / "dask.zarr", evaluator=ev, quiet=True, scheduler=cluster.address
    )
    assert remote.stats.backend == "dask"
    assert remote.stats.chunks_computed == local.stats.n_chunks > 4
    assert len(remote.stats.cache) == 2  # both workers ran chunks
    assert store_files(remote.path) == store_files(local.path)
    # each worker loaded the engine from NUMBA_CACHE_DIR: cache hits, no compilation
    for worker, c in remote.stats.cache.items():
        assert c["misses"] == 0, (worker, c)
        assert c["hits"] > 0, (worker, c)


def test_killed_worker_mid_sweep_still_gives_identical_store(cluster, tmp_path) -> None:
    slow = SlowEvaluator(_evaluator(), delay=0.25)
    ref = run_sweep(_study(16), tmp_path / "ref.zarr", evaluator=_evaluator(), quiet=True)
    victim = cluster.add_worker()
    cluster.wait_for_workers(3)
    store = tmp_path / "killed.zarr"
    box: dict[str, object] = {}

    def work() -> None:
        try:
            box["res"] = run_sweep(
                _study(16), store, evaluator=slow, quiet=True, scheduler=cluster.address
            )
        except BaseException as exc:  # pragma: no cover - reported below
            box["err"] = exc

    t = threading.Thread(target=work)
    t.start()
    deadline = time.monotonic() + 120
    while len(SweepStore(store).done_chunks()) < 5 and time.monotonic() < deadline:
        assert t.is_alive(), box
        time.sleep(0.02)
    os.kill(victim.pid, signal.SIGKILL)
    victim.wait(timeout=10)
    t.join(timeout=180)
    assert not t.is_alive()
    assert "err" not in box, box.get("err")
    res = box["res"]
    assert res.complete  # type: ignore[attr-defined]
    # the victim had finished chunks before it died; the survivors did the rest
    workers = res.stats.cache  # type: ignore[attr-defined]
    assert any(w.endswith(f":{victim.pid}") for w in workers), workers
    assert sum(c["tasks"] for c in workers.values()) == ref.stats.n_chunks
    assert len(SweepStore(store).done_chunks()) == ref.stats.n_chunks
    assert store_files(store) == store_files(ref.path)
