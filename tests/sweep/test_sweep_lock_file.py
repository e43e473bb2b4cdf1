"""A lock file that names no writer (empty, damaged) or cannot be read: taken for a killed
writer's once it is old enough that no writer can still be writing its line, refused with the
file named (and how to clear it) before that."""

from __future__ import annotations

import errno
import os
import shutil
import time
from pathlib import Path

import pytest
from sweep_fakes import FakeEvaluator

from impactlab.sweep import Study, run_sweep
from impactlab.sweep.locking import UNREADABLE_GRACE_S


def _study() -> Study:
    return Study(name="lk", grid={"mu": [0.1, 0.2]}, fixed={"angle": 0.35, "vy": -1.41})


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    """The study's finished store, run once for the module."""
    path = tmp_path_factory.mktemp("lk") / "lk.zarr"
    return run_sweep(_study(), path, evaluator=FakeEvaluator(), quiet=True).path


@pytest.fixture
def store(finished, tmp_path):
    """A copy of the finished store, the test's own to lock."""
    return shutil.copytree(finished, tmp_path / "lk.zarr")


def _age(path, seconds: float) -> None:
    then = time.time() - seconds
    os.utime(path, (then, then))


@pytest.mark.parametrize("text", ["", "\n", "garbage", "host-only", "h 12 extra"])
def test_an_old_lock_naming_no_writer_is_taken_over(store, text) -> None:
    lock = store / ".sweep" / "lock"
    lock.write_text(text)
    _age(lock, UNREADABLE_GRACE_S + 1)
    res = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert res.complete and not lock.exists()


@pytest.mark.parametrize(("text", "what"), [("", "is empty"), ("x", "names no writer")])
def test_a_new_lock_naming_no_writer_may_be_a_starting_writer(
    store, text, what, monkeypatch
) -> None:
    from impactlab.sweep import locking

    monkeypatch.setattr(locking, "UNREADABLE_GRACE_S", 3600.0)  # new however slow the machine
    lock = store / ".sweep" / "lock"
    lock.write_text(text)
    with pytest.raises(ValueError, match="its lock file") as caught:
        run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    message = str(caught.value)
    assert message.startswith(f"store {str(store)!r}: its lock file {str(lock)!r} {what}")
    assert f"delete {str(lock)!r} if no process is writing the store" in message
    assert "process 0" not in message and "\n" not in message
    assert lock.exists()  # left to its writer


def test_a_lock_that_cannot_be_read_is_named(store, monkeypatch) -> None:
    lock = store / ".sweep" / "lock"
    lock.write_text("")
    _age(lock, UNREADABLE_GRACE_S + 1)
    read = Path.read_bytes

    def refused(path: Path) -> bytes:
        if path == lock:
            raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(path))
        return read(path)

    monkeypatch.setattr(Path, "read_bytes", refused)
    with pytest.raises(ValueError, match="its lock file") as caught:
        run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert str(caught.value) == (
        f"store {str(store)!r}: its lock file {str(lock)!r} cannot be read (Permission denied); "
        f"if no process is writing the store, delete {str(lock)!r} and run again"
    )
    assert lock.exists()


def test_a_lock_replaced_while_judged_is_not_removed(store, monkeypatch) -> None:
    """An old empty lock that a new writer replaces before it is removed: the new writer's
    lock stays, and the second writer is refused."""
    from impactlab.sweep import locking

    lock = store / ".sweep" / "lock"
    lock.write_text("")
    _age(lock, UNREADABLE_GRACE_S + 1)
    judged = locking._unreadable

    def replaced(path, where):
        st = judged(path, where)
        path.unlink()
        path.write_text(f"{os.uname().nodename} {os.getppid()}")  # a live writer's
        return st

    monkeypatch.setattr(locking, "_unreadable", replaced)
    with pytest.raises(ValueError, match="is being written by process"):
        run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert lock.read_text().split()[1] == str(os.getppid())
