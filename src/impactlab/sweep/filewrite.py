"""Files that a sweep's export and plots write: whole or not at all, and a failure that names
the file.

Each file is written under a temporary name beside it (``.<name>.<pid>.partial``) and renamed
into place, so a full disk or a kill leaves no half-written file. An ``OSError`` of the system
that names no file (or the temporary one) is given the file's own name, so the command line
says which file could not be written. A library that reports a failed write without an errno
(netCDF4's ``RuntimeError: NetCDF: HDF error`` when the disk fills) is turned into an
``OSError``: ``ENOSPC`` where the file system has next to no space left, else ``EIO`` with the
library's text.
"""

from __future__ import annotations

import errno
import os
import shutil
from collections.abc import Callable
from pathlib import Path

from impactlab.sweep.hooks import checkpoint

__all__ = ["LOW_SPACE_BYTES", "library_write_error", "write_atomic"]

#: Free bytes under which a write that failed without an errno is taken as a full disk.
LOW_SPACE_BYTES = 1 << 20


def write_atomic(out: Path, write: Callable[[Path], None]) -> None:
    """``write`` a temporary file beside ``out``, then put it in place (none left on error; an
    OSError with an errno and without a file, or with the temporary one, names ``out``)."""
    tmp = out.with_name(f".{out.name}.{os.getpid()}.partial")
    try:
        write(tmp)
        checkpoint("write:partial")
        os.replace(tmp, out)
    except OSError as exc:
        tmp.unlink(missing_ok=True)
        named = exc.filename is not None and str(exc.filename) != str(tmp)
        if exc.strerror is not None and not named:  # an errno's error: its file is ``out``
            exc.filename = str(out)
        raise
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def library_write_error(exc: Exception, path: Path, what: str) -> OSError:
    """The OSError of a write of ``path`` (still there) that a library reported as ``exc``,
    without an errno: no space left on the device where its file system has under
    :data:`LOW_SPACE_BYTES` free, else an input/output error that quotes ``exc``; ``what``
    names the library (``"the NetCDF library"``)."""
    try:
        free: int | None = shutil.disk_usage(path.parent).free
    except OSError:
        free = None
    if free is not None and free < LOW_SPACE_BYTES:
        return OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    return OSError(
        errno.EIO, f"{what} could not write the file ({exc}; check the free space and the disk)"
    )
