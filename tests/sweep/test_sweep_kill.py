"""A sweep killed at any moment, store creation included, resumes to the store of an
uninterrupted run; a killed sweep leaves no worker processes behind.

The sweep runs in a subprocess that kills itself at a named stage (the test hook
``impactlab.sweep.hooks``: ``IMPACTLAB_SWEEP_KILL_AT``), so every kill happens at an exact,
chosen point and no test depends on timing.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from sweep_fakes import FakeEvaluator, kill_study, store_files, wait_for

from impactlab.sweep import SweepStore, run_sweep
from impactlab.sweep.hooks import KILL_AT, KILL_SIGNAL
from impactlab.sweep.locking import pid_alive

pytestmark = pytest.mark.slow  # end to end: sweeps in child processes, killed and resumed

HERE = Path(__file__).resolve().parent

_SCRIPT = textwrap.dedent("""
    import signal
    import sys
    # a process started from a non-interactive background job inherits SIGINT ignored (and
    # Python then installs no KeyboardInterrupt handler): restore the interactive default
    signal.signal(signal.SIGINT, signal.default_int_handler)
    sys.path.insert(0, {here!r})
    from sweep_fakes import FakeEvaluator, kill_study
    from impactlab.sweep import run_sweep
    run_sweep(kill_study({seed}), {store!r}, evaluator=FakeEvaluator(pid_dir={pids!r}),
              backend={backend!r}, workers=2, restart={restart!r})
""")


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
    """Run the kill study into ``store`` in a subprocess that sends itself ``sig`` at ``stage``;
    returns its exit status, its stderr and its process id."""
    pid_dir = pids or store.parent / "pids"
    pid_dir.mkdir(exist_ok=True)
    script = _SCRIPT.format(
        here=str(HERE),
        seed=seed,
        store=str(store),
        pids=str(pid_dir),
        backend=backend,
        restart=restart,
    )
    env = {**os.environ, KILL_AT: stage, KILL_SIGNAL: sig}
    log = store.parent / f"{stage.replace(':', '-')}.log"
    with log.open("wb") as fh:  # a file, not a pipe: leftover processes cannot hold it open
        proc = subprocess.Popen([sys.executable, "-c", script], env=env, stderr=fh)
        proc.wait(timeout=600)
    return proc.returncode, log.read_bytes(), proc.pid


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
