"""One writer per store: a lock file holding the writer's host and process id.

A lock whose process is gone (same host, no such process) is stale and taken over; a lock of a
live process, or of another host, refuses a second writer.
"""

from __future__ import annotations

import os
import socket
from pathlib import Path


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


def acquire_lock(lock: Path, store: Path) -> None:
    """Take ``lock`` for this process; refuse if another live process on this host (or a
    process on another host) holds it. A lock left by a killed process is taken over."""
    for _ in range(2):
        try:
            write_lock(lock)
            return
        except FileExistsError:
            host, pid = _holder(lock)
            if f"{host} {pid}" == owner():
                return  # already ours
            if stale(host, pid):
                lock.unlink(missing_ok=True)
                continue
            raise ValueError(
                f"store {str(store)!r} is being written by process {pid} on {host!r}; "
                f"wait for it, or delete {str(lock)!r} if that process is gone"
            ) from None


def release_lock(lock: Path) -> None:
    """Remove ``lock`` if this process holds it."""
    if _holder(lock) == (socket.gethostname(), os.getpid()):
        lock.unlink(missing_ok=True)
