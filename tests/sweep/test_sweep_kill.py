"""A sweep killed at any moment, store creation included, resumes to the store of an
uninterrupted run; a killed sweep leaves no worker processes behind.

The sweep runs in a child process that kills itself at a named stage (the test hook
``impactlab.sweep.hooks``: ``IMPACTLAB_SWEEP_KILL_AT``), so every kill happens at an exact,
chosen point and no test depends on timing.
"""

from __future__ import annotations

import multiprocessing
import os
import signal
from pathlib import Path

import pytest
from sweep_fakes import FakeEvaluator, kill_study, run_kill_study, store_files, wait_for

from impactlab.sweep import SweepStore, run_sweep
from impactlab.sweep.hooks import KILL_AT, KILL_SIGNAL
from impactlab.sweep.locking import pid_alive

pytestmark = pytest.mark.slow  # end to end: sweeps in child processes, killed and resumed

#: Children forked from a server that imported the sweep package once (a fresh interpreter per
#: kill would import it again, 2-3 s each); each child is still a process of its own, killed
#: by the hook's real signal.
_CTX = multiprocessing.get_context("forkserver")
_CTX.set_forkserver_preload(["sweep_fakes", "impactlab.sweep"])


def run_killed(
    store: Path,
    stage: str,
    sig: str = "SIGKILL",
    *,
    backend: str = "threads",
    seed: int = 5,
    restart: bool = False,
    pids: Path | None = None,
) -> tuple[int, bytes, int]:
    """Run the kill study into ``store`` in a child process that sends itself ``sig`` at
    ``stage``; returns its exit status (-signal number when killed), its stderr and its
    process id."""
    pid_dir = pids or store.parent / "pids"
    pid_dir.mkdir(exist_ok=True)
    env = {KILL_AT: stage, KILL_SIGNAL: sig}
    log = store.parent / f"{stage.replace(':', '-')}.log"
    # stderr into a file, not a pipe: leftover processes cannot hold it open
    args = (str(log), env, seed, str(store), str(pid_dir), backend, restart)
    proc = _CTX.Process(target=run_kill_study, args=args)
    proc.start()
    proc.join(timeout=600)
    assert proc.exitcode is not None, "the killed sweep still runs after 600 s"
    assert proc.pid is not None
    return proc.exitcode, log.read_bytes(), proc.pid


@pytest.fixture(scope="module")
def reference(tmp_path_factory) -> dict[int, Path]:
    """Uninterrupted stores of the kill study (seeds 5 and 6)."""
    root = tmp_path_factory.mktemp("ref")
    return {
        seed: run_sweep(
            kill_study(seed), root / f"ref{seed}.zarr", evaluator=FakeEvaluator(), quiet=True
        ).path
        for seed in (5, 6)
    }


def _leftovers(folder: Path) -> list[str]:
    """Temporary siblings of a store (``.kill.zarr.creating-...``) left in ``folder``."""
    return sorted(p.name for p in folder.iterdir() if p.name.startswith(".kill.zarr."))


@pytest.mark.parametrize(
    "stage",
    [
        "create:tempdir",
        "create:arrays",
        "create:built",
        "create:renamed",
        "chunk:0:data",
        "chunk:0:done",
        "chunk:7:data",
        "chunk:17:data",
    ],
)
def test_killed_at_any_stage_then_resumed_gives_identical_store(tmp_path, reference, stage):
    store = tmp_path / "kill.zarr"
    rc, err, _ = run_killed(store, stage)
    assert rc == -signal.SIGKILL, err.decode()
    if stage in ("create:tempdir", "create:arrays", "create:built"):
        assert not store.exists()  # a store exists complete or not at all
        assert _leftovers(tmp_path)
    else:
        assert SweepStore(store).exists()
    again = run_sweep(kill_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.complete
    assert store_files(store) == store_files(reference[5])
    assert _leftovers(tmp_path) == []


def test_killed_while_restarting_then_run_again(tmp_path, reference) -> None:
    store = tmp_path / "kill.zarr"
    run_sweep(kill_study(5), store, evaluator=FakeEvaluator(), quiet=True)
    rc, err, _ = run_killed(store, "restart:moved", seed=6, restart=True)
    assert rc == -signal.SIGKILL, err.decode()
    assert not store.exists()  # moved aside whole: never half deleted
    run_sweep(kill_study(6), store, evaluator=FakeEvaluator(), quiet=True)
    assert store_files(store) == store_files(reference[6])
    assert _leftovers(tmp_path) == []


@pytest.mark.parametrize("sig", ["SIGKILL", "SIGINT"])
def test_killed_mid_sweep_then_resumed_computes_only_the_missing_chunks(
    tmp_path, reference, sig
) -> None:
    store = tmp_path / "kill.zarr"
    rc, err, _ = run_killed(store, "chunk:3:done", sig)
    assert rc != 0
    if sig == "SIGINT":
        assert b"run the same command again" in err
    done = SweepStore(store).done_chunks()
    assert {0, 1, 2, 3} <= done and len(done) < 18
    again = run_sweep(kill_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_before == len(done)
    assert again.stats.chunks_computed == 18 - len(done)
    assert store_files(store) == store_files(reference[5])


def test_killed_process_pool_sweep_leaves_no_workers(tmp_path, reference) -> None:
    store = tmp_path / "kill.zarr"
    pids = tmp_path / "pids"
    rc, err, parent = run_killed(store, "chunk:2:done", backend="processes", pids=pids)
    workers = [int(p.name) for p in pids.iterdir()]
    try:
        assert rc == -signal.SIGKILL, err.decode()
        assert workers and parent not in workers  # chunks ran in pool processes
        wait_for(lambda: not any(pid_alive(w) for w in workers), "the pool workers to exit", 120)
    finally:
        for w in workers:
            if pid_alive(w):
                os.kill(w, signal.SIGKILL)
    done = SweepStore(store).done_chunks()
    assert 2 in done  # the pool delivers chunks in the order they finish
    again = run_sweep(kill_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_before == len(done)
    assert store_files(store) == store_files(reference[5])
