"""One calibration at a time in a folder of saved chains: a lock file held while it runs (two
runs writing one chain would each crash in HDF5's own lock, or spoil the chain), and the
errors of a chain file another program holds open, of a saved chain that does not fit the
calibration, or of an interrupted run."""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import IO, Any

__all__ = [
    "CalibrationInterrupted",
    "SavedChainError",
    "StateInUseError",
    "chain_in_use",
    "state_lock",
]

LOCK_NAME = ".lock"


class StateInUseError(ValueError):
    """Another calibration (or another program) is using the folder of saved chains
    ``folder``."""

    def __init__(self, message: str, folder: Path) -> None:
        super().__init__(message)
        self.folder = folder

    def __reduce__(self) -> tuple[Any, ...]:  # pickled whole: raised on a Dask worker
        return type(self), (str(self), self.folder)


class SavedChainError(ValueError):
    """A saved chain, ``state``, that this calibration cannot resume, and ``reason``: made with
    other inputs (the measurements, priors, model, walkers, seed or engine options changed), or
    unreadable (a run stopped while writing it). The file is kept; ``restart=True``
    (``--restart``) discards it."""

    def __init__(self, state: Path, reason: str) -> None:
        self.state, self.reason = state, reason
        super().__init__(
            f"the saved chain {state} {reason}; it is kept: restart=True discards it and starts "
            "again (or give another state_dir)"
        )

    def __reduce__(self) -> tuple[Any, ...]:  # pickled whole: raised on a Dask worker
        return type(self), (self.state, self.reason)


class CalibrationInterrupted(KeyboardInterrupt):
    """Ctrl-C during a chain: ``model``, the last saved ``step`` of ``steps``, ``saved`` (the
    chain is kept in a state folder and a new run resumes it)."""

    def __init__(self, model: str, step: int, steps: int, saved: bool) -> None:
        self.model, self.step, self.steps, self.saved = model, int(step), int(steps), saved
        how = (
            "run the same command again to resume"
            if saved
            else "nothing was saved (give a folder for the chains, --out, to resume later)"
        )
        super().__init__(f"interrupted at step {self.step} of {steps} ({model}); {how}")


def _try_lock(fh: IO[str]) -> None:
    """An exclusive lock on ``fh`` or OSError when another process holds one."""
    if sys.platform == "win32":  # pragma: no cover - Windows
        import msvcrt

        msvcrt.locking(fh.fileno(), msvcrt.LK_NBLCK, 1)
    else:
        import fcntl

        fcntl.flock(fh.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)


@contextmanager
def state_lock(folder: Path) -> Iterator[None]:
    """Hold the lock of ``folder`` (created if missing) while the block runs; StateInUseError when
    another calibration holds it. Folders created here are removed again when nothing but the
    lock was written into them (a run refused before its first step leaves no empty folder)."""
    created = [d for d in (folder, *folder.parents) if not d.exists()]
    folder.mkdir(parents=True, exist_ok=True)
    lock = folder / LOCK_NAME
    fh = lock.open("a+")
    try:
        try:
            _try_lock(fh)
        except OSError:
            raise StateInUseError(
                f"another calibration is using {folder}: wait for it to end or choose another "
                "folder",
                folder,
            ) from None
        yield
    finally:
        fh.close()  # closing releases the lock
        if created and [p.name for p in folder.iterdir()] == [LOCK_NAME]:
            lock.unlink(missing_ok=True)
            for d in created:  # innermost first
                with contextlib.suppress(OSError):
                    d.rmdir()


def chain_in_use(state: Path, exc: OSError, step: int) -> StateInUseError:
    """The error of a chain file that HDF5 could not open (``exc``): another program holds
    it open (a reader of the file while it is written)."""
    return StateInUseError(
        f"cannot open the saved chain {state}: another program has it open ({exc.strerror or exc})"
        f"; close it, then run the same command again to resume from step {step}",
        state.parent,
    )
