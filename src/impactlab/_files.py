"""Write a file whole or not at all: a user's data and a run's results never left cut short.

The text goes to a temporary file beside the target (same folder, so same file system), which
then replaces the target in one step (``os.replace``): an interrupted write, a full disk or a
crash leaves the old file as it was, and the temporary one is removed. A target that exists is
replaced only where it could be written in place (a read-only file is refused as ``open`` would
refuse it: ``os.replace`` would not ask), the new file keeps its permission bits, and a symbolic
link is written through (the file it names is replaced, the link kept).
"""

from __future__ import annotations

import errno
import os
import stat
from pathlib import Path


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes) -> None:
    """Write ``data`` to ``path`` whole, or leave ``path`` as it was (see module);
    PermissionError for an existing file that cannot be written."""
    target = Path(path)
    if target.is_symlink():  # write the file the link names: the link stays a link
        target = target.resolve()
    mode = None
    if target.exists():
        if not os.access(target, os.W_OK):
            raise PermissionError(errno.EACCES, os.strerror(errno.EACCES), str(target))
        mode = stat.S_IMODE(target.stat().st_mode)
    tmp = target.with_name(f".{target.name}.{os.getpid()}.partial")
    try:
        with open(tmp, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        if mode is not None:
            os.chmod(tmp, mode)
        os.replace(tmp, target)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def write_text_atomic(path: str | os.PathLike[str], text: str, encoding: str = "utf-8") -> None:
    """Write ``text`` to ``path`` whole, or leave ``path`` as it was (see module)."""
    write_bytes_atomic(path, text.encode(encoding))
