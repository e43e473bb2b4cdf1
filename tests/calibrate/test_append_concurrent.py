"""Drops appended to one measurements file by several processes at once are all kept (each read,
check, replace and read back holds an exclusive lock on the file's folder, the folder of the
file a link names), and a duplicate label is still refused under the lock; a folder that cannot
be locked takes the drop unlocked, with a warning."""

from __future__ import annotations

import errno
import multiprocessing
import os
import sys
import time
import warnings
import zlib
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from impactlab.calibrate import CalibrationWarning, measurement_append, read_measurements
from impactlab.calibrate.measurement_append import append_record

if sys.platform != "win32":
    import fcntl

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="fcntl locks (POSIX)")

PROCESSES, EACH = 6, 4


def _drop(label: str) -> dict[str, object]:
    """A drop whose e follows its label (one drop's values under two labels are refused)."""
    e = 0.3 + (zlib.crc32(label.encode()) % 100_000) * 1e-6
    return {"label": label, "angle": "20 deg", "vy": -1.4, "e": e, "e_sigma": 0.01}


def _appender(path: str, who: int, start: object) -> None:
    start.wait()  # type: ignore[attr-defined]
    for i in range(EACH):
        append_record(path, _drop(f"p{who}-{i}"))


def test_concurrent_appends_keep_every_drop(tmp_path: Path) -> None:
    """Four analyses appending at once kept three drops, each reporting success."""
    path = tmp_path / "drops.csv"
    ctx = multiprocessing.get_context("fork")
    start = ctx.Barrier(PROCESSES)
    procs = [ctx.Process(target=_appender, args=(str(path), n, start)) for n in range(PROCESSES)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(120)
    assert [p.exitcode for p in procs] == [0] * PROCESSES
    labels = read_measurements(path).labels
    assert sorted(labels) == sorted(f"p{n}-{i}" for n in range(PROCESSES) for i in range(EACH))
    assert [p.name for p in tmp_path.iterdir()] == ["drops.csv"]  # no lock or partial file left


def _same_label(path: str, start: object) -> None:
    """Append drop "twin"; exit status 3 when it is refused as a label the file has already."""
    start.wait()  # type: ignore[attr-defined]
    try:
        append_record(path, _drop("twin"))
    except ValueError as exc:
        sys.exit(3 if "a drop labelled 'twin' is there already" in str(exc) else 4)


def test_the_label_check_runs_under_the_lock(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """Two processes append the same label at once: one is kept, the other refused. Each
    write is held back (0.5 s after its read and check), so that without the lock both would
    read the file without the label and both succeed."""
    path = tmp_path / "drops.csv"
    append_record(path, _drop("d0"))
    write = measurement_append.write_bytes_atomic

    def slow_write(*args: Any) -> None:
        time.sleep(0.5)
        write(*args)

    monkeypatch.setattr(measurement_append, "write_bytes_atomic", slow_write)
    ctx = multiprocessing.get_context("fork")
    start = ctx.Barrier(2)
    procs = [ctx.Process(target=_same_label, args=(str(path), start)) for _ in range(2)]
    for p in procs:
        p.start()
    for p in procs:
        p.join(60)
    assert {p.exitcode for p in procs} == {0, 3}  # one kept, one refused
    assert read_measurements(path).labels == ("d0", "twin")


def _spy_lock(monkeypatch: pytest.MonkeyPatch) -> tuple[list[str], list[tuple[str, bool]]]:
    """(the folders locked, the steps of an append with whether a lock was held then): every
    ``os.open`` and ``fcntl.flock`` seen, and each read, write and read back of the file."""
    opened: dict[int, str] = {}
    held: list[str] = []
    locked: list[str] = []
    steps: list[tuple[str, bool]] = []
    real_open, real_flock = os.open, fcntl.flock

    def spy_open(path: Any, flags: int, *args: Any, **kw: Any) -> int:
        fd = real_open(path, flags, *args, **kw)
        opened[fd] = os.fspath(path)
        return fd

    def spy_flock(fd: int, op: int) -> None:
        real_flock(fd, op)
        if op == fcntl.LOCK_EX:
            held.append(opened[fd])
            locked.append(opened[fd])
        elif op == fcntl.LOCK_UN:
            held.remove(opened[fd])

    def spied(name: str) -> Callable[..., Any]:
        real = getattr(measurement_append, name)

        def step(*args: Any, **kw: Any) -> Any:
            steps.append((name, bool(held)))
            return real(*args, **kw)

        return step

    monkeypatch.setattr(os, "open", spy_open)
    monkeypatch.setattr(fcntl, "flock", spy_flock)
    for name in ("read_text", "write_bytes_atomic", "read_measurements"):
        monkeypatch.setattr(measurement_append, name, spied(name))
    return locked, steps


def test_a_link_locks_the_folder_of_the_file_it_names(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    (tmp_path / "data").mkdir()
    path = tmp_path / "data" / "drops.csv"
    (tmp_path / "link.csv").symlink_to(path)
    append_record(tmp_path / "link.csv", _drop("d0"))
    locked, steps = _spy_lock(monkeypatch)
    append_record(tmp_path / "link.csv", _drop("d1"))
    assert [Path(x).resolve() for x in locked] == [(tmp_path / "data").resolve()]
    assert ("write_bytes_atomic", True) in steps
    assert (tmp_path / "link.csv").is_symlink() and read_measurements(path).labels == ("d0", "d1")
    assert [p.name for p in (tmp_path / "data").iterdir()] == ["drops.csv"]


def test_the_drops_returned_are_read_under_the_lock(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """The file's read, check, write and the read of the drops returned all hold the lock:
    another process's drop never follows the new one in what is returned."""
    path = tmp_path / "drops.csv"
    append_record(path, _drop("d0"))
    locked, steps = _spy_lock(monkeypatch)
    meas = append_record(path, _drop("d1"))
    assert meas.labels == ("d0", "d1") and locked == [str(tmp_path)]
    assert [s for s, _ in steps] == [
        "read_text",
        "read_measurements",  # the label check
        "write_bytes_atomic",
        "read_measurements",  # the drops returned
    ]
    assert all(held for _, held in steps), steps


@pytest.mark.parametrize("code", [errno.ENOLCK, errno.EBADF])
def test_a_folder_that_cannot_be_locked_appends_unlocked_with_a_warning(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, code: int
) -> None:
    """``flock`` refused (NFS without a lock service): the drop is appended all the same, and a
    warning says that appends from other processes at the same time are not safe."""
    real_flock = fcntl.flock

    def flock(fd: int, op: int) -> None:
        if op == fcntl.LOCK_EX:
            raise OSError(code, os.strerror(code))
        real_flock(fd, op)

    path = tmp_path / "drops.csv"
    append_record(path, _drop("d0"))
    monkeypatch.setattr(fcntl, "flock", flock)
    with pytest.warns(CalibrationWarning) as caught:
        meas = append_record(path, _drop("d1"))
    assert [str(w.message) for w in caught] == [
        f"{path}: drop 'd1' appended without a lock on its folder (the folder cannot be locked: "
        f"{os.strerror(code)}): appends to this file from other processes at the same time are "
        "not safe (a drop may be lost); append one at a time there"
    ]
    assert meas.labels == ("d0", "d1") == read_measurements(path).labels


def test_a_folder_that_cannot_be_opened_appends_unlocked_with_a_warning(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    real_open = os.open

    def spy_open(path: Any, flags: int, *args: Any, **kw: Any) -> int:
        if Path(path) == tmp_path:
            raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(path))
        return real_open(path, flags, *args, **kw)

    monkeypatch.setattr(os, "open", spy_open)
    with pytest.warns(CalibrationWarning, match="the folder cannot be opened: Permission denied"):
        append_record(tmp_path / "drops.csv", _drop("d0"))
    assert read_measurements(tmp_path / "drops.csv").labels == ("d0",)


def test_a_locked_append_gives_no_warning(tmp_path: Path) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        append_record(tmp_path / "drops.csv", _drop("d0"))
