"""One writer per store: a lock file holding the writer's host and process id.

A lock whose process is gone (same host, no such process) is stale and taken over; a lock of a
live process, or of another host, refuses a second writer. A lock whose text names no holder
(empty or damaged: a writer killed between creating the file and writing its line) is stale
once it is :data:`UNREADABLE_GRACE_S` old; younger, it may be a writer's that is writing its
line right now, and is refused (as is a lock that cannot be read at all), with the file named.
A store whose lock cannot be created (a read-only file system, no permission) is refused
naming the store: it can still be read.
"""

from __future__ import annotations

import os
import socket
import time
from pathlib import Path

from impactlab._oserror import UNWRITABLE, oserror_words

#: Seconds after which a lock naming no holder is taken for a killed writer's: a live writer
#: writes its line within microseconds of creating the file.
UNREADABLE_GRACE_S = 10.0


def pid_alive(pid: int) -> bool:
    """True if a process with this id exists on this host (a zombie counts as gone)."""
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:  # no /proc (not Linux), or the process just went
        return True
    return stat.rsplit(")", 1)[-1].split()[0] != "Z"


def owner() -> str:
    """This process as a lock holder: ``"<host> <pid>"``."""
    return f"{socket.gethostname()} {os.getpid()}"


def stale(host: str, pid: int) -> bool:
    """True for a holder on this host whose process is gone."""
    return host == socket.gethostname() and not pid_alive(pid)


def write_lock(lock: Path) -> None:
    """Create ``lock`` for this process (it must not exist)."""
    fd = os.open(lock, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
    with os.fdopen(fd, "w") as fh:
        fh.write(owner())


def _holder(lock: Path) -> tuple[str, int]:
    try:
        host, pid = lock.read_text().split()
        return host, int(pid)
    except (OSError, ValueError):
        return "", 0


def _unreadable(lock: Path, store: Path) -> os.stat_result | None:
    """For a lock naming no holder: its stat when it is old enough to be a killed writer's
    (stale), else ValueError naming the file and how to clear it; None when it is gone."""
    try:
        text, st = lock.read_bytes(), lock.stat()
    except FileNotFoundError:
        return None
    except OSError as exc:
        raise ValueError(
            f"store {str(store)!r}: its lock file {str(lock)!r} cannot be read "
            f"({exc.strerror or exc}); if no process is writing the store, delete {str(lock)!r} "
            "and run again"
        ) from None
    age = time.time() - st.st_mtime
    if age >= UNREADABLE_GRACE_S:
        return st
    what = "is empty" if not text.strip() else "names no writer (host and process id)"
    raise ValueError(
        f"store {str(store)!r}: its lock file {str(lock)!r} {what} and is {age:.0f} s old: "
        f"a writer may be starting; run again in {UNREADABLE_GRACE_S:g} s (it is then taken "
        f"for a killed writer's), or delete {str(lock)!r} if no process is writing the store"
    )


def acquire_lock(lock: Path, store: Path) -> None:
    """Take ``lock`` for this process; refuse if another live process on this host (or a
    process on another host) holds it. A lock left by a killed process is taken over, and so
    is one naming no holder once it is ``UNREADABLE_GRACE_S`` old."""
    for _ in range(3):
        try:
            write_lock(lock)
            return
        except FileExistsError:
            pass  # held, or left behind: below
        except OSError as exc:
            if exc.errno not in UNWRITABLE:
                raise
            raise ValueError(_unwritable(store, lock, exc)) from None
        host, pid = _holder(lock)
        if f"{host} {pid}" == owner():
            return  # already ours
        if not host:  # empty, damaged or unreadable
            st = _unreadable(lock, store)
            if st is not None and _same_file(lock, st):
                lock.unlink(missing_ok=True)
            continue
        if stale(host, pid):
            lock.unlink(missing_ok=True)
            continue
        raise ValueError(
            f"store {str(store)!r} is being written by process {pid} on {host!r}; "
            f"wait for it, or delete {str(lock)!r} if that process is gone"
        ) from None
    raise ValueError(
        f"store {str(store)!r}: another process keeps taking its lock {str(lock)!r}; wait for "
        "it, or delete the file if no process is writing the store"
    )


def _unwritable(store: Path, lock: Path, exc: OSError) -> str:
    """Why a run cannot write the store ``store`` whose ``lock`` it cannot create."""
    why = (oserror_words(exc) or (exc.strerror or str(exc), ""))[0]
    return (
        f"store {str(store)!r}: {why}, so a run cannot write it (not even its lock file "
        f"{str(lock)!r}); impactlab sweep info, export and plot read it as it is (open_sweep in "
        f"Python); to compute more, copy it to a writable place and run the study there"
    )


def _same_file(lock: Path, st: os.stat_result) -> bool:
    """True while ``lock`` is still the file ``st`` described (not replaced by a new writer's)."""
    try:
        now = lock.stat()
    except FileNotFoundError:
        return False
    return (now.st_ino, now.st_mtime_ns, now.st_size) == (st.st_ino, st.st_mtime_ns, st.st_size)


def release_lock(lock: Path) -> None:
    """Remove ``lock`` if this process holds it."""
    if _holder(lock) == (socket.gethostname(), os.getpid()):
        lock.unlink(missing_ok=True)
